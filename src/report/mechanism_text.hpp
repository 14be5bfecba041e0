#pragma once
// `linkage solve --mechanism FILE` as text, in the layout of the homework's worked
// solution: inputs and definitions, inertia, each joint's constraint at three levels,
// each body's forces, Newton-Euler per body, then each case and the agreement table.
#include <string>
#include <utility>
#include <vector>

#include "report/mechanism_solution.hpp"
#include "report/report_options.hpp"

namespace linkage {

/// "Case 3: four equations in generalized coordinates, no pin force": a case's heading.
[[nodiscard]] std::string case_heading(const CaseSystem& c);
/// The lines printed under "Equations, one per row of A q = B:", as printed (indented
/// four columns, each row labelled, long rows wrapped to options.width).
[[nodiscard]] std::vector<std::string> case_equation_lines(const sym::System& system, const CaseSystem& c,
                                                           const ReportOptions& options);

/// A case's heading and equations as the Unicode text report prints them (80 columns),
/// without solving it: what `linkage render --show equations` draws.
struct CaseEquations {
  std::string heading;
  std::vector<std::string> lines;
};
[[nodiscard]] CaseEquations case_equations(const sym::System& system, CaseId id);
/// The same as a `Text` {heading, lines}: render's EquationsText, which report may not
/// name, for `linkage render --show equations` and a lesson's render step alike.
template <class Text>
[[nodiscard]] Text case_equations_as(const sym::System& system, int case_id) {
  CaseEquations e = case_equations(system, static_cast<CaseId>(case_id));
  return Text{std::move(e.heading), std::move(e.lines)};
}

[[nodiscard]] std::string mechanism_text(const MechanismSolution& solution, const ReportOptions& options);

}  // namespace linkage
