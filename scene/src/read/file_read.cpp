// POSIX stat + stdio: the size is known before the buffer is allocated, and anything that is not
// a regular file is refused without being opened for reading.
#include "read/file_read.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace lintel::scene_read {

std::string regular_file_size(const std::string& path, size_t& size) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::strerror(errno);
  if (S_ISDIR(st.st_mode)) return "is a directory";
  if (!S_ISREG(st.st_mode)) return "is not a regular file";
  size = static_cast<size_t>(st.st_size);
  return {};
}

std::string read_file_bounded(const std::string& path, size_t max_bytes, std::vector<uint8_t>& out) {
  out.clear();
  size_t size = 0;
  if (std::string why = regular_file_size(path, size); !why.empty()) return why;
  if (size > max_bytes)
    return "is " + std::to_string(size) + " bytes, over the limit of " + std::to_string(max_bytes) + " bytes";
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) return std::strerror(errno);
  out.resize(size);
  const size_t got = size ? std::fread(out.data(), 1, size, file.get()) : 0;
  if (got != size) {
    out.clear();
    return "read error after " + std::to_string(got) + " of " + std::to_string(size) + " bytes";
  }
  return {};
}

std::string directory_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string join_path(const std::string& dir, const std::string& file) {
  if (dir.empty()) return file;
  return dir.back() == '/' ? dir + file : dir + "/" + file;
}

}  // namespace lintel::scene_read
