// libFuzzer entry point for the scene loader (configure with CXX=clang++-14 -DLINTEL_LIBFUZZER=ON
// -DLINTEL_SANITIZE=ON so that the loader itself runs under ASan/UBSan too): every
// input must load into a consistent World or fail with one proper error line. Run e.g.
//   build-fuzz/bin/loader_libfuzzer -max_len=65536 CORPUS_DIR   (seeded with tests/scene/fixtures/good)
#include "world_invariants.h"

#include <lintel/scene_io.h>

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lintel::World world;
  std::vector<std::string> warnings;
  const lintel::Status s = lintel::load_world_from_memory(data, size, "fuzz", "", world, &warnings);
  const std::string why = s.ok() ? lintel::fuzz::world_invariant_violation(world)
                                 : lintel::fuzz::error_message_violation(s.message(), "fuzz");
  if (!why.empty()) {
    std::fprintf(stderr, "loader invariant broken: %s\n", why.c_str());
    std::abort();
  }
  return 0;
}
