#pragma once
// Everything `linkage solve` shows, computed once and printed by each format
// (text_report, latex_report, markdown_report, json_report).
#include <array>
#include <optional>
#include <vector>

#include "formulations/formulation.hpp"
#include "model/inputs.hpp"
#include "model/kinematics.hpp"

namespace linkage {

/// One unknown across the solved cases: its value in each (in case order), and how far
/// apart they are. A case that does not solve for it yields it through its eliminated
/// equations (solution_value), e.g. Case 3's pin force from (1.2), (2.2).
struct Agreement {
  Unknown unknown{};
  std::vector<double> values;     // one per solved case, in WorkedSolution::cases order
  std::vector<bool> recovered;    // true where the case does not solve for it directly
  double max_abs_difference = 0;  // max |a - b| over every pair of cases
};

struct WorkedSolution {
  Inputs inputs;
  Derived derived;
  std::vector<CaseSolution> cases;   // in the order asked
  std::vector<Agreement> agreement;  // all eight unknowns; empty unless two or more cases
};

/// The parts of a worked solution, in the order they print: the inputs, the three
/// derivation groups, and within each case its equations and symbolic matrices, numeric
/// matrices, solution, and residual with condition number; then the cases' comparison.
enum class ReportPart { inputs, inertia, constraints, energy, symbolic, numeric, solution, residual, comparison };
inline constexpr std::size_t kReportPartCount = 9;

/// How the human-readable formats (text, LaTeX, Markdown) print.
struct ReportOptions {
  int digits = 6;                                 // significant digits; JSON always prints full precision
  expr::Style text_style = expr::Style::unicode;  // the text format's symbols: unicode or ascii
  std::size_t width = 80;                         // the text format's line width, display columns
  /// Which parts print (`linkage solve` prints all; a lesson's solve step chooses).
  std::array<bool, kReportPartCount> parts{true, true, true, true, true, true, true, true, true};
  [[nodiscard]] bool shows(ReportPart p) const { return parts[static_cast<std::size_t>(p)]; }
};

/// Solves the selected cases (each id in 1..3) at the inputs. Throws Error::input when
/// the inputs, though each in range, are so large or small that a derived quantity or
/// a matrix entry overflows, so no infinity or NaN ever reaches the output.
[[nodiscard]] WorkedSolution work_out(const Inputs& inputs, const std::vector<int>& case_ids);

}  // namespace linkage
