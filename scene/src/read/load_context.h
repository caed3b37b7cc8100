// What every step of the scene loader shares: the file label that starts each message, the
// warnings sink, and the one way elements are named ("node 7 'Door.001'", "accessor 3"), so that
// every message has the shape "<file>: <element>: <fault>" on a single line.
#pragma once

#include <lintel/status.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lintel::scene_read {

class LoadContext {
 public:
  LoadContext(std::string label, std::vector<std::string>* warnings);

  const std::string& label() const { return label_; }
  // Whether buffer and image URIs may resolve outside the scene's folder (LoadOptions).
  bool allow_outside_paths() const { return allow_outside_paths_; }
  void set_allow_outside_paths(bool allow) { allow_outside_paths_ = allow; }
  // Bytes the scene file and its buffers may take together (0: no budget beyond the limits).
  uint64_t max_memory_bytes() const { return max_memory_bytes_; }
  void set_max_memory_bytes(uint64_t bytes) { max_memory_bytes_ = bytes; }

  // "<label>: <element>: <fault>" (or "<label>: <fault>" when element is empty), one line.
  Status fail(std::string_view element, std::string_view fault) const;
  // The same shape, appended to the warnings vector (if the caller gave one).
  void warn(std::string_view element, std::string_view fault) const;

 private:
  std::string label_;
  std::vector<std::string>* warnings_;
  bool allow_outside_paths_ = false;
  uint64_t max_memory_bytes_ = 0;
};

// "node 7 'Door.001'", or "node 7" when the name is empty. Names are sanitized (see one_line).
std::string describe(std::string_view kind, size_t index, std::string_view name);

// `text` with control characters replaced by '?' and cut to `max_chars` (with "..."), so that a
// hostile name or a library message cannot break the one-line contract.
std::string one_line(std::string_view text, size_t max_chars = 160);

// Short rendering of a number for messages ("0.001", "1e+39"), 6 significant digits.
std::string number_text(double value);

}  // namespace lintel::scene_read
