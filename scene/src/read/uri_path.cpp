// realpath() resolves "..", "." and every symlink of both the folder and the file, so one prefix
// comparison of the two answers "inside?" for "../../etc/passwd", "%2e%2e/...", and a link
// planted in the folder that points out of it alike.
#include "read/uri_path.h"

#include "read/file_read.h"
#include "read/gltf_preflight.h"
#include "read/load_context.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <memory>

namespace lintel::scene_read {
namespace {

bool real_path(const std::string& path, std::string& out) {
  std::unique_ptr<char, decltype(&std::free)> real(::realpath(path.c_str(), nullptr), &std::free);
  if (!real) return false;
  out = real.get();
  return true;
}

}  // namespace

std::string resolve_relative_uri(const std::string& kind, const std::string& base_dir, const std::string& uri,
                                 bool allow_outside, std::string& path) {
  const std::string shown = "'" + one_line(uri, 200) + "'";
  if (uri.empty()) return "'uri' is empty";
  if (uri.find("://") != std::string::npos) return "remote URI " + shown + " is not supported";
  const std::string decoded = decode_uri_like_tinygltf(uri);
  if (decoded.find('\0') != std::string::npos) return "URI " + shown + " contains a NUL byte";
  if (uri.front() == '/' || decoded.front() == '/')
    return "absolute path " + shown + " is not allowed (URIs are relative)";
  if (base_dir.empty()) return "external " + kind + " " + shown + " cannot be resolved without a base directory";
  path = join_path(base_dir, decoded);
  if (allow_outside) return {};
  std::string real_dir, real_file;
  if (!real_path(base_dir, real_dir))
    return "cannot resolve the scene's folder '" + base_dir + "': " + std::strerror(errno);
  if (!real_path(path, real_file)) return "cannot read " + shown + ": " + std::strerror(errno);
  const std::string prefix = real_dir == "/" ? real_dir : real_dir + "/";
  if (real_file.compare(0, prefix.size(), prefix) != 0)
    return shown + " resolves to '" + one_line(real_file, 200) + "', outside the scene's folder '" + real_dir +
           "' (allow it with --allow-outside-paths)";
  return {};
}

}  // namespace lintel::scene_read
