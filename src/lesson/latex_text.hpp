#pragma once
// LaTeX math as Unicode text, so a lesson's formulas read in a terminal:
//   \frac{m\,(w^2 + L^2)}{12}  ->  (m (w² + L²))/12
//   \ddot{\theta}_1            ->  θ̈₁
// Greek letters, accents (\dot, \ddot, \hat, \bar), sub- and superscripts (Unicode
// digits and signs, else _x / ^(x)), \frac, common operators and functions,
// \left/\right, spacing and font commands, aligned environments (& is dropped and a
// double backslash breaks the line) and matrices (written [a, b; c, d]). Anything
// unknown is kept as written without its backslash.
#include <string>
#include <string_view>

namespace linkage::lesson {

[[nodiscard]] std::string latex_to_unicode(std::string_view latex);

}  // namespace linkage::lesson
