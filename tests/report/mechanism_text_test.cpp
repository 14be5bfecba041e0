// The worked derivation of any mechanism as text: for the homework, built by the general
// procedure, each case's equations and symbolic matrices print as the golden file
// (tests/data/solve/example-all-ascii.txt) prints them.
#include "report/mechanism_text.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "report/mechanism_latex.hpp"
#include "support/mechanisms_in_code.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

using test::source_path;
using test::test_mechanism;

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

// Issue 25: the derivation shows a value that reads the state as the file writes it
// (S.s, rod.theta), and how Case 1, which has no slider coordinate, writes the slider's
// names; in text, LaTeX and Markdown alike.
TEST(MechanismText, StateValuesPrintAsTheFileWritesThem) {
  const Mechanism m = load_mechanism(test_mechanism("state-loads-cart.toml"));
  const MechanismSolution s = work_out_mechanism(m, {CaseId::maximal});
  const std::string text = mechanism_text(s, ascii());
  for (const char* piece :
       {"  Values that read the state, as the file writes them:\n", "    damping of joint P: c*(1 + rod.theta^2)\n",
        "    stiffness of spring k1: k*(1 + (S.s/a)^2)\n", "    torque on rod: -0.2*S.s*rod.theta_dot\n",
        "Case 1 writes them in maximal coordinates: S.s = x_cart, S.s_dot = x_cart';"})
    EXPECT_NE(text.find(piece), std::string::npos) << piece;
  EXPECT_NE(mechanism_markdown(s, ascii()).find("- stiffness of spring k1: `k*(1 + (S.s/a)^2)`"), std::string::npos);
  const std::string latex = mechanism_latex(s, ascii());
  EXPECT_NE(latex.find("\\item stiffness of spring k1: \\texttt{"), std::string::npos);
  EXPECT_NE(latex.find("S.s $= x_{\\mathrm{cart}}$"), std::string::npos);
  // A mechanism whose values read no state prints no such part.
  EXPECT_EQ(mechanism_text(work_out_mechanism(built::four_bar(), {CaseId::maximal}), ascii()).find("Values that read"),
            std::string::npos);
}

// A gear's row holds a constant, c_G: each format defines it as the rest of the row at
// the initial state, with its value (0.3 r1 = 0.015 m with the pinion started at 0.3 rad).
TEST(MechanismText, AGearsConstantIsDefinedByTheRestOfItsRow) {
  Mechanism m = load_mechanism(source_path("mechanisms/gear-train.toml"));
  for (InitialValue& v : m.initial)
    if (v.key == "pinion.theta") v.value = 0.3;
  const MechanismSolution s = work_out_mechanism(m, {CaseId::maximal});
  EXPECT_NE(mechanism_text(s, ascii())
                .find("    c_G = r1 th_pinion + r2 th_gear at t = 0 = 0.3 r1 = 0.3 * 0.05 "
                      "= 0.015 m\n"),
            std::string::npos)
      << mechanism_text(s, ascii());
  const std::string expected = "c_G &= r_1 \\theta_{\\mathrm{pinion}} + r_2 \\theta_{\\mathrm{gear}} \\Big|_{t = 0}";
  EXPECT_NE(mechanism_latex(s, ascii()).find(expected), std::string::npos);
  EXPECT_NE(mechanism_markdown(s, ascii()).find(expected), std::string::npos);
  EXPECT_NE(mechanism_latex(s, ascii()).find("&= 0.3 r_1 = 0.015\\ \\mathrm{m}"), std::string::npos);
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

// A spring's length is a symbol of its own: defined once, in the forces section, and
// written l_k1 in the loads and every case's equations instead of the square root.
TEST(MechanismText, SpringLengthIsOneSymbolDefinedOnce) {
  Mechanism m = built::spring_pendulum(false);
  m.initial = {{"1.x", 0.2, {}}, {"1.y", -0.35, {}}, {"1.x_dot", 0.1, {}}};
  const MechanismSolution s = work_out_mechanism(m, {CaseId::maximal, CaseId::generalized, CaseId::reduced});
  const std::string text = mechanism_text(s, ascii());
  const auto definition = text.find("  l_k1 = sqrt(x1^2 + y1^2) = ");
  ASSERT_NE(definition, std::string::npos) << text;
  EXPECT_EQ(text.find("sqrt", text.find('\n', definition)), std::string::npos) << "the root is written once\n" << text;
  EXPECT_NE(text.find("(1.1)  m x1'' = x1 (k l0 / l_k1 - c (x1' x1 + y1' y1) / l_k1^2 - k)"), std::string::npos)
      << text;
  for (const char* part : {"Case 1: two equations in maximal coordinates, no joints",
                           "Case 3: two equations in generalized coordinates, no joints",
                           "V = m g y1 + k (l0 - l_k1)^2 / 2", "P = -c (x1' x1 + y1' y1)^2 / l_k1^2"})
    EXPECT_NE(text.find(part), std::string::npos) << part << "\n" << text;
  // Both ends at one place: one line naming the spring, no NaN.
  m.initial = {{"1.x", 0, {}}, {"1.y", 0, {}}};
  try {
    (void)work_out_mechanism(m, {CaseId::maximal});
    ADD_FAILURE() << "a spring of length 0 was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("spring k1 has length 0 at this state"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace linkage
