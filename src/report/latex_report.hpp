#pragma once
// `linkage solve --format latex` and `--format markdown`.
#include <string>

#include "report/worked_solution.hpp"

namespace linkage {

/// A LaTeX fragment to paste into a document or a slide (needs amsmath): bold run-in
/// headings, a tabular of inputs, align* for the derivation and the labelled
/// equations (\tag{1.1}), one multline* per matrix equation A q = B (bmatrix; "= B" on
/// its second line, so an 8x8 system fits the text width).
[[nodiscard]] std::string latex_report(const WorkedSolution& worked, const ReportOptions& options);

/// Markdown for a Git forge: a heading per section, tables for the inputs, solutions
/// and agreement, matrices in $$ math blocks (no LaTeX comments inside them).
[[nodiscard]] std::string markdown_report(const WorkedSolution& worked, const ReportOptions& options);

}  // namespace linkage
