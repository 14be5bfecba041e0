#pragma once
// Draws a scene's draw list (world units) onto a Cairo context through a camera:
// trail, blocks, arrows, centre-of-mass symbols, the pin, then labels. Sizes of lines
// and marks come from the DrawStyle, not from the world scale, so they stay readable at
// any zoom.
#include <cairo.h>

#include <array>
#include <span>

#include "render/camera.hpp"
#include "render/label_layout.hpp"
#include "render/style.hpp"
#include "scene/draw_list.hpp"

namespace linkage {

/// The colour of another run drawn over the main one: an ensemble member at `ramp` 0..1
/// (from the trail's colour to the velocity's, apart from the blocks'), or the compared
/// run (the text colour, dashed).
[[nodiscard]] Rgba overlay_colour(const Theme& theme, double ramp, bool compare);

/// The colour of an arrow kind in the theme.
[[nodiscard]] const Rgba& arrow_colour(const Theme& theme, ArrowKind kind);

/// The opacity of a trail's segment whose newer end has `fade` (1 now, 0 at the
/// trail's age limit): the theme's, times fade squared, so old parts fade quickly.
[[nodiscard]] double trail_alpha(const Theme& theme, double fade);

/// Where a frame's names go, in pixels: each block's number on its block, the pin's
/// name and each arrow's name (with its value when stretched) clear of one another, of
/// the marks, the `occupied` panels, the arrows and the blocks where the frame has room.
/// Fixed capacity, so a frame allocates nothing; kept for tests to check.
struct SceneLabels {
  struct Placed {
    Rect box;
    Vec2 head = Vec2::Zero();  // what it names
    std::array<char, 48> text{};
    Rgba colour;
    bool block = false;   // a block's number (drawn on the block)
    bool leader = false;  // a line to the head
  };
  std::array<Placed, 16> labels{};
  std::size_t count = 0;
  std::array<Segment, 40> segments{};  // the arrows as drawn, then the blocks' edges (body = index)
  std::size_t segment_count = 0;
  std::array<Rect, 40> boxes{};  // occupied panels, marks, then the names
  std::size_t box_count = 0;
};
void layout_scene_labels(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera, int width,
                         int height, std::span<const Rect> occupied, SceneLabels& out);

/// Draws everything in `list` (antialiased) in a width x height frame, names clear of
/// the `occupied` panels; `labels` receives the names' layout.
void paint_scene(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera, int width, int height,
                 std::span<const Rect> occupied, SceneLabels& labels);

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
