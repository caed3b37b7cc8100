// Writing files so that a failure leaves nothing half-written: each file goes to a temporary
// name beside its target and is renamed over it only once every file was written completely.
#pragma once

#include <lintel/status.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::scene_write {

struct FileContent {
  std::string path;
  const uint8_t* data = nullptr;
  size_t size = 0;
};

// Writes all files to "<path>.tmp", then renames them in order. On failure the temporaries are
// removed; files already renamed (only possible if a later rename fails) stay complete.
Status commit_files(const std::vector<FileContent>& files);

}  // namespace lintel::scene_write
