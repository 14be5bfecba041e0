#pragma once
// `linkage solve` of any mechanism as LaTeX and as Markdown: the worked derivation in the
// sections and order of mechanism_text (inputs and definitions, inertia, each joint's
// constraint at three levels, the forces on each body, Newton-Euler per body, each case,
// the agreement of the cases), laid out as the homework's latex_report and
// markdown_report lay out theirs.
//
// Long equations wrap at the operators of their top-level sums (latex_math's
// equation_row). A system of at most eight unknowns whose A fits the homework's width
// prints A q = B as the homework does, in one display. A wider one (a four-bar's Case 1
// has 17 unknowns) prints A in blocks of columns, A_1, A_2, ..., each beside the unknowns
// q_1, q_2, ... its columns multiply, then B, under the sentence A_1 q_1 + A_2 q_2 + ... =
// B; the symbolic and the numeric A split at the same columns.
#include <cstddef>
#include <string>

#include "report/mechanism_solution.hpp"
#include "report/report_options.hpp"

namespace linkage {

/// A LaTeX fragment (ASCII; needs amsmath) to paste into a document or a slide.
[[nodiscard]] std::string mechanism_latex(const MechanismSolution& solution, const ReportOptions& options);

/// Markdown for a Git forge: a heading per section, tables, math in $$ blocks.
[[nodiscard]] std::string mechanism_markdown(const MechanismSolution& solution, const ReportOptions& options);

/// A clip's page holds the worked equations up to this many bytes of HTML (a long chain's
/// run to megabytes; the largest shipped, coupled-pendulums' Case 1, is 182 kB).
inline constexpr std::size_t kPageEquationsLimit = 1'000'000;

/// That Markdown as HTML with MathML (markdown_to_html), as a clip's page shows it beside the
/// clip; longer than `limit` bytes, a paragraph saying so and which `linkage solve` prints it.
[[nodiscard]] std::string mechanism_html(const MechanismSolution& solution, const ReportOptions& options,
                                         std::size_t limit = kPageEquationsLimit);

}  // namespace linkage
