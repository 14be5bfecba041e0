#pragma once
// The selected case's equations drawn in a band under the motion (--show equations),
// line for line as `linkage solve` prints them: the report's lines in DejaVu Sans Mono,
// one column per code point, so wrapped rows stay aligned as on a terminal. The font
// is the frame's text size (at least a legible minimum), shrunk to fit the width and a
// share of the height but never below that minimum: a frame too small for that is an
// error naming a size that fits.
#include <cairo.h>

#include <string>
#include <vector>

#include "render/overlays.hpp"
#include "render/settings.hpp"
#include "render/style.hpp"

namespace linkage {

inline constexpr double kMinEquationFont = 9;  // px (pt on vector surfaces): smaller is not legible
inline constexpr double kEquationShare = 0.4;  // of the height the caption leaves: the band's largest

/// The lines drawn: the report's, without the indentation they all share.
[[nodiscard]] std::vector<std::string> equation_lines_drawn(const EquationsText& text);

/// The band's size for `text` across `width` with at most `max_height`: the font size and
/// the band's height; fits() is false when the font would be below kMinEquationFont.
struct EquationsFit {
  double font_size = 0;
  double height = 0;
  [[nodiscard]] bool fits() const { return font_size >= kMinEquationFont; }
};
[[nodiscard]] EquationsFit fit_equations(cairo_t* cr, const DrawStyle& style, const EquationsText& text, double width,
                                         double max_height);

/// Paints the band `area`: the background, then a box holding the heading and the
/// lines at `fit`'s size, centred.
void paint_equations(cairo_t* cr, const DrawStyle& style, const EquationsText& text, const EquationsFit& fit,
                     const Rect& area);

}  // namespace linkage
