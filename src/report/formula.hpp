#pragma once
// Formulas of the derived quantities (inertia, pin and C2 positions, energies) as small
// expression trees built at run time. Each formula is written once and yields
//   its symbolic form      I_zz^C = m (w² + L²) / 12
//   its substituted form          = 0.1 × (0.1² + 0.3²) / 12
// in Unicode, ASCII or LaTeX, and its value, which the tests check against the model
// (src/model/kinematics.cpp). The matrix entries are not formulas of this kind: they
// come from the compile-time definitions in src/formulations.
#include <memory>
#include <string>
#include <string_view>

#include "formulations/expr.hpp"

namespace linkage {

/// A named quantity with its three spellings and its value.
struct Symbol {
  std::string_view unicode;
  std::string_view ascii;
  std::string_view latex;
  double value = 0;
  /// An input: substituted in shortest round-trip form (as the user gave it), where a
  /// derived quantity is substituted rounded to the report's significant digits.
  bool exact = false;

  [[nodiscard]] std::string_view spelling(expr::Style style) const;
};

/// Whether symbols print as names or as their values.
enum class Spelling { symbolic, substituted };

/// Marks the places where a long text formula may be wrapped (before the operator of a
/// sum); text_layout and latex_math break there and remove the marks.
inline constexpr char kBreakMark = '\x1f';

class Formula {
 public:
  /// Symbols convert implicitly, so formulas read like the math: `m * square(w)`.
  Formula(const Symbol& symbol);  // NOLINT(google-explicit-constructor)
  /// A non-negative integer constant.
  [[nodiscard]] static Formula integer(int n);

  [[nodiscard]] double eval() const;
  /// The formula in `style`; `digits` significant digits for substituted derived values.
  /// Carries kBreakMark before each sum operator (see strip_marks).
  [[nodiscard]] std::string print(expr::Style style, Spelling spelling, int digits) const;

  friend Formula operator+(const Formula& a, const Formula& b);
  friend Formula operator-(const Formula& a, const Formula& b);
  friend Formula operator*(const Formula& a, const Formula& b);
  friend Formula operator/(const Formula& a, const Formula& b);
  friend Formula square(const Formula& a);
  friend Formula sin(const Formula& a);
  friend Formula cos(const Formula& a);

  struct Node;

 private:
  explicit Formula(std::shared_ptr<const Node> node) : node_(std::move(node)) {}
  std::shared_ptr<const Node> node_;
};

// Declared at namespace scope too, so two Symbols combine through the implicit conversion.
Formula operator+(const Formula& a, const Formula& b);
Formula operator-(const Formula& a, const Formula& b);
Formula operator*(const Formula& a, const Formula& b);
Formula operator/(const Formula& a, const Formula& b);
Formula square(const Formula& a);
Formula sin(const Formula& a);
Formula cos(const Formula& a);

/// A number as a report prints it: `digits` significant digits, or the shortest
/// round-trip form when `digits` is 0; LaTeX writes an exponent as "\times 10^{-5}".
[[nodiscard]] std::string format_number(double value, expr::Style style, int digits);

}  // namespace linkage
