// docs/problem.md states the problem with the equations exactly as `linkage solve
// --format markdown` prints them, so the page cannot drift from the program.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "support/test_support.hpp"

namespace linkage {
namespace {

const std::string& problem_page() {
  static const std::string text = test::read_text(std::filesystem::path(LINKAGE_SOURCE_DIR) / "docs" / "problem.md");
  return text;
}

std::string solve_markdown() {
  const test::RunResult r = test::run_linkage({"solve", "--format", "markdown"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

TEST(ProblemPage, QuotesEveryLabelledEquationAsPrinted) {
  std::istringstream printed(solve_markdown());
  int equations = 0;
  for (std::string line; std::getline(printed, line);) {
    if (line.find("\\text{(") == std::string::npos) continue;
    EXPECT_NE(problem_page().find(line), std::string::npos) << "docs/problem.md lacks\n" << line;
    ++equations;
  }
  EXPECT_EQ(equations, 8 + 6 + 4);
}

TEST(ProblemPage, QuotesEachCasesSymbolicMatrixAsPrinted) {
  const std::string printed = solve_markdown();
  const std::string start = "In matrix form, rows in the order of the equations:\n\n";
  int matrices = 0;
  for (std::size_t at = printed.find(start); at != std::string::npos; at = printed.find(start, at)) {
    at += start.size();
    const std::size_t end = printed.find("\n$$\n", at + 3);
    ASSERT_NE(end, std::string::npos);
    const std::string block = printed.substr(at, end + 3 - at);
    EXPECT_NE(problem_page().find(block), std::string::npos) << "docs/problem.md lacks\n" << block;
    ++matrices;
  }
  EXPECT_EQ(matrices, 3);
}

}  // namespace
}  // namespace linkage
