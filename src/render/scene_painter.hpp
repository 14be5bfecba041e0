#pragma once
// The marks every picture draws in pixels: arrows (plain and stretched), the centre-of-mass
// symbol, the pin, and a trail's fading. Sizes of lines and marks come from the
// DrawStyle, not from the world scale, so they stay readable at any zoom.
#include <cairo.h>

#include "core/types.hpp"
#include "render/style.hpp"

namespace linkage {

/// The opacity of a trail's segment whose newer end has `fade` (1 now, 0 at the
/// trail's age limit): the theme's, times fade squared, so old parts fade quickly.
[[nodiscard]] double trail_alpha(const Theme& theme, double fade);

/// An arrow in pixel coordinates from `tail` to `tip`: a shaft and a filled head. Heads
/// shrink with very short arrows so they never overshoot the tip.
void paint_arrow(cairo_t* cr, const DrawStyle& style, const Vec2& tail, const Vec2& tip, const Rgba& colour);
/// The shortest arrow that still reads as one, px: one head length, where paint_arrow's
/// head is 60% of its full size and the shaft shows behind it. An arrow shorter than this
/// at its scale (a pin force of a few mN beside gravity at one scale) is drawn
/// stretched_arrow_px long instead, dashed, its label giving its value.
[[nodiscard]] inline double least_visible_arrow_px(const DrawStyle& style) { return style.arrow_head_length(); }
/// How long a stretched arrow is drawn, px: a full head and room for the dashes.
[[nodiscard]] inline double stretched_arrow_px(const DrawStyle& style) { return 3 * style.arrow_head_length(); }
/// An arrow drawn longer than its scale says: a dashed shaft and a full head.
void paint_stretched_arrow(cairo_t* cr, const DrawStyle& style, const Vec2& tail, const Vec2& tip, const Rgba& colour);
/// The centre-of-mass symbol (a circle with two opposite quarters filled) at a pixel point.
void paint_com_symbol(cairo_t* cr, const DrawStyle& style, const Vec2& at, double radius);
/// The pin symbol at a pixel point.
void paint_pin(cairo_t* cr, const DrawStyle& style, const Vec2& at);

}  // namespace linkage
