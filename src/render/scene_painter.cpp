#include "render/scene_painter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "render/text.hpp"

namespace linkage {

Rgba overlay_colour(const Theme& theme, double ramp, bool compare) {
  if (compare) return theme.text;
  const Rgba &a = theme.trail, &b = theme.velocity;
  return {a.r + ramp * (b.r - a.r), a.g + ramp * (b.g - a.g), a.b + ramp * (b.b - a.b), 1.0};
}

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

// Other runs' blocks and pins as outlines: the ensemble's thin and faint behind the main
// run, the compared run's dashed over it (so the same settings trace its edges exactly).
void paint_ghosts(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera, bool compare) {
  cairo_save(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  const std::array<double, 2> dashes{5 * style.u, 3 * style.u};
  for (const GhostBlocks& ghost : list.ghosts) {
    if (ghost.compare != compare) continue;
    const Rgba colour = overlay_colour(*style.theme, ghost.ramp, compare);
    cairo_new_path(cr);
    for (const BlockShape& block : ghost.blocks) {
      for (std::size_t c = 0; c < block.corners.size(); ++c) {
        const Vec2 p = camera.to_pixels(block.corners[c]);
        cairo_line_to(cr, p.x(), p.y());
      }
      cairo_close_path(cr);
      cairo_new_sub_path(cr);
    }
    const Vec2 pin = camera.to_pixels(ghost.pin);
    cairo_arc(cr, pin.x(), pin.y(), 0.8 * style.pin_radius(), 0, 2 * std::numbers::pi);
    set_colour(cr, with_alpha(colour, compare ? 0.9 : 0.4));
    cairo_set_line_width(cr, (compare ? 1.3 : 0.8) * style.edge_width());
    if (compare) cairo_set_dash(cr, dashes.data(), 2, 0);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  cairo_restore(cr);
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
  for (const Arrow& arrow : list.arrows) {
    const Vec2 tail = camera.to_pixels(arrow.tail), tip = camera.to_pixels(arrow.tail + arrow.vector);
    if (arrow.stretched)
      paint_stretched_arrow(cr, style, tail, tip, arrow_colour(*style.theme, arrow.kind));
    else
      paint_arrow(cr, style, tail, tip, arrow_colour(*style.theme, arrow.kind));
  }
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

// "16.3 mN": three significant digits with an SI prefix keeping the number in 1 .. 999.
void format_value(char* out, std::size_t size, double value, const char* unit) {
  static constexpr std::array<const char*, 7> kPrefixes{"n", "\u00b5", "m", "", "k", "M", "G"};
  int group = 3;
  while (group > 0 && value != 0 && std::fabs(value) < 0.9995) {
    value *= 1000;
    --group;
  }
  while (group < 6 && std::fabs(value) >= 999.5) {
    value /= 1000;
    ++group;
  }
  std::snprintf(out, size, "%.3g %s%s", value, kPrefixes[static_cast<std::size_t>(group)], unit);
}

// `s` with its box (by its ink, grown by `margin`) centred at `at`.
Rect text_box(cairo_t* cr, const text::Font& font, const Vec2& at, const char* s, double margin) {
  text::use(cr, font);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s, &e);
  return {at.x() - 0.5 * e.width - margin, at.y() - 0.5 * e.height - margin, e.width + 2 * margin,
          e.height + 2 * margin};
}

Vec2 centre_of(const Rect& r) { return {r.x + 0.5 * r.width, r.y + 0.5 * r.height}; }

}  // namespace

void layout_scene_labels(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera, int width,
                         int height, std::span<const Rect> occupied, SceneLabels& out) {
  out.count = out.segment_count = out.box_count = 0;
  const auto add_segment = [&](const Segment& segment) {
    if (out.segment_count < out.segments.size()) out.segments[out.segment_count++] = segment;
  };
  const auto take = [&](const Rect& box) {
    if (out.box_count < out.boxes.size()) out.boxes[out.box_count++] = box;
  };
  for (const Rect& r : occupied) take(r);
  for (const Arrow& arrow : list.arrows)
    add_segment({camera.to_pixels(arrow.tail), camera.to_pixels(arrow.tail + arrow.vector)});
  const std::size_t arrows = out.segment_count;
  for (const BlockShape& block : list.blocks)
    for (std::size_t c = 0; c < block.corners.size(); ++c)
      add_segment({camera.to_pixels(block.corners[c]), camera.to_pixels(block.corners[(c + 1) % block.corners.size()]),
                   block.index});
  if (!room_for_labels(style, list, camera)) return;
  for (const Marker& marker : list.markers) {
    const Vec2 at = camera.to_pixels(marker.at);
    const double r = marker.kind == MarkerKind::com_system ? style.system_com_radius()
                     : marker.kind == MarkerKind::pin      ? style.pin_radius()
                                                           : style.com_radius();
    take({at.x() - r, at.y() - r, 2 * r, 2 * r});
  }
  const Theme& theme = *style.theme;
  const text::Font tag_font{style.text_size(), true};
  const text::Font block_font{style.block_label_size(), true};
  const auto clear_of = [&](const Rect& box, std::size_t segments) {
    for (std::size_t i = 0; i < out.box_count; ++i)
      if (overlaps(box, out.boxes[i])) return false;
    return !touches(box, std::span<const Segment>(out.segments.data(), segments));
  };
  const auto add = [&](const Rect& box, const Vec2& head, const char* text, const Rgba& colour, bool block,
                       bool leader) {
    if (out.count == out.labels.size()) return;
    SceneLabels::Placed& placed = out.labels[out.count++];
    placed.box = box;
    placed.head = head;
    std::snprintf(placed.text.data(), placed.text.size(), "%s", text);
    placed.colour = colour;
    placed.block = block;
    placed.leader = leader;
    take(box);
  };
  std::array<char, 48> text{};
  // Each block's number on the block, halfway out along its free half or, if an arrow
  // or mark is there, nearer the end or the centre.
  for (const Label& label : list.labels) {
    std::snprintf(text.data(), text.size(), "%.*s", static_cast<int>(label.text.size()), label.text.data());
    const Rgba& colour = label.block == 0 ? theme.text : theme.block_edge[label.block == 1 ? 0 : 1];
    const BlockShape* block = nullptr;
    for (const BlockShape& b : list.blocks)
      if (b.index == label.block) block = &b;
    const Vec2 centre = camera.to_pixels(block ? block->centre : label.at), at = camera.to_pixels(label.at);
    Rect chosen = text_box(cr, block_font, at, text.data(), 0.1 * block_font.size);
    // Along the block's axis on its free half first, then on its pin half, then a little
    // to either side of the axis.
    const Vec2 along = at - centre, across = 0.35 * Vec2(-along.y(), along.x());
    bool found = false;
    for (const double side : {0.0, 1.0, -1.0})
      for (const double f : {1.0, 1.4, 0.6, 1.7, 0.3, -0.6, -1.0, -1.4, -1.7}) {
        const Rect box =
            text_box(cr, block_font, centre + f * along + side * across, text.data(), 0.1 * block_font.size);
        if (!found && clear_of(box, arrows)) {
          chosen = box;
          found = true;
        }
      }
    add(chosen, centre_of(chosen), text.data(), colour, true, false);
  }
  // The arrows named beside their shafts (the free-body view's pin forces): each name
  // must be plainly nearer its own than the others.
  std::array<Segment, 4> sided{};
  std::size_t sided_count = 0;
  for (const Arrow& arrow : list.arrows)
    if (arrow.tag_side.norm() > 0 && sided_count < sided.size())
      sided[sided_count++] = {camera.to_pixels(arrow.tail), camera.to_pixels(arrow.tail + arrow.vector)};
  std::array<Segment, 4> rivals{};
  const auto place = [&](const Vec2& head, const Vec2& direction, const char* s, const Rgba& colour,
                         const Segment* own = nullptr) {
    const Rect size = text_box(cr, tag_font, head, s, 0.2 * style.text_size());
    LabelObstacles obstacles{std::span<const Rect>(out.boxes.data(), out.box_count),
                             std::span<const Segment>(out.segments.data(), out.segment_count)};
    if (own != nullptr) {
      std::size_t n = 0;
      for (std::size_t i = 0; i < sided_count; ++i)
        if (sided[i].a != own->a || sided[i].b != own->b) rivals[n++] = sided[i];
      obstacles.own = own;
      obstacles.rivals = std::span<const Segment>(rivals.data(), n);
    }
    const Placement at = place_label(size, head, direction, obstacles, style, width, height);
    add(at.box, head, s, colour, false, at.leader);
  };
  // Arrow names past the head (or beside the shaft, `tag_side`), in the arrow's colour,
  // with the value when the arrow is valued.
  const auto name_arrow = [&](const Arrow& arrow) {
    const Vec2 tail = camera.to_pixels(arrow.tail), tip = camera.to_pixels(arrow.tail + arrow.vector);
    const double length = (tip - tail).norm();
    // Every arrow drawn is named: one shorter than least_visible_arrow_px is stretched.
    if (length < least_visible_arrow_px(style) && !arrow.stretched) return;
    const int n = std::snprintf(text.data(), text.size(), "%.*s", static_cast<int>(arrow.tag.size()), arrow.tag.data());
    if (arrow.valued && n > 0 && static_cast<std::size_t>(n) + 6 < text.size()) {
      std::snprintf(text.data() + n, text.size() - static_cast<std::size_t>(n), " = ");
      format_value(text.data() + n + 3, text.size() - static_cast<std::size_t>(n) - 3, arrow.magnitude,
                   arrow.kind == ArrowKind::velocity ? "m/s" : "N");
    }
    if (arrow.tag_side.norm() > 0) {
      const Segment own{tail, tip};
      place(0.5 * (tail + tip), Vec2(arrow.tag_side.x(), -arrow.tag_side.y()), text.data(),
            arrow_colour(theme, arrow.kind), &own);
    } else
      place(tip, (tip - tail) / length, text.data(), arrow_colour(theme, arrow.kind));
  };
  // Names beside a shaft first: they must stay at their own arrow (the free-body view's
  // pin forces), where a P could otherwise take the place.
  for (const Arrow& arrow : list.arrows)
    if (!arrow.tag.empty() && arrow.tag_side.norm() > 0) name_arrow(arrow);
  // Marker names (P) off to the side their direction says.
  for (const Marker& marker : list.markers) {
    if (marker.tag.empty()) continue;
    std::snprintf(text.data(), text.size(), "%.*s", static_cast<int>(marker.tag.size()), marker.tag.data());
    place(camera.to_pixels(marker.at), Vec2(marker.tag_direction.x(), -marker.tag_direction.y()), text.data(),
          theme.text);
  }
  // Then the others, pin forces first: they are the point of the picture.
  for (const ArrowKind kind : {ArrowKind::pin_force, ArrowKind::gravity, ArrowKind::velocity})
    for (const Arrow& arrow : list.arrows)
      if (arrow.kind == kind && !arrow.tag.empty() && arrow.tag_side.norm() == 0) name_arrow(arrow);
}

namespace {

void paint_labels(cairo_t* cr, const DrawStyle& style, const SceneLabels& labels) {
  const Rgba halo = with_alpha(style.theme->background, 0.85);
  const text::Font tag_font{style.text_size(), true};
  const text::Font block_font{style.block_label_size(), true};
  for (std::size_t i = 0; i < labels.count; ++i) {
    const SceneLabels::Placed& label = labels.labels[i];
    const Vec2 at = centre_of(label.box);
    if (label.leader) {
      // A thin line towards the head from the box's nearest point, stopping short of
      // the mark there (the pin, an arrow's tip) so it never covers it.
      const Vec2 near(std::clamp(label.head.x(), label.box.x, label.box.x + label.box.width),
                      std::clamp(label.head.y(), label.box.y, label.box.y + label.box.height));
      const Vec2 away = near - label.head;
      const double stop = 1.6 * style.pin_radius();
      if (away.norm() > 2 * stop) {
        const Vec2 start = label.head + stop * away.normalized();
        set_colour(cr, with_alpha(label.colour, 0.7));
        cairo_set_line_width(cr, 0.8 * style.u);
        cairo_move_to(cr, start.x(), start.y());
        cairo_line_to(cr, near.x(), near.y());
        cairo_stroke(cr);
      }
    }
    const text::Font& font = label.block ? block_font : tag_font;
    text::draw_centred_with_halo(cr, font, at.x(), at.y(), label.text.data(), label.colour, halo,
                                 (label.block ? 0.25 : 0.3) * font.size);
  }
}

}  // namespace

void paint_scene(cairo_t* cr, const DrawStyle& style, const DrawList& list, const Camera& camera, int width, int height,
                 std::span<const Rect> occupied, SceneLabels& labels) {
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  paint_trail(cr, style, list, camera);
  paint_ghosts(cr, style, list, camera, false);
  paint_blocks(cr, style, list, camera);
  paint_ghosts(cr, style, list, camera, true);
  // Arrows before the marks, so arrows visibly start at the centre-of-mass symbols and
  // the pin; pin forces last among arrows, as they are the point of the picture.
  paint_arrows(cr, style, list, camera);
  paint_markers(cr, style, list, camera);
  layout_scene_labels(cr, style, list, camera, width, height, occupied, labels);
  paint_labels(cr, style, labels);
}

}  // namespace linkage
