#pragma once
// How the reports spell what is not an expression: numbers, units, labels, and the
// two sides of an equation (expression_print.hpp prints the expressions themselves).
#include <initializer_list>
#include <string>
#include <string_view>

#include "core/style.hpp"

namespace linkage {

/// Marks the places where a long text formula may be wrapped (before the operator of a
/// sum); text_layout and latex_math break there and remove the marks.
inline constexpr char kBreakMark = '\x1f';

/// A number as a report prints it: `digits` significant digits, or the shortest
/// round-trip form when `digits` is 0; LaTeX writes an exponent as "\times 10^{-5}".
[[nodiscard]] std::string format_number(double value, Style style, int digits);

/// An ASCII unit ("kg m^2", "m/s^2") in `style`: "kg m²"; LaTeX "\mathrm{kg\,m^2}".
[[nodiscard]] std::string unit_text(std::string_view ascii_unit, Style style);

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

}  // namespace linkage
