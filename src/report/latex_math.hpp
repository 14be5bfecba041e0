#pragma once
// LaTeX pieces shared by the LaTeX and Markdown reports of a mechanism: headings, the derivation steps as align rows,
// equations wrapped at their top-level sums, matrices as bmatrix, the labelled equations of a case, the solution, the
// residual line and the table of how closely the cases agree.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "report/notation.hpp"

namespace linkage {

/// Text-mode LaTeX with the special characters (& % $ # _ { } ~ ^ \) escaped.
[[nodiscard]] std::string latex_escape(std::string_view text);

/// A bold run-in heading after a "% ---- title ----" comment line, then `text` (LaTeX).
[[nodiscard]] std::string latex_heading(std::string_view title, std::string_view text);

/// Roughly how many characters wide LaTeX math prints (\sin 3, \theta 1, \frac 0, a
/// binary operator with its spacing 2).
[[nodiscard]] std::size_t visible_length(std::string_view tex);

/// `tex` with kBreakMark before each + and - of its top-level sum (outside braces and
/// parentheses), where the row layouts below may wrap it.
[[nodiscard]] std::string mark_sums(std::string_view tex);

/// One step of a derivation: "quantity &= formula", then "&= substituted = result".
/// `formula` and `substituted` may carry kBreakMark; an empty `substituted` leaves its
/// row out, an empty `formula` too ("quantity &= result").
struct MathStep {
  std::string quantity;
  std::string formula;
  std::string substituted;
  std::string result;  // value and unit, e.g. "0.11\ \mathrm{m}"
};

/// Rows for an align*/aligned environment, steps separated by \\[1ex].
[[nodiscard]] std::string step_rows(const std::vector<MathStep>& steps, std::string_view indent);

/// "lhs &= rhs" followed by `suffix` (a \tag or "&& \text{...}"), wrapped at the sums of
/// either side (see mark_sums) when longer than `limit` visible characters: the left
/// side's rows right-aligned before the relation, the right side's continued with \quad.
[[nodiscard]] std::string equation_row(std::string_view lhs, std::string_view rhs, std::string_view suffix,
                                       std::size_t limit, std::string_view indent);

/// A bmatrix of LaTeX entries, one row per line; non-empty `row_comments` end each row
/// as a LaTeX comment ("% (1.1)"), which Markdown math must not contain.
[[nodiscard]] std::string bmatrix(const std::vector<std::vector<std::string>>& rows,
                                  const std::vector<std::string>& row_comments, std::string_view indent);

/// A short column vector on one line: \begin{bmatrix} a \\ b \end{bmatrix}.
[[nodiscard]] std::string inline_column(const std::vector<std::string>& entries, std::string_view indent,
                                        std::string_view environment = "bmatrix");

/// A column vector with one entry per line (and the row comments as in bmatrix).
[[nodiscard]] std::string column_vector(const std::vector<std::string>& entries,
                                        const std::vector<std::string>& row_comments, std::string_view indent);

/// How matrix_equation lays out A q = B.
struct MatrixLayout {
  bool numeric = false;              // numbers (to `digits`) instead of symbolic_system() entries
  bool row_comments = false;         // "% (1.1)" after each row of A and B (LaTeX only, not Markdown math)
  bool break_before_equals = false;  // "A q \\ = B", for a multline* environment
};

/// A q = B as three bmatrices from printed entries (`layout.numeric` is not consulted);
/// `labels` (parenthesized) end the rows as comments when `layout.row_comments`.
[[nodiscard]] std::string matrix_equation(const std::vector<std::vector<std::string>>& A,
                                          const std::vector<std::string>& unknowns, const std::vector<std::string>& B,
                                          const std::vector<std::string>& labels, const MatrixLayout& layout,
                                          std::string_view indent);

/// The solution as q = [values] with a column of units, all printed LaTeX.
[[nodiscard]] std::string solution_equation(const std::vector<std::string>& unknowns,
                                            const std::vector<std::string>& values,
                                            const std::vector<std::string>& units, std::string_view indent);

/// One unknown of a solution table.
struct SolutionRow {
  std::string latex;  // the unknown's name
  double value = 0;
  std::string unit;  // ASCII, e.g. "m/s^2" (see unit_text)
  std::string meaning;
};

/// The solution as a Markdown table: unknown, value, unit, meaning.
[[nodiscard]] std::string solution_markdown(const std::vector<SolutionRow>& rows, int digits);

/// "\lVert A q - B \rVert_2 = ..., \qquad \kappa_2(A) = ...".
[[nodiscard]] std::string residual_line(double residual, double condition);

/// One quantity across the solved cases, for the closing table: its LaTeX name, its
/// value in each case (none where the case has none), which of them are recovered
/// rather than solved for, and the largest difference.
struct AgreementRow {
  std::string latex;
  std::vector<std::optional<double>> values;
  std::vector<bool> recovered;
  double max_abs_difference = 0;
};

/// The closing table as a LaTeX tabular (case numbers as column heads; $^{*}$ marks a
/// recovered value, -- a missing one).
[[nodiscard]] std::string agreement_tabular(const std::vector<int>& cases, const std::vector<AgreementRow>& rows,
                                            int digits);

/// The closing table in Markdown (\* marks a recovered value, - a missing one).
[[nodiscard]] std::string agreement_markdown(const std::vector<int>& cases, const std::vector<AgreementRow>& rows,
                                             int digits);

}  // namespace linkage
