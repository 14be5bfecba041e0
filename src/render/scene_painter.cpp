#include "render/scene_painter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/text.hpp"

namespace linkage {

void paint_arrow(cairo_t* cr, const DrawStyle& style, const Vec2& tail, const Vec2& tip, const Rgba& colour) {
  const Vec2 along = tip - tail;
  const double length = along.norm();
  if (length < 0.5) return;  // under half a pixel: nothing to see
  const Vec2 unit = along / length;
  const Vec2 normal(-unit.y(), unit.x());
  // The head takes at most 60% of a short arrow, keeping its shape.
  const double shrink = std::min(1.0, 0.6 * length / style.arrow_head_length());
  const double head_length = style.arrow_head_length() * shrink;
  const double half_width = style.arrow_head_half_width() * shrink;
  const Vec2 base = tip - head_length * unit;

  set_colour(cr, colour);
  cairo_set_line_width(cr, style.arrow_width() * std::max(shrink, 0.5));
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_move_to(cr, tail.x(), tail.y());
  // The shaft stops inside the head, so its square end never pokes out beside the tip.
  const Vec2 shaft_end = base + 0.3 * head_length * unit;
  cairo_line_to(cr, shaft_end.x(), shaft_end.y());
  cairo_stroke(cr);

  const Vec2 left = base + half_width * normal, right = base - half_width * normal;
  cairo_move_to(cr, tip.x(), tip.y());
  cairo_line_to(cr, left.x(), left.y());
  cairo_line_to(cr, right.x(), right.y());
  cairo_close_path(cr);
  cairo_fill(cr);
}

void paint_stretched_arrow(cairo_t* cr, const DrawStyle& style, const Vec2& tail, const Vec2& tip, const Rgba& colour) {
  const Vec2 along = tip - tail;
  const double length = along.norm();
  if (length < 0.5) return;
  const Vec2 unit = along / length;
  // The head at full size, then the shaft up to it in short dashes.
  const Vec2 normal(-unit.y(), unit.x());
  const Vec2 base = tip - style.arrow_head_length() * unit;
  const Vec2 left = base + style.arrow_head_half_width() * normal,
             right = base - style.arrow_head_half_width() * normal;
  set_colour(cr, colour);
  cairo_move_to(cr, tip.x(), tip.y());
  cairo_line_to(cr, left.x(), left.y());
  cairo_line_to(cr, right.x(), right.y());
  cairo_close_path(cr);
  cairo_fill(cr);
  const Vec2 end = base + 0.3 * style.arrow_head_length() * unit;
  const std::array<double, 2> dashes{2.2 * style.u, 2.2 * style.u};
  cairo_set_line_width(cr, 0.8 * style.arrow_width());
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_set_dash(cr, dashes.data(), 2, 0);
  cairo_move_to(cr, tail.x(), tail.y());
  cairo_line_to(cr, end.x(), end.y());
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
}

void paint_com_symbol(cairo_t* cr, const DrawStyle& style, const Vec2& at, double radius) {
  const Theme& theme = *style.theme;
  constexpr double pi = std::numbers::pi;
  cairo_new_path(cr);
  cairo_arc(cr, at.x(), at.y(), radius, 0, 2 * pi);
  set_colour(cr, theme.background);
  cairo_fill(cr);
  // Quarters up-right and down-left filled: the usual mark for a centre of mass.
  set_colour(cr, theme.com);
  for (const double start : {-0.5 * pi, 0.5 * pi}) {
    cairo_move_to(cr, at.x(), at.y());
    cairo_arc(cr, at.x(), at.y(), radius, start, start + 0.5 * pi);
    cairo_close_path(cr);
    cairo_fill(cr);
  }
  cairo_arc(cr, at.x(), at.y(), radius, 0, 2 * pi);
  cairo_set_line_width(cr, 0.25 * radius);
  cairo_stroke(cr);
}

void paint_pin(cairo_t* cr, const DrawStyle& style, const Vec2& at) {
  const Theme& theme = *style.theme;
  cairo_new_path(cr);
  cairo_arc(cr, at.x(), at.y(), style.pin_radius(), 0, 2 * std::numbers::pi);
  set_colour(cr, theme.pin_fill);
  cairo_fill_preserve(cr);
  set_colour(cr, theme.pin_edge);
  cairo_set_line_width(cr, style.edge_width());
  cairo_stroke(cr);
}

double trail_alpha(const Theme& theme, double fade) {
  const double f = std::clamp(fade, 0.0, 1.0);
  return theme.trail.a * f * f;
}

}  // namespace linkage
