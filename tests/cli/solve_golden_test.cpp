// Golden files of `linkage solve` for the spec's example, in tests/data/solve/. Text is
// checked in ASCII and in Unicode (forced, so the locale does not matter), LaTeX,
// Markdown and JSON byte for byte: the output is deterministic. Two more hold Case 3 in
// Lagrange's form (--form lagrange) for a tree and a closed loop. And `linkage modes` in
// LaTeX and Markdown (tests/data/modes/): the double pendulum and the four-bar on a spring.
//
// Regenerate after an intended change, then review the diff:
//   LINKAGE_UPDATE_GOLDENS=1 ctest --test-dir build -R SolveGolden
#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>

#include "support/test_support.hpp"

namespace linkage {
namespace {

struct Golden {
  const char* file;
  std::vector<std::string> args;
  const char* folder = "solve";  // under tests/data
};

const std::vector<Golden>& goldens() {
  static const std::vector<Golden> list = {
      {"example-all-ascii.txt", {"solve", "--ascii"}},
      {"example-case1-unicode.txt", {"solve", "--case", "1", "--unicode"}},
      {"example-all.tex", {"solve", "--format", "latex"}},
      {"example-all.md", {"solve", "--format", "markdown"}},
      {"example-all.json", {"solve", "--format", "json"}},
      // Case 3 in Lagrange's form: a tree and a closed loop.
      {"lagrange-double-pendulum-unicode.txt",
       {"solve", "--mechanism", "double-pendulum", "--case", "3", "--form", "lagrange", "--unicode"}},
      {"lagrange-slider-crank-ascii.txt",
       {"solve", "--mechanism", "slider-crank", "--case", "3", "--form", "lagrange", "--ascii"}},
      {"double-pendulum.tex", {"modes", "--mechanism", "double-pendulum", "--format", "latex"}, "modes"},
      {"double-pendulum.md", {"modes", "--mechanism", "double-pendulum", "--format", "markdown"}, "modes"},
      {"four-bar-spring.tex", {"modes", "--mechanism", "four-bar-spring", "--format", "latex"}, "modes"},
      {"four-bar-spring.md", {"modes", "--mechanism", "four-bar-spring", "--format", "markdown"}, "modes"},
  };
  return list;
}

std::filesystem::path golden_path(const Golden& golden) {
  return std::filesystem::path(LINKAGE_SOURCE_DIR) / "tests" / "data" / golden.folder / golden.file;
}

// The first line where two texts differ, for a readable failure.
std::string first_difference(const std::string& expected, const std::string& actual) {
  std::istringstream a(expected), b(actual);
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, la));
    const bool more_b = static_cast<bool>(std::getline(b, lb));
    if (!more_a && !more_b) return "(identical lines; differing line endings?)";
    if (la != lb || more_a != more_b)
      return "line " + std::to_string(line) + "\n  golden: " + (more_a ? la : "<end>") +
             "\n  actual: " + (more_b ? lb : "<end>");
  }
}

class SolveGolden : public testing::TestWithParam<Golden> {};

TEST_P(SolveGolden, MatchesTheFile) {
  const Golden& golden = GetParam();
  const test::RunResult r = test::run_linkage(golden.args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto path = golden_path(golden);
  const char* update = std::getenv("LINKAGE_UPDATE_GOLDENS");
  if (update != nullptr && std::string(update) == "1") {
    test::write_text(path, r.out);
    GTEST_SKIP() << "wrote " << path;
  }
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " missing; run with LINKAGE_UPDATE_GOLDENS=1";
  const std::string expected = test::read_text(path);
  EXPECT_TRUE(expected == r.out) << golden.file << " differs at " << first_difference(expected, r.out)
                                 << "\n(regenerate: LINKAGE_UPDATE_GOLDENS=1 ctest -R SolveGolden, then review)";
  // Deterministic: a second run prints the same bytes.
  EXPECT_TRUE(test::run_linkage(golden.args).out == r.out);
}

INSTANTIATE_TEST_SUITE_P(Example, SolveGolden, testing::ValuesIn(goldens()),
                         [](const testing::TestParamInfo<Golden>& param) {
                           std::string name = param.param.folder == std::string("solve") ? "" : "modes_";
                           for (const char* c = param.param.file; *c != '\0'; ++c)
                             name += std::isalnum(static_cast<unsigned char>(*c)) != 0 ? *c : '_';
                           return name;
                         });

}  // namespace
}  // namespace linkage
