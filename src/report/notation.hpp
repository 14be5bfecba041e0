#pragma once
// How the reports spell things in each style: the input symbols (θ₁ / th1 /
// \theta_1), the unknowns, units, and one row of A q = B as an equation,
//   (3.1)  I θ̈₁ + D sin θ₁ Fx - D cos θ₁ Fy = 0
// built from the printed entries of symbolic_system(), never retyped.
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "formulations/expr.hpp"
#include "formulations/unknowns.hpp"
#include "model/inputs.hpp"
#include "report/formula.hpp"

namespace linkage {

/// The input `key` as a symbol with its value (exact: substituted as given).
[[nodiscard]] Symbol input_symbol(const InputKey& key, const Inputs& inputs);

/// The name of an unknown in `style` (ẍ₁, x1'', \ddot{x}_1).
[[nodiscard]] std::string_view unknown_name(Unknown u, expr::Style style);

/// An ASCII unit ("kg m^2", "m/s^2") in `style`: "kg m²"; LaTeX "\mathrm{kg\,m^2}".
[[nodiscard]] std::string unit_text(std::string_view ascii_unit, expr::Style style);

/// The pieces joined. Appending only also sidesteps GCC 12's false -Wrestrict on
/// `"literal" + std::string` (GCC bug 105329).
[[nodiscard]] std::string concat(std::initializer_list<std::string_view> pieces);

/// An equation label in parentheses: "1.1" -> "(1.1)".
[[nodiscard]] std::string parenthesized(std::string_view label);

/// One row of A q = B written as an equation.
struct EquationSides {
  std::string lhs;  // e.g. "m ẍ₁ - Fx"
  std::string rhs;  // e.g. "0"
};
/// Each nonzero entry of `A_row` times its unknown, zero terms skipped, "1/m Fx"
/// written "Fx/m", a sum coefficient in parentheses; the right side is `B_entry`.
/// `A_row` and `B_entry` are symbolic_system() entries in `style`. In text styles the
/// left side carries kBreakMark before each term's sign.
[[nodiscard]] EquationSides equation_sides(const std::vector<std::string>& A_row, const std::string& B_entry,
                                           const std::vector<Unknown>& unknowns, expr::Style style);

}  // namespace linkage
