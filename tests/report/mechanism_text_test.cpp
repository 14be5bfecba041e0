// The worked derivation of any mechanism as text: for the homework, built by the general
// procedure, each case's equations and symbolic matrices print as the golden file
// (tests/data/solve/example-all-ascii.txt) prints them.
#include "report/mechanism_text.hpp"

#include <gtest/gtest.h>

#include "support/mechanisms_in_code.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

// The lines of `text` from the line equal to `first` up to (not including) the first line
// that starts with `until`.
std::string section(const std::string& text, const std::string& first, const std::string& until) {
  const auto begin = text.find(first + "\n");
  if (begin == std::string::npos) return "<missing " + first + ">";
  const auto end = text.find("\n" + until, begin);
  return text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

ReportOptions ascii() {
  ReportOptions o;
  o.text_style = Style::ascii;
  return o;
}

TEST(MechanismText, HomeworkCaseEquationsAsTheGolden) {
  const MechanismSolution s =
      work_out_mechanism(built::homework(), {CaseId::maximal, CaseId::generalized, CaseId::reduced});
  const std::string text = mechanism_text(s, ascii());
  const std::string golden =
      test::read_text(std::filesystem::path(LINKAGE_SOURCE_DIR) / "tests" / "data" / "solve" / "example-all-ascii.txt");
  for (const char* c : {"1", "2", "3"}) {
    const std::string start = std::string("  Equations, one per row of A q = B:");
    // Each case's equations and symbolic A | B, up to the numeric matrices.
    const std::string heading = std::string("Case ") + c + ": ";
    const auto in_golden = golden.find(heading);
    const auto in_ours = text.find(heading);
    ASSERT_NE(in_golden, std::string::npos);
    ASSERT_NE(in_ours, std::string::npos) << text;
    EXPECT_EQ(section(text.substr(in_ours), start, "  Numeric A | B:"),
              section(golden.substr(in_golden), start, "  Numeric A | B:"))
        << "Case " << c;
  }
}

TEST(MechanismText, FourBarPrintsEveryPart) {
  const MechanismSolution s =
      work_out_mechanism(built::four_bar(), {CaseId::maximal, CaseId::generalized, CaseId::reduced});
  const std::string text = mechanism_text(s, ascii());
  for (const char* part : {"Inputs and definitions", "Moments of inertia", "Joint B: pin", "(closes a loop)",
                           "Forces and moments on each body", "Newton-Euler equations", "Case 3: ", "The cases agree",
                           "The loop through B was closed"})
    EXPECT_NE(text.find(part), std::string::npos) << part << "\n" << text;
  EXPECT_EQ(text.find("nan"), std::string::npos);
}

}  // namespace
}  // namespace linkage
