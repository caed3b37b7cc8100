// Reading whole files with a size limit checked before anything is allocated: the scene file
// itself and the external buffers it names go through here, so that a path to a huge file, a
// directory or a device (/dev/zero) ends in a message rather than in memory exhaustion.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lintel::scene_read {

// Size of the regular file at `path`. Returns an empty string on success, otherwise a reason
// ("No such file or directory", "is a directory", "is not a regular file").
std::string regular_file_size(const std::string& path, size_t& size);

// Reads the regular file at `path` (at most `max_bytes`) into `out`. Empty string on success,
// otherwise a one-line reason.
std::string read_file_bounded(const std::string& path, size_t max_bytes, std::vector<uint8_t>& out);

// The directory part of `path` ("scenes/a.gltf" -> "scenes", "a.gltf" -> "."), used to resolve
// external buffer URIs.
std::string directory_of(const std::string& path);

// `dir` + "/" + `file` the way tinygltf joins them (no doubled slash).
std::string join_path(const std::string& dir, const std::string& file);

}  // namespace lintel::scene_read
