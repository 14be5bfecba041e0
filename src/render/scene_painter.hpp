#pragma once
// Draws a scene's draw list (world units) onto a Cairo context through a camera:
// trail, blocks, arrows, centre-of-mass symbols, the pin, then labels. Sizes of lines
// and marks come from the DrawStyle, not from the world scale, so they stay readable at
// any zoom.
#include <cairo.h>

#include "render/camera.hpp"
#include "render/style.hpp"
#include "scene/draw_list.hpp"

namespace linkage {

/// The colour of an arrow kind in the theme.
[[nodiscard]] const Rgba& arrow_colour(const Theme& theme, ArrowKind kind);

/// The opacity of a trail's segment whose newer end has `fade` (1 now, 0 at the
/// trail's age limit): the theme's, times fade squared, so old parts fade quickly.
[[nodiscard]] double trail_alpha(const Theme& theme, double fade);

/// Draws everything in `list` (antialiased).
void paint_scene(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera);

/// An arrow in pixel coordinates from `tail` to `tip`: a shaft and a filled head. Heads
/// shrink with very short arrows so they never overshoot the tip.
void paint_arrow(cairo_t* cr, const DrawStyle& style, const Vec2& tail, const Vec2& tip, const Rgba& colour);
/// The centre-of-mass symbol (a circle with two opposite quarters filled) at a pixel point.
void paint_com_symbol(cairo_t* cr, const DrawStyle& style, const Vec2& at, double radius);
/// The pin symbol at a pixel point.
void paint_pin(cairo_t* cr, const DrawStyle& style, const Vec2& at);

}  // namespace linkage
