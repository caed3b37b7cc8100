// README's table of the CLI's work limits against the constants `lintel` checks
// (apps/lintel/resource_budget.h): each row naming a constant must show its value.
#include "resource_budget.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <regex>

namespace lintel::cli {
namespace {

std::string readme() {
  std::ifstream in(std::string(LINTEL_SOURCE_DIR) + "/README.md", std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The number in the README's table row that names `constant`, digits grouped by spaces.
uint64_t documented(const std::string& constant) {
  const std::string text = readme();
  const std::regex row("\\| ([0-9 ]+) \\(`" + constant + "`\\) \\|");
  std::smatch m;
  if (!std::regex_search(text, m, row)) return 0;
  std::string digits = m[1];
  digits.erase(std::remove(digits.begin(), digits.end(), ' '), digits.end());
  return std::stoull(digits);
}

TEST(CliLimitsDoc, ReadmeTableMatchesTheConstants) {
  EXPECT_EQ(documented("kMaxRenderSurfels"), kMaxRenderSurfels);
  EXPECT_EQ(documented("kMaxWalkCellFrames"), kMaxWalkCellFrames);
}

}  // namespace
}  // namespace lintel::cli
