#pragma once
// GiNaC expressions in the project's notation: Unicode or ASCII text, or LaTeX, with every
// symbol spelt as the symbol table says (θ̇₁, th1', \dot{\theta}_1). The printer decides
// the layout itself, so the output does not depend on GiNaC's internal (hash) order:
//
// Products: the numeric coefficient first ("2 g"; -1 as a leading minus), then the factors
//   in increasing SymbolInfo::rank (parameters, definitions, inertias, time, rates,
//   coordinates), then functions by their argument's lowest rank (sin before cos before
//   tan on the same argument), then parenthesized sums, then accelerations and forces:
//   "m g D cos θ₁". Negative powers go to a denominator: "Fx/m" and "1/m" for one symbol,
//   "m (L² + w²) / 12" otherwise; LaTeX "\frac{...}{12}". Powers: ² ³ (Unicode), ^2
//   (ASCII), ^2 or ^{12} (LaTeX); a half power is a square root (√x, sqrt(x), \sqrt{x}).
// Functions: "sin θ₁", "sin(th1)", "\sin\theta_1" for a symbol or a number; parentheses
//   around anything compound: "sin(θ₁ - θ₂)", "\sin\left(\theta_1 - \theta_2\right)";
//   sin² θ₁; tan, exp (LaTeX e^{x}), log (ln), sqrt; the constant π.
// Numbers: integers and rationals exact; floats in shortest round-trip form.
// Sums:
//   1. Factors common to every term are pulled out, "D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)",
//      and with them a numeric factor every term shares ("/ 12") and the sign when every
//      term is negative ("-D (a + b)"). A numeric factor alone is not pulled out.
//   2. Otherwise terms with the same constant factors (parameters, definitions, inertias)
//      are written as one group: "ẋ₁ - D (θ̇₁ sin θ₁ + θ̇₂ sin θ₂)",
//      "m (ẋ₁² + ẏ₁²) / 2 + I (θ̇₁² + θ̇₂²) / 2".
//   3. Terms (and groups, by their first term) in order: terms with a coordinate, rate,
//      acceleration, force or t first, by the ranks of those factors ("θ̇₁² ..." before
//      "θ̇₂² ..."); then terms of constants only, fewer factors first, then by rank
//      ("I + m D²", "L / 2 - b"); numbers last: "D (...) - 2 g".
//   4. A sum does not start with a minus when it has a positive term: the first positive
//      term moves to the front ("x₂ - x₁").
//   5. A sum that is a factor of a product (GiNaC keeps c (a - b) or -c (b - a) as its
//      hash order falls) is written with fewer negative terms, on a tie with its last
//      term positive: "m (x₂ - x₁)", "-m (b - a + c)".
//   Text styles put kBreakMark (report/notation.hpp) before each operator of the top-level
//   sum, where report/text_layout may wrap; LaTeX carries none.
// A symbol missing from the table, or an expression with no notation here (a relation, a
// matrix, a complex number, an unknown function), is a programming error: std::logic_error.
#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

#include "core/style.hpp"
#include "report/notation.hpp"
#include "symbolic/symbols.hpp"

namespace linkage {

/// The number to show for a symbol in a substituted form, e.g. "0.11" for D.
using ValueText = std::function<std::string(const sym::SymbolInfo&)>;

/// `e` in `style`, symbols by their spelling: "D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂) - 2 g".
[[nodiscard]] std::string print(const GiNaC::ex& e, const sym::SymbolTable& table, Style style);

/// `e` with every symbol replaced by `value_text` of it, laid out exactly as print()
/// lays out `e`, multiplication shown as " × " (ASCII " * ", LaTeX " \times "):
/// "0.1 × (0.3² + 0.1²) / 12", "1 + 0.11 × cos 0.1". A negative value is parenthesized.
[[nodiscard]] std::string print_substituted(const GiNaC::ex& e, const sym::SymbolTable& table, Style style,
                                            const ValueText& value_text);

/// One row of A q = B as an equation: each nonzero A_row[c] times unknowns[c] in the
/// order of the unknowns, coefficient 1 and -1 as the bare unknown, a sum coefficient in
/// parentheses, a reciprocal coefficient 1/m written "Fx/m" (LaTeX \frac{F_x}{m}), LaTeX
/// "m \, \ddot{x}_1"; no term gives "0". The right side is print(B). In text styles the
/// left side carries kBreakMark before each term's sign.
[[nodiscard]] EquationSides equation_sides(const std::vector<GiNaC::ex>& A_row, const GiNaC::ex& B,
                                           const std::vector<const sym::SymbolInfo*>& unknowns,
                                           const sym::SymbolTable& table, Style style);

}  // namespace linkage
