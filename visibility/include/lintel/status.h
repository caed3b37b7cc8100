// The error channel for bad data (files, cameras, devices): a status carrying a one-line message
// that names the file, the element and the fault. Broken preconditions assert instead.
// No exceptions cross Lintel's public API.
#pragma once

#include <string>
#include <utility>

namespace lintel {

class Status {
 public:
  Status() = default;  // success
  static Status error(std::string message) { return Status(std::move(message)); }

  bool ok() const { return message_.empty(); }
  explicit operator bool() const { return ok(); }
  // One line, e.g. "scenes/x.gltf: node 5 'Door': portal polygon is not planar (...)".
  const std::string& message() const { return message_; }

 private:
  explicit Status(std::string message) : message_(message.empty() ? "unknown error" : std::move(message)) {}
  std::string message_;
};

}  // namespace lintel
