// The stability suite: "where methods fail". Generated cases that break portal engines — eyes
// on and just off portal planes, grazing views, portals nearly parallel to the near plane, huge
// coordinates, long chains, rings of 2..256 cells, non-uniform cell scales, the divide-before-
// near-clip projection — each run through every method and scored like the accuracy benchmark
// (termination within bound, false negatives, bounds drift against exact, pops).
#pragma once

#include <lintel/reference/accuracy_bench.h>

#include <string>
#include <vector>

namespace lintel {

struct StabilityOptions {
  uint32_t views_per_case = 30;
  uint32_t resolution = 256;
  bool progress = true;
};

struct StabilityResult {
  std::vector<MethodScore> scores;      // scene = the case label
  std::vector<std::string> case_notes;  // "label: what it is", one per case
  double wall_s = 0.0;
};

Status run_stability_suite(const MethodFactory& methods, const StabilityOptions& options, StabilityResult& out);

// DIR/stability.md (a markdown table) and DIR/stability.json.
Status write_stability_outputs(const StabilityResult& result, const std::string& dir);

}  // namespace lintel
