// stdio with explicit error checks on write, flush and close (a full disk shows up at fclose).
#include "file_commit.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace lintel::scene_write {
namespace {

Status write_whole(const std::string& path, const uint8_t* data, size_t size) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return Status::error(path + ": cannot open for writing: " + std::strerror(errno));
  const bool written = size == 0 || std::fwrite(data, 1, size, f) == size;
  const int saved = errno;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed) {
    std::remove(path.c_str());
    return Status::error(path + ": write failed: " + std::strerror(written ? errno : saved));
  }
  return {};
}

}  // namespace

Status commit_files(const std::vector<FileContent>& files) {
  std::vector<std::string> temporaries;
  for (const FileContent& f : files) {
    const std::string tmp = f.path + ".tmp";
    if (Status s = write_whole(tmp, f.data, f.size); !s) {
      for (const std::string& t : temporaries) std::remove(t.c_str());
      return Status::error(f.path + ": cannot write (" + s.message() + ")");
    }
    temporaries.push_back(tmp);
  }
  for (size_t i = 0; i < files.size(); ++i) {
    if (std::rename(temporaries[i].c_str(), files[i].path.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      for (size_t j = i; j < temporaries.size(); ++j) std::remove(temporaries[j].c_str());
      return Status::error(files[i].path + ": cannot rename the temporary file into place: " + why);
    }
  }
  return {};
}

}  // namespace lintel::scene_write
