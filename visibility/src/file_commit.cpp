// Safe output files: lstat refuses anything but a regular file before a byte is written, mkstemp
// gives a temporary that cannot collide with an existing file, fsync + rename make the switch
// all-or-nothing. A device (/dev/null, /dev/full) or a symlink is never replaced.
#include <lintel/file_commit.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace lintel {
namespace {

std::string directory_part(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISCHR(mode)) return "is a character device";
  if (S_ISBLK(mode)) return "is a block device";
  if (S_ISFIFO(mode)) return "is a FIFO";
  if (S_ISSOCK(mode)) return "is a socket";
  return "is not a regular file";
}

mode_t new_file_mode() {
  const mode_t mask = ::umask(0);  // reading the umask means setting it; restored at once
  ::umask(mask);
  return 0666 & ~mask;
}

// Removes the temporaries on every exit path unless released.
struct TemporaryFiles {
  std::vector<std::string> paths;
  ~TemporaryFiles() {
    for (const std::string& p : paths) ::unlink(p.c_str());
  }
};

Status write_all(int fd, const std::string& tmp, const std::string& path, const uint8_t* data, size_t size) {
  size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return Status::error(path + ": cannot write '" + tmp + "': " + std::strerror(n < 0 ? errno : EIO));
    done += size_t(n);
  }
  if (::fsync(fd) != 0) return Status::error(path + ": cannot write '" + tmp + "': " + std::strerror(errno));
  return {};
}

Status create_temporary(const std::string& path, const std::string& suffix, int& fd, std::string& tmp) {
  std::string pattern = path + ".tmp.XXXXXX" + suffix;
  fd = ::mkstemps(pattern.data(), int(suffix.size()));
  if (fd < 0) return Status::error(path + ": cannot create a temporary file beside it: " + std::strerror(errno));
  tmp = pattern;
  struct stat st {};
  // A replaced file keeps its mode; mkstemp's 0600 would otherwise hide outputs from other users.
  const mode_t mode = ::stat(path.c_str(), &st) == 0 ? (st.st_mode & 07777) : new_file_mode();
  (void)::fchmod(fd, mode);  // best effort: the file is complete either way
  return {};
}

}  // namespace

std::string output_refusal(const std::string& path) {
  if (path.empty()) return "the output path is empty";
  if (path.find('\0') != std::string::npos) return "the output path contains a NUL byte";
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) {
    if (errno != ENOENT) return std::strerror(errno);
    struct stat dir {};
    const std::string parent = directory_part(path);
    if (::stat(parent.c_str(), &dir) != 0) return "directory '" + parent + "' does not exist";
    if (!S_ISDIR(dir.st_mode)) return "'" + parent + "' is not a directory";
    return {};
  }
  if (S_ISLNK(st.st_mode)) {
    char target[4096];
    const ssize_t n = ::readlink(path.c_str(), target, sizeof target - 1);
    const std::string to = n > 0 ? std::string(target, size_t(n)) : std::string("?");
    return "is a symbolic link to '" + to + "'; refusing to replace it (pass the link's target to write there)";
  }
  if (!S_ISREG(st.st_mode)) return kind_of(st.st_mode) + "; refusing to replace it";
  return {};
}

Status commit_files(const std::vector<FileContent>& files) {
  for (const FileContent& f : files)
    if (std::string why = output_refusal(f.path); !why.empty()) return Status::error(f.path + ": " + why);
  TemporaryFiles temporaries;
  for (const FileContent& f : files) {
    int fd = -1;
    std::string tmp;
    if (Status s = create_temporary(f.path, "", fd, tmp); !s) return s;
    temporaries.paths.push_back(tmp);
    Status written = write_all(fd, tmp, f.path, f.data, f.size);
    if (::close(fd) != 0 && written)
      written = Status::error(f.path + ": cannot write '" + tmp + "': " + std::strerror(errno));
    if (!written) return written;
  }
  for (size_t i = 0; i < files.size(); ++i) {
    if (std::string why = output_refusal(files[i].path); !why.empty())
      return Status::error(files[i].path + ": " + why);  // changed while we wrote
    if (std::rename(temporaries.paths[i].c_str(), files[i].path.c_str()) != 0)
      return Status::error(files[i].path + ": cannot rename the temporary file into place: " + std::strerror(errno));
    temporaries.paths[i].clear();  // renamed: nothing left to remove (unlink("") fails harmlessly)
  }
  return {};
}

Status commit_file(const std::string& path, const std::string& text) {
  return commit_files({{path, reinterpret_cast<const uint8_t*>(text.data()), text.size()}});
}

Status make_temporary_beside(const std::string& path, const std::string& suffix, std::string& temporary) {
  if (std::string why = output_refusal(path); !why.empty()) return Status::error(path + ": " + why);
  int fd = -1;
  if (Status s = create_temporary(path, suffix, fd, temporary); !s) return s;
  ::close(fd);
  return {};
}

Status commit_temporary(const std::string& temporary, const std::string& path) {
  std::string why = output_refusal(path);
  if (why.empty() && std::rename(temporary.c_str(), path.c_str()) != 0)
    why = std::string("cannot rename the temporary file into place: ") + std::strerror(errno);
  if (why.empty()) return {};
  ::unlink(temporary.c_str());
  return Status::error(path + ": " + why);
}

}  // namespace lintel
