// lintel::commit_files, the one way outputs are put in place: only a missing or regular target is
// replaced; a device, FIFO, directory or symlink is refused before anything is created; an
// existing "<out>.tmp" is never touched; a replaced file keeps its mode; a failure leaves no
// temporary and no target changed.
#include <lintel/file_commit.h>

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace lintel {
namespace {

namespace fs = std::filesystem;

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class FileCommit : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "lintel-commit-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }
  size_t entries() const { return size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator())); }
  std::string dir_;
};

TEST_F(FileCommit, WritesANewFileAndReplacesARegularOne) {
  const std::string path = dir_ + "/out.txt";
  ASSERT_TRUE(commit_file(path, "first").ok());
  EXPECT_EQ(read_text(path), "first");
  ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
  ASSERT_TRUE(commit_file(path, "second").ok());
  EXPECT_EQ(read_text(path), "second");
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u) << "a replaced file keeps its permission bits";
  EXPECT_EQ(entries(), 1u) << "no temporary left behind";
}

TEST_F(FileCommit, NeverTouchesAnExistingTemporary) {
  const std::string path = dir_ + "/out.txt";
  std::ofstream(path + ".tmp") << "someone else's";
  ASSERT_TRUE(commit_file(path, "mine").ok());
  EXPECT_EQ(read_text(path + ".tmp"), "someone else's");
  EXPECT_EQ(read_text(path), "mine");
  EXPECT_EQ(entries(), 2u);
}

TEST_F(FileCommit, RefusesEverythingButRegularFiles) {
  ASSERT_EQ(::mkfifo((dir_ + "/fifo").c_str(), 0600), 0);
  fs::create_directory(dir_ + "/folder");
  std::ofstream(dir_ + "/real") << "kept";
  fs::create_symlink("real", dir_ + "/link");
  struct Case {
    std::string path, needle;
  } cases[] = {{"/dev/null", "is a character device"},
               {dir_ + "/fifo", "is a FIFO"},
               {dir_ + "/folder", "is a directory"},
               {dir_ + "/link", "is a symbolic link to 'real'"},
               {dir_ + "/missing/out", "does not exist"}};
  for (const Case& c : cases) {
    const Status s = commit_file(c.path, "x");
    ASSERT_FALSE(s.ok()) << c.path;
    EXPECT_EQ(s.kind(), StatusKind::BadInput);
    EXPECT_NE(s.message().find(c.path + ": "), std::string::npos) << s.message();
    EXPECT_NE(s.message().find(c.needle), std::string::npos) << s.message();
  }
  EXPECT_EQ(read_text(dir_ + "/real"), "kept");
  EXPECT_TRUE(fs::is_symlink(dir_ + "/link"));
  EXPECT_EQ(entries(), 4u) << "a refusal creates nothing";
  // The link's target, named directly, is written.
  EXPECT_TRUE(commit_file(dir_ + "/real", "new").ok());
  EXPECT_EQ(read_text(dir_ + "/link"), "new");
}

TEST_F(FileCommit, OneRefusedTargetLeavesEveryFileUnchanged) {
  fs::create_directory(dir_ + "/b.bin");
  const std::string a = "scene";
  const Status s = commit_files({{dir_ + "/a.gltf", reinterpret_cast<const uint8_t*>(a.data()), a.size()},
                                 {dir_ + "/b.bin", reinterpret_cast<const uint8_t*>(a.data()), a.size()}});
  EXPECT_FALSE(s.ok());
  EXPECT_FALSE(fs::exists(dir_ + "/a.gltf")) << "checked before any file is written";
  EXPECT_EQ(entries(), 1u);
}

TEST_F(FileCommit, TemporaryForAnotherProgramIsCommittedOrRefused) {
  const std::string path = dir_ + "/walk.mp4";
  std::string tmp;
  ASSERT_TRUE(make_temporary_beside(path, ".mp4", tmp).ok());
  EXPECT_EQ(tmp.substr(tmp.size() - 4), ".mp4");
  std::ofstream(tmp) << "video";
  ASSERT_TRUE(commit_temporary(tmp, path).ok());
  EXPECT_EQ(read_text(path), "video");
  EXPECT_FALSE(fs::exists(tmp));
  EXPECT_FALSE(make_temporary_beside("/dev/null", ".mp4", tmp).ok());
}

}  // namespace
}  // namespace lintel
