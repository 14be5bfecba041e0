// Unicode math in prose becomes TeX inline math; math, code and other text stay as they are.
// LaTeX math becomes Unicode text for a terminal.
#include "report/unicode_tex.hpp"

#include <gtest/gtest.h>

#include "report/text_layout.hpp"

namespace linkage {
namespace {

TEST(UnicodeTex, SymbolsBecomeInlineMath) {
  EXPECT_EQ(tex_math_in_prose("block 1 at θ₁ = 0.1 rad"), "block 1 at $\\theta_{1}$ = 0.1 rad");
  EXPECT_EQ(tex_math_in_prose("ẍ₁ and ÿ₂ and θ̈₂"), "$\\ddot{x}_{1}$ and $\\ddot{y}_{2}$ and $\\ddot{\\theta}_{2}$");
  // Latin-1 ¹ ² ³ and · print in pdflatex text as they are (units stay upright).
  EXPECT_EQ(tex_math_in_prose("I = 0.1 kg m², g in m/s², 01 · Title, θ²"),
            "I = 0.1 kg m², g in m/s², 01 · Title, $\\theta^{2}$");
  EXPECT_EQ(tex_math_in_prose("x₁'' − 2 × 3 → ‖A‖"), "$x_{1}$'' $-$ 2 $\\times$ 3 $\\to$ $\\|$A$\\|$");
  EXPECT_EQ(tex_math_in_prose("10⁻⁹ and ⁴alone"), "10${}^{-9}$ and ${}^{4}$alone");
  EXPECT_EQ(tex_math_in_prose("[▶ clip.mp4](clip.mp4)"), "[$\\blacktriangleright$ clip.mp4](clip.mp4)");
  // pandoc does not close math at a "$" followed by a digit: the digits join the span.
  EXPECT_EQ(tex_math_in_prose("an 8×8 matrix, θ1 and θ₂2"), "an 8$\\times 8$ matrix, $\\theta 1$ and $\\theta_{2}2$");
}

TEST(UnicodeTex, MathCodeAndTypographyStay) {
  const std::string kept =
      "Say $\\theta_1 = θ$ and $$x² + y$$ and `θ₁ code` and ’quotes’ — dashes… café\n"
      "```\nθ₂ in a fence\n```\nafter θ";
  EXPECT_EQ(tex_math_in_prose(kept),
            "Say $\\theta_1 = θ$ and $$x² + y$$ and `θ₁ code` and ’quotes’ — dashes… café\n"
            "```\nθ₂ in a fence\n```\nafter $\\theta$");
  EXPECT_EQ(tex_math_in_prose(""), "");
  EXPECT_EQ(tex_math_in_prose("a $ lone dollar θ"), "a $ lone dollar $\\theta$");
}

// One table serves both ways: a symbol's TeX reads back as the symbol.
TEST(UnicodeTex, SymbolsReadBackFromTheirTex) {
  for (const char* symbol : {"α", "θ", "φ", "Ω", "∂", "×", "±", "≤", "≠", "→", "⇒", "∞", "∑", "∫", "∈", "∼"}) {
    const std::string_view tex = tex_symbol(decode_utf8(symbol, 0).cp);
    ASSERT_FALSE(tex.empty()) << symbol;
    EXPECT_EQ(latex_to_unicode(tex), symbol) << tex;
  }
  EXPECT_EQ(tex_symbol(U'·'), "");  // Latin-1: pdflatex prints it as it is
  EXPECT_EQ(latex_to_unicode("\\cdot \\varepsilon \\epsilon \\phi \\ldots"), "· ε ε φ …");
}

TEST(LatexToUnicode, FormulasReadInATerminal) {
  EXPECT_EQ(latex_to_unicode("I_{zz}^C = \\frac{m\\,(w^2 + L^2)}{12}"), "I_zz^C = (m (w² + L²))/12");
  EXPECT_EQ(latex_to_unicode("\\ddot{\\theta}_1 + \\dot{x}_2"), "θ\u0308₁ + x\u0307₂");
  EXPECT_EQ(latex_to_unicode("D = \\frac{L}{2} - b"), "D = L/2 - b");
  EXPECT_EQ(latex_to_unicode("\\sin\\theta_1 \\cdot F_x"), "sin θ₁ · F_x");
  EXPECT_EQ(latex_to_unicode("-\\dot\\theta\\sin\\theta (\\cos x)"), "-θ\u0307 sin θ (cos x)");
  EXPECT_EQ(latex_to_unicode("\\begin{aligned} a &= b \\\\ c &= d \\end{aligned}"), "a = b\nc = d");
  EXPECT_EQ(latex_to_unicode("\\left( x \\right)^{2}"), "(x)²");
  EXPECT_EQ(latex_to_unicode("\\lVert r^{CP} \\rVert"), "‖ r^CP ‖");
  EXPECT_EQ(latex_to_unicode("10^{-4}\\ \\mathrm{kg\\,m^2}"), "10⁻⁴ kg m²");
  EXPECT_EQ(latex_to_unicode("\\int_{-L/2}^{L/2} x"), "∫_(-L/2)^(L/2) x");
  EXPECT_EQ(latex_to_unicode("\\begin{bmatrix} m & 0 \\\\ 0 & I \\end{bmatrix} q"), "[m, 0; 0, I] q");
}

}  // namespace
}  // namespace linkage
