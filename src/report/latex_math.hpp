#pragma once
// LaTeX pieces shared by the LaTeX and Markdown reports: the derivation steps as
// align rows, matrices as bmatrix, the labelled equations of a case.
#include <string>
#include <string_view>
#include <vector>

#include "report/derivation.hpp"
#include "report/worked_solution.hpp"

namespace linkage {

/// Text-mode LaTeX with the special characters (& % $ # _ { } ~ ^ \) escaped.
[[nodiscard]] std::string latex_escape(std::string_view text);

/// Rows for an align*/aligned environment, two per step: "quantity &= formula", then
/// "&= substituted = value unit", e.g. I_{zz}^{C} &= \frac{m \left(w^2 + L^2\right)}{12}.
[[nodiscard]] std::string derivation_rows(const DerivationGroup& group, int digits, std::string_view indent);

/// A bmatrix of LaTeX entries, one row per line; non-empty `row_comments` end each row
/// as a LaTeX comment ("% (1.1)"), which Markdown math must not contain.
[[nodiscard]] std::string bmatrix(const std::vector<std::vector<std::string>>& rows,
                                  const std::vector<std::string>& row_comments, std::string_view indent);

/// How matrix_equation lays out A q = B.
struct MatrixLayout {
  bool numeric = false;              // numbers (to `digits`) instead of symbolic_system() entries
  bool row_comments = false;         // "% (1.1)" after each row of A and B (LaTeX only, not Markdown math)
  bool break_before_equals = false;  // "A q \\ = B", for a multline* environment
};

/// The case's A q = B as three bmatrices.
[[nodiscard]] std::string matrix_equation(const CaseSolution& c, const MatrixLayout& layout, int digits,
                                          std::string_view indent);

/// The solution as q = [values] with a column of units.
[[nodiscard]] std::string solution_equation(const CaseSolution& c, int digits, std::string_view indent);

/// The labelled rows "lhs &= rhs" of the case's equations, without the labels.
[[nodiscard]] std::vector<std::string> equation_rows(const CaseSolution& c);

}  // namespace linkage
