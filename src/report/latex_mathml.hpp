#pragma once
// LaTeX math as MathML (MathML Core, which browsers render natively), for the subset the
// reports print: Greek letters and the other symbols of unicode_tex's table, \frac, \sqrt,
// \dot and \ddot, \mathrm and \text, \left ... \right and \big ... \Bigg delimiters, the
// spaces \, \: \; \ \quad \qquad, sub- and superscripts, and the environments aligned (its
// columns right, left, right, ...) and bmatrix, pmatrix, matrix, with & cells and \\ rows
// (\\[1ex] adds space above the next row, class "gap"). The page's stylesheet aligns the
// columns by the classes "aligned" and "matrix" of <mtable>.
#include <string>
#include <string_view>
#include <vector>

namespace linkage {

/// `latex` as one <math> element (display="block" when `display`), well-formed XML with
/// < > & escaped. A command or environment outside the subset, or a stray }, & or \\, is
/// kept visible as <merror><mtext>\name</mtext></merror> and, with `unknown`, appended to it.
/// Throws LatexNestingError (unicode_tex.hpp) for math nested deeper than kMaxNesting.
[[nodiscard]] std::string latex_to_mathml(std::string_view latex, bool display,
                                          std::vector<std::string>* unknown = nullptr);

}  // namespace linkage
