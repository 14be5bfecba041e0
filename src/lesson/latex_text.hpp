#pragma once
// LaTeX math as Unicode text, so a lesson's formulas read in a terminal:
//   \frac{m\,(w^2 + L^2)}{12}  ->  (m (w² + L²))/12
//   \ddot{\theta}_1            ->  θ̈₁
// Greek letters, accents (\dot, \ddot, \hat, \bar), sub- and superscripts (Unicode
// digits and signs, else _x / ^(x)), \frac, common operators and functions,
// \left/\right, spacing and font commands, aligned environments (& is dropped and a
// double backslash breaks the line) and matrices (written [a, b; c, d]). Anything
// unknown is kept as written without its backslash. Math nested deeper than
// kMaxNesting (core/limits.hpp) is refused, so hostile text cannot exhaust the stack.
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace linkage::lesson {

/// Thrown (exit code 2) for math nested more than kMaxNesting levels deep. `at` points
/// into the text given to latex_to_unicode, at the first level too many, so a caller
/// holding the whole text can say where that is.
class LatexNestingError : public Error {
 public:
  explicit LatexNestingError(const char* at);
  [[nodiscard]] const char* at() const { return at_; }

 private:
  const char* at_;
};

[[nodiscard]] std::string latex_to_unicode(std::string_view latex);

}  // namespace linkage::lesson
