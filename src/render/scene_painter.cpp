#include "render/scene_painter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "render/text.hpp"

namespace linkage {

const Rgba& arrow_colour(const Theme& theme, ArrowKind kind) {
  switch (kind) {
    case ArrowKind::pin_force:
      return theme.pin_force;
    case ArrowKind::gravity:
      return theme.gravity;
    case ArrowKind::velocity:
      return theme.velocity;
  }
  return theme.text;
}

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

namespace {

void paint_trail(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera) {
  // Segment by segment, each as opaque as its newer end is young; butt caps so
  // neighbouring segments do not double up where they meet.
  cairo_set_line_width(cr, style.trail_width());
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  for (std::size_t j = 1; j < list.trail.size(); ++j) {
    const Vec2 a = camera.to_pixels(list.trail[j - 1].at), b = camera.to_pixels(list.trail[j].at);
    set_colour(cr, with_alpha(style.theme->trail, trail_alpha(*style.theme, list.trail[j].fade)));
    cairo_move_to(cr, a.x(), a.y());
    cairo_line_to(cr, b.x(), b.y());
    cairo_stroke(cr);
  }
}

void paint_blocks(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera) {
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_width(cr, style.edge_width());
  for (const BlockShape& block : list.blocks) {
    const std::size_t i = block.index == 1 ? 0 : 1;
    for (std::size_t c = 0; c < block.corners.size(); ++c) {
      const Vec2 p = camera.to_pixels(block.corners[c]);
      if (c == 0)
        cairo_move_to(cr, p.x(), p.y());
      else
        cairo_line_to(cr, p.x(), p.y());
    }
    cairo_close_path(cr);
    set_colour(cr, style.theme->block_fill[i]);
    cairo_fill_preserve(cr);
    set_colour(cr, style.theme->block_edge[i]);
    cairo_stroke(cr);
  }
}

void paint_arrows(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera) {
  for (const Arrow& arrow : list.arrows)
    paint_arrow(cr, style, camera.to_pixels(arrow.tail), camera.to_pixels(arrow.tail + arrow.vector),
                arrow_colour(*style.theme, arrow.kind));
}

void paint_markers(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera) {
  for (const Marker& marker : list.markers) {
    const Vec2 at = camera.to_pixels(marker.at);
    switch (marker.kind) {
      case MarkerKind::com:
        paint_com_symbol(cr, style, at, style.com_radius());
        break;
      case MarkerKind::com_system:
        paint_com_symbol(cr, style, at, style.system_com_radius());
        break;
      case MarkerKind::pin:
        paint_pin(cr, style, at);
        break;
    }
  }
}

// True when the blocks are large enough on screen for names beside them (a fit camera
// over a long fall shows them a few pixels long).
bool room_for_labels(const DrawStyle& style, const DrawList& list, const Camera& camera) {
  if (list.blocks.empty()) return true;
  const BlockShape& block = list.blocks.front();
  const double length = (camera.to_pixels(block.corners[1]) - camera.to_pixels(block.corners[2])).norm();
  return length >= 3 * style.block_label_size();
}

// Boxes already taken by names and marks in this frame, so a later name can move
// aside. Fixed capacity: a frame allocates nothing.
class TakenBoxes {
 public:
  struct Box {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  };
  [[nodiscard]] bool free(const Box& b) const {
    for (std::size_t i = 0; i < count_; ++i) {
      const Box& o = boxes_[i];
      if (b.x0 < o.x1 && o.x0 < b.x1 && b.y0 < o.y1 && o.y0 < b.y1) return false;
    }
    return true;
  }
  void take(const Box& b) {
    if (count_ < boxes_.size()) boxes_[count_++] = b;
  }

