// Test-only ways into gpu::Context, kept out of the installed ContextOptions: a context on a
// device that pretends to lack features, to prove that such a device is refused (or that an
// optional feature is done without). Tests reach it through lintel_gpu_internal; never installed.
#pragma once

#include <lintel/gpu/context.h>

#include <memory>
#include <string>
#include <vector>

namespace lintel::gpu {

struct ContextTesting {
  // Context::create, treating `features` (Vulkan names, e.g. "drawIndirectFirstInstance") as
  // unsupported: the device is evaluated and created as if it lacked them.
  static Status create_pretending_missing(const ContextOptions& options, const std::vector<std::string>& features,
                                          std::unique_ptr<Context>& out) {
    return Context::create(options, features, out);
  }
};

}  // namespace lintel::gpu
