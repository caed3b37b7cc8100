// The error channel for bad data (files, cameras, devices): a status carrying a kind and a
// one-line message that names the file, the element and the fault. Broken preconditions assert
// instead. No exceptions cross Lintel's public API.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

namespace lintel {

// Why an operation failed; the CLI maps each kind to its exit code (BadInput 2, the others 1).
enum class StatusKind : uint8_t {
  Ok,
  BadInput,     // the caller's data or arguments are wrong: a file, a camera, an option
  Unsupported,  // valid input this device or build cannot do: a missing Vulkan feature, a limit
  Internal,     // Lintel's own fault: a GPU/CPU mismatch, a Vulkan call that should not fail
};

class [[nodiscard]] Status {
 public:
  Status() = default;  // success
  // Bad input (the common case): one line naming the file, element and fault.
  static Status error(std::string message) { return Status(StatusKind::BadInput, std::move(message)); }
  static Status unsupported(std::string message) { return Status(StatusKind::Unsupported, std::move(message)); }
  static Status internal(std::string message) { return Status(StatusKind::Internal, std::move(message)); }

  bool ok() const { return kind_ == StatusKind::Ok; }
  explicit operator bool() const { return ok(); }
  StatusKind kind() const { return kind_; }
  // One line, e.g. "scenes/x.gltf: node 5 'Door': portal polygon is not planar (...)".
  const std::string& message() const { return message_; }

 private:
  Status(StatusKind kind, std::string message)
      : kind_(kind), message_(message.empty() ? "unknown error" : std::move(message)) {}
  StatusKind kind_ = StatusKind::Ok;
  std::string message_;
};

// The process exit code a command-line tool should use for a failed status: 2 for bad input,
// 1 for everything else.
inline int exit_code_of(const Status& status) {
  return status.ok() ? 0 : status.kind() == StatusKind::BadInput ? 2 : 1;
}

}  // namespace lintel