 private:
  std::array<Box, 32> boxes_{};
  std::size_t count_ = 0;
};

// The box of `s` centred (by its ink) at `at`, grown by `margin`.
TakenBoxes::Box text_box(cairo_t* cr, const text::Font& font, const Vec2& at, const char* s, double margin) {
  text::use(cr, font);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s, &e);
  return {at.x() - 0.5 * e.width - margin, at.y() - 0.5 * e.height - margin, at.x() + 0.5 * e.width + margin,
          at.y() + 0.5 * e.height + margin};
}

void paint_labels(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera) {
  if (!room_for_labels(style, list, camera)) return;
  const Theme& theme = *style.theme;
  const Rgba halo = with_alpha(theme.background, 0.85);
  const text::Font tag_font{style.text_size(), true};
  const text::Font block_font{style.block_label_size(), true};
  const double tag_halo = 0.3 * style.text_size();
  TakenBoxes taken;
  for (const Marker& marker : list.markers) {
    const Vec2 at = camera.to_pixels(marker.at);
    const double r = marker.kind == MarkerKind::com_system ? style.system_com_radius() : style.com_radius();
    taken.take({at.x() - r, at.y() - r, at.x() + r, at.y() + r});
  }
  for (const Label& label : list.labels) {
    const Vec2 at = camera.to_pixels(label.at);
    const Rgba& colour = label.block == 0 ? theme.text : theme.block_edge[label.block == 1 ? 0 : 1];
    const std::string s(label.text);  // short: no heap (small-string buffer)
    text::draw_centred_with_halo(cr, block_font, at.x(), at.y(), s.c_str(), colour, halo, 0.25 * block_font.size);
    taken.take(text_box(cr, block_font, at, s.c_str(), 0.0));
  }
  // Marker names (P) clear of the system's centre-of-mass symbol, which is often close.
  for (const Marker& marker : list.markers) {
    if (marker.tag.empty()) continue;
    const Vec2 direction(marker.tag_direction.x(), -marker.tag_direction.y());  // y down
    const Vec2 at = camera.to_pixels(marker.at) + (style.system_com_radius() + 0.9 * style.text_size()) * direction;
    const std::string s(marker.tag);
    text::draw_centred_with_halo(cr, tag_font, at.x(), at.y(), s.c_str(), theme.text, halo, tag_halo);
    taken.take(text_box(cr, tag_font, at, s.c_str(), 0.0));
  }
  // Arrow names beside the head, in the arrow's colour: on its left (so F and -F, which
  // point opposite ways from P, get opposite sides), else on its right, else beyond the
  // tip, else left out rather than drawn over another name. Pin forces first.
  for (const ArrowKind kind : {ArrowKind::pin_force, ArrowKind::gravity, ArrowKind::velocity}) {
    for (const Arrow& arrow : list.arrows) {
      if (arrow.kind != kind || arrow.tag.empty()) continue;
      const Vec2 tail = camera.to_pixels(arrow.tail), tip = camera.to_pixels(arrow.tail + arrow.vector);
      const double length = (tip - tail).norm();
      if (length < 2 * style.arrow_head_length()) continue;  // too short to name without clutter
      const Vec2 along = (tip - tail) / length;
      const Vec2 left(along.y(), -along.x());  // pixels have y down
      const Vec2 beside = tip - 0.5 * style.arrow_head_length() * along;
      const double aside = style.arrow_head_half_width() + 0.8 * style.text_size();
      const std::string s(arrow.tag);
      for (const Vec2& at :
           {Vec2(beside + aside * left), Vec2(beside - aside * left), Vec2(tip + 0.9 * style.text_size() * along)}) {
        const TakenBoxes::Box box = text_box(cr, tag_font, at, s.c_str(), 0.15 * style.text_size());
        if (!taken.free(box)) continue;
        text::draw_centred_with_halo(cr, tag_font, at.x(), at.y(), s.c_str(), arrow_colour(theme, kind), halo,
                                     tag_halo);
        taken.take(box);
        break;
      }
    }
  }
}

}  // namespace

void paint_scene(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera) {
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  paint_trail(cr, style, list, camera);
  paint_blocks(cr, style, list, camera);
  // Arrows before the marks, so arrows visibly start at the centre-of-mass symbols and
  // the pin; pin forces last among arrows, as they are the point of the picture.
  paint_arrows(cr, style, list, camera);
  paint_markers(cr, style, list, camera);
  paint_labels(cr, style, list, camera);
}

}  // namespace linkage
