#include "render/mechanism_forces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "render/scene_painter.hpp"
#include "render/text.hpp"
#include "scene/arrow_scale.hpp"

namespace linkage {
namespace {

using List = MechanismDrawList;

constexpr const char* kJointName = "joint forces";
constexpr const char* kAppliedName = "applied forces";
constexpr const char* kGravityName = "gravity";
constexpr const char* kSpringName = "spring forces";
constexpr const char* kVelocityName = "velocity";
constexpr const char* kRelativeVelocityName = "velocity relative to G";
constexpr const char* kAccelerationName = "acceleration";
constexpr const char* kDriverTorqueName = "driver torque";
constexpr const char* kDriverForceName = "driver force";
constexpr const char* kComName = "centres of mass";
constexpr const char* kCutNote = "cut short: its label gives the value";
// On two lines, so the legend stays narrow enough to fit beside a body.
constexpr const char* kStretchedNote = "dashed: too short to see at its scale,";
constexpr const char* kStretchedNote2 = "drawn longer; its label gives the value";

// At the homework clip's sizes (its arrow tags, block names and legend), readable from
// the back of a lecture hall.
text::Font label_font(const DrawStyle& style) { return {style.text_size(), true}; }
text::Font body_font(const DrawStyle& style) { return {style.block_label_size(), true}; }
text::Font legend_font(const DrawStyle& style) { return {style.text_size(), false}; }
constexpr double kLineHeight = 1.1;  // a label's height per font size, a little under any hinted one

// A text's box centred on `at`, with room for its halo.
Rect box_around(cairo_t* cr, const DrawStyle& style, const text::Font& font, const std::string& s, const Vec2& at) {
  const text::Metrics m = text::metrics(cr, font);
  const double pad = 1.5 * style.u;
  const double w = text::width(cr, font, s.c_str()) + 2 * pad, h = m.ascent + m.descent + 2 * pad;
  return {at.x() - 0.5 * w, at.y() - 0.5 * h, w, h};
}

Vec2 centre_of(const Rect& r) { return {r.x + 0.5 * r.width, r.y + 0.5 * r.height}; }

// A world arc as pixel points, from start to start + sweep.
std::vector<Vec2> arc_points(const Camera& camera, const List::Torque& torque, int count) {
  std::vector<Vec2> points;
  for (int i = 0; i <= count; ++i) {
    const double angle = torque.start + torque.sweep * i / count;
    points.push_back(camera.to_pixels(torque.centre + torque.radius * Vec2(std::cos(angle), std::sin(angle))));
  }
  return points;
}

struct Obstacles {
  std::vector<Rect> boxes;
  std::vector<Segment> segments, coils;
};

// The double bar across a cut arrow's shaft, a third of the way from its tail: a gap in
// the background colour between two slanted strokes, as a drawing marks a broken-off length.
void paint_cut(cairo_t* cr, const DrawStyle& style, const Vec2& tail, const Vec2& tip, const Rgba& colour) {
  const Vec2 along = (tip - tail).normalized(), across(-along.y(), along.x());
  const Vec2 mid = tail + 0.4 * (tip - tail);
  const double half = 2.6 * style.arrow_width(), spread = 2.2 * style.u;
  const Vec2 slant = (across + 0.45 * along).normalized();
  set_colour(cr, style.theme->background);
  cairo_new_path(cr);
  const std::array<Vec2, 4> gap{Vec2(mid - spread * along - half * slant), Vec2(mid + spread * along - half * slant),
                                Vec2(mid + spread * along + half * slant), Vec2(mid - spread * along + half * slant)};
  for (const Vec2& p : gap) cairo_line_to(cr, p.x(), p.y());
  cairo_close_path(cr);
  cairo_fill(cr);
  set_colour(cr, colour);
  cairo_set_line_width(cr, 0.7 * style.arrow_width());
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const double side : {-1.0, 1.0}) {
    const Vec2 a = mid + side * spread * along - half * slant, b = mid + side * spread * along + half * slant;
    cairo_move_to(cr, a.x(), a.y());
    cairo_line_to(cr, b.x(), b.y());
  }
  cairo_stroke(cr);
}

// An arc of `radius` pixels about `centre` (pixels) from `start` to start + sweep (world
// angles: counter-clockwise on the screen for sweep > 0), with a head at its end.
void paint_arc_arrow(cairo_t* cr, const DrawStyle& style, const Vec2& centre, double radius, double start, double sweep,
                     const Rgba& colour) {
  if (radius <= 0 || sweep == 0) return;
  const auto at = [&](double angle) { return Vec2(centre + radius * Vec2(std::cos(angle), -std::sin(angle))); };
  // The arc stops where the head begins; the head is a short arrow along the chord,
  // long enough that paint_arrow keeps the head full size.
  const double head = std::min(1.7 * style.arrow_head_length() / radius, 0.5 * std::fabs(sweep));
  const double body = sweep - std::copysign(head, sweep);
  constexpr int kSteps = 48;
  set_colour(cr, colour);
  cairo_set_line_width(cr, style.arrow_width());
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_new_path(cr);
  for (int i = 0; i <= kSteps; ++i) {
    const Vec2 p = at(start + body * i / kSteps);
    cairo_line_to(cr, p.x(), p.y());
  }
  cairo_stroke(cr);
  paint_arrow(cr, style, at(start + body), at(start + sweep), colour);
}

void paint_torque(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List::Torque& torque) {
  paint_arc_arrow(cr, style, camera.to_pixels(torque.centre), torque.radius * camera.scale(), torque.start,
                  torque.sweep, torque.driver ? style.theme->motor : style.theme->velocity);
}

}  // namespace

double motor_radius_px(const DrawStyle& style) { return 3.4 * style.pin_radius(); }

void paint_motors(cairo_t* cr, const DrawStyle& style, const Camera& camera, const MechanismDrawList& list) {
  // A motor as a drawing shows one: a circle in the motor's colour around the driven
  // joint with a curved arrow inside it (a slider's: a straight one along its axis).
  const Rgba& colour = style.theme->motor;
  const double r = motor_radius_px(style);
  for (const List::Motor& motor : list.motors) {
    const Vec2 at = camera.to_pixels(motor.at);
    cairo_new_path(cr);
    cairo_arc(cr, at.x(), at.y(), r, 0, 2 * std::numbers::pi);
    set_colour(cr, with_alpha(colour, 0.18));
    cairo_fill_preserve(cr);
    set_colour(cr, colour);
    cairo_set_line_width(cr, 1.3 * style.edge_width());
    cairo_stroke(cr);
    if (motor.slider) {
      const Vec2 along = Vec2(motor.axis.x(), -motor.axis.y()).normalized();  // y flips in pixels
      paint_arrow(cr, style, at - 0.75 * r * along, at + 0.75 * r * along, colour);
    } else {
      paint_arc_arrow(cr, style, at, 0.62 * r, 0.75 * std::numbers::pi, 1.5 * std::numbers::pi, colour);
    }
  }
}

namespace {

// The legend's rows: per kind a reference arrow at the kind's scale, its value and the
// scale per centimetre; then what a cut and a stretched arrow mean. Measures the
// content's width and height; paints too when `paint`. Given the content's `width`, the
// centres of mass's symbol goes at the right end of the first row with room for it (a
// row of its own would leave a floating pair's legend no place clear of the bodies).
Vec2 legend_rows(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List::Legend& legend, const Vec2& at,
                 bool paint, double width = 0) {
  const Theme& theme = *style.theme;
  const text::Font font = legend_font(style);
  const text::Metrics m = text::metrics(cr, font);
  const double u = style.u, row = 1.7 * font.size;
  double names = 0;
  const auto row_name = [&legend](List::Arrow::Kind kind, double sweep = 0) {
    switch (kind) {
      case List::Arrow::Kind::joint:
        return kJointName;
      case List::Arrow::Kind::applied:
        return kAppliedName;
      case List::Arrow::Kind::gravity:
        return kGravityName;
      case List::Arrow::Kind::spring:
        return kSpringName;
      case List::Arrow::Kind::velocity:
        return legend.relative_velocity ? kRelativeVelocityName : kVelocityName;
      case List::Arrow::Kind::acceleration:
        return kAccelerationName;
      case List::Arrow::Kind::driver:
        return sweep > 0 ? kDriverTorqueName : kDriverForceName;
    }
    return kJointName;
  };
  const bool forces = legend.metres > 0;
  if (forces && legend.joint) names = std::max(names, text::width(cr, font, kJointName));
  if (forces && legend.applied) names = std::max(names, text::width(cr, font, kAppliedName));
  for (const List::Legend::Row& r : legend.rows)
    names = std::max(names, text::width(cr, font, row_name(r.kind, r.sweep)));
  for (const std::string& trail : legend.trails) names = std::max(names, text::width(cr, font, trail.c_str()));
  double y = at.y(), widest = 0;
  const auto baseline = [&] { return y + 0.5 * row + 0.5 * (m.ascent - m.descent); };
  const double com_entry = 2 * style.com_radius() + 6 * u + text::width(cr, font, kComName);
  bool com_placed = !legend.com || !(width > 0);
  const auto com_beside = [&](double used) {
    if (com_placed || used + 16 * u + com_entry > width) return;
    com_placed = true;
    const double x = at.x() + width - com_entry;
    if (!paint) return;
    paint_com_symbol(cr, style, {x + style.com_radius(), y + 0.5 * row}, style.com_radius());
    text::draw(cr, font, x + 2 * style.com_radius() + 6 * u, baseline(), kComName, theme.text);
  };
  // A torque's row (sweep > 0): its reference arc, as wide as the row is high, in place of the arrow.
  const auto scale_row = [&](const char* name, const Rgba& colour, double metres, const std::string& value,
                             const std::string& scale, double sweep = 0) {
    const double arrow = sweep > 0 ? 0.9 * row : metres * camera.scale(), x = at.x() + names + 8 * u;
    const std::string note = value + "   (" + scale + ")";
    if (paint) {
      text::draw(cr, font, at.x(), baseline(), name, theme.text);
      if (sweep > 0)
        paint_arc_arrow(cr, style, {x + 0.5 * arrow, y + 0.5 * row}, 0.4 * row, 0.5 * std::numbers::pi - 0.5 * sweep,
                        sweep, colour);
      else
        paint_arrow(cr, style, {x, y + 0.5 * row}, {x + arrow, y + 0.5 * row}, colour);
      text::draw(cr, font, x + arrow + 6 * u, baseline(), note.c_str(), theme.text);
    }
    const double used = names + 8 * u + arrow + 6 * u + text::width(cr, font, note.c_str());
    widest = std::max(widest, used);
    com_beside(used);
    y += row;
  };
  const auto marked_row = [&](const char* note, const char* more, bool cut) {
    const Vec2 tail(at.x(), y + 0.5 * row), tip(at.x() + 40 * u, y + 0.5 * row);
    if (paint) {
      if (cut) {
        paint_arrow(cr, style, tail, tip, theme.text_muted);
        paint_cut(cr, style, tail, tip, theme.text_muted);
      } else {
        paint_stretched_arrow(cr, style, tail, tip, theme.text_muted);
      }
      text::draw(cr, font, tip.x() + 6 * u, baseline(), note, theme.text_muted);
    }
    widest = std::max(widest, 46 * u + text::width(cr, font, note));
    y += row;
    if (more == nullptr) return;
    y -= 0.35 * row;  // a continued line, closer than a new row
    if (paint) text::draw(cr, font, tip.x() + 6 * u, baseline(), more, theme.text_muted);
    widest = std::max(widest, 46 * u + text::width(cr, font, more));
    y += row;
  };
  if (forces && legend.joint) scale_row(kJointName, theme.pin_force, legend.metres, legend.value, legend.joint_scale);
  if (forces && legend.applied)
    scale_row(kAppliedName, theme.velocity, legend.applied_metres, legend.applied_value, legend.applied_scale);
  for (const List::Legend::Row& r : legend.rows)
    scale_row(row_name(r.kind, r.sweep), arrow_colour(theme, r.kind), r.metres, r.value, r.scale, r.sweep);
  if (legend.cut) marked_row(kCutNote, nullptr, true);
  if (legend.stretched) marked_row(kStretchedNote, kStretchedNote2, false);
  // What is not an arrow: each trail (a line), then a note.
  const double glyph = 40 * u, x = at.x() + names + 8 * u;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "last %.3g s", legend.trail_seconds);
  for (const std::string& trail : legend.trails) {
    if (paint) {
      text::draw(cr, font, at.x(), baseline(), trail.c_str(), theme.text);
      set_colour(cr, theme.trail);
      cairo_set_line_width(cr, style.trail_width());
      cairo_move_to(cr, x, y + 0.5 * row);
      cairo_line_to(cr, x + glyph, y + 0.5 * row);
      cairo_stroke(cr);
      text::draw(cr, font, x + glyph + 6 * u, baseline(), seconds, theme.text_muted);
    }
    const double used = names + 8 * u + glyph + 6 * u + text::width(cr, font, seconds);
    widest = std::max(widest, used);
    com_beside(used);
    y += row;
  }
  if (!legend.note.empty()) {
    if (paint) text::draw(cr, font, at.x(), baseline(), legend.note.c_str(), theme.text_muted);
    widest = std::max(widest, text::width(cr, font, legend.note.c_str()));
    y += row;
  }
  return {widest, y - at.y()};
}

// What the legend must not cover, in pixels: each body's, arrow's, joint's and torque's box.
std::vector<Rect> drawn_boxes(const DrawStyle& style, const Camera& camera, const List& list) {
  std::vector<Rect> boxes;
  const auto around = [&](const std::vector<Vec2>& points, double grow) {
    Bounds b;
    for (const Vec2& p : points) b.include(camera.to_pixels(p));
    boxes.push_back(
        {b.min.x() - grow, b.min.y() - grow, b.max.x() - b.min.x() + 2 * grow, b.max.y() - b.min.y() + 2 * grow});
  };
  for (const List::Outline& outline : list.outlines)
    around(outline.points, outline.shape == Shape::point ? 1.6 * style.com_radius() : style.edge_width());
  for (const List::Arrow& arrow : list.arrows)
    around({arrow.tail, arrow.tail + arrow.vector}, style.arrow_head_length());
  for (const List::Marker& marker : list.markers) around({marker.at}, 10 * style.u);
  for (const List::Motor& motor : list.motors) around({motor.at}, motor_radius_px(style) + 2 * style.u);
  for (const List::Line& line : list.lines)
    if (line.kind != List::Line::Kind::trail && !line.points.empty()) around(line.points, style.edge_width());
  for (const List::Torque& torque : list.torques)
    around({torque.centre - Vec2::Constant(torque.radius), torque.centre + Vec2::Constant(torque.radius)},
           style.arrow_head_length());
  return boxes;
}

// Whether q's shaft runs along p's line (parallel, within `gap` of it, overlapping or
// less than `apart` from it end to end): the two read as one arrow. A joint's pair, equal
// and opposite from one point, is the convention, not a clash.
bool along_one_line(const Segment& p, const Segment& q, double gap, double apart) {
  const Vec2 dp = p.b - p.a, dq = q.b - q.a;
  if (dp.norm() < 1 || dq.norm() < 1 || (p.a - q.a).norm() < 1) return false;
  const Vec2 d = dp.normalized(), n(-d.y(), d.x());
  if (std::fabs(d.x() * dq.normalized().y() - d.y() * dq.normalized().x()) > 0.1) return false;
  if (std::fabs((q.a - p.a).dot(n)) >= gap || std::fabs((q.b - p.a).dot(n)) >= gap) return false;
  const double q0 = (q.a - p.a).dot(d), q1 = (q.b - p.a).dot(d);
  return std::min(dp.norm(), std::max(q0, q1)) - std::max(0.0, std::min(q0, q1)) > -apart;
}

// Whether q leaves p's tail in about p's direction (within 20 degrees): drawn there, one
// would hide the other (a falling body's acceleration over its weight, both from G).
bool from_one_tail(const Segment& p, const Segment& q) {
  const Vec2 dp = p.b - p.a, dq = q.b - q.a;
  if (dp.norm() < 1 || dq.norm() < 1 || (p.a - q.a).norm() >= 1) return false;
  return dp.normalized().dot(dq.normalized()) > std::cos(20 * std::numbers::pi / 180);
}

// The arrows in pixels as drawn: one along another's line (a crank's force along its
// coupler's) moved aside, so each can be told from the other; one from another's tail
// the same way moved aside by a head's width and a shaft's, the two heads side by side.
std::vector<Segment> arrows_apart(const DrawStyle& style, const Camera& camera, const List& list) {
  std::vector<Segment> arrows;
  for (const List::Arrow& arrow : list.arrows)
    arrows.push_back({camera.to_pixels(arrow.tail), camera.to_pixels(arrow.tail + arrow.vector)});
  const double gap = 2 * style.arrow_width();
  for (std::size_t j = 0; j < arrows.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      if (from_one_tail(arrows[i], arrows[j])) {
        // To the side q's head leans to, so the heads are at least that far apart.
        const Vec2 d = (arrows[i].b - arrows[i].a).normalized(), n(-d.y(), d.x());
        const double side = (arrows[j].b - arrows[i].a).dot(n) >= 0 ? 1.0 : -1.0;
        const Vec2 shift = side * (2 * style.arrow_head_half_width() + style.arrow_width()) * n;
        arrows[j].a += shift;
        arrows[j].b += shift;
        continue;
      }
      if (!along_one_line(arrows[i], arrows[j], gap, style.arrow_head_length())) continue;
      const Vec2 d = (arrows[i].b - arrows[i].a).normalized(), n(-d.y(), d.x());
      const double off = (0.5 * (arrows[j].a + arrows[j].b) - arrows[i].a).dot(n);
      const Vec2 shift = ((off >= 0 ? 1.0 : -1.0) * gap - off) * n;
      arrows[j].a += shift;
      arrows[j].b += shift;
    }
  }
  return arrows;
}

// A w x h box where it covers least of `drawn` (and none of `taken`): bottom left when
// clear, else another corner or a place along the frame's edge, below the title and time.
// `covered`: the area of `drawn` it covers there.
Rect clear_place(const DrawStyle& style, double w, double h, int width, int height, const std::vector<Rect>& occupied,
                 const std::vector<Rect>& drawn, const std::vector<Rect>& taken, double& covered) {
  const double pad = 8 * style.u;
  const double left = std::floor(style.padding()), right = std::floor(width - style.padding() - w);
  const double bottom = std::floor(height - style.padding() - h);
  const auto below_occupied = [&](double x) {
    double top = style.padding();
    for (const Rect& r : occupied)
      if (overlap_area({x, 0, w, static_cast<double>(height)}, r) > 0) top = std::max(top, r.y + r.height + pad);
    return std::ceil(top);
  };
  // The corners first, then along the edges: a wide swing can fill every corner in turn.
  std::vector<Rect> places{Rect{left, bottom, w, h}, Rect{right, bottom, w, h}, Rect{left, below_occupied(left), w, h},
                           Rect{right, below_occupied(right), w, h}};
  constexpr int kSteps = 16;
  for (int k = 1; k < kSteps; ++k) {
    const double x = std::floor(left + (right - left) * k / kSteps);
    places.push_back({x, bottom, w, h});
    places.push_back({x, below_occupied(x), w, h});
  }
  for (const double x : {left, right}) {
    const double top = below_occupied(x);
    for (int k = 1; k < kSteps; ++k) places.push_back({x, std::floor(top + (bottom - top) * k / kSteps), w, h});
  }
  Rect best = places.front();
  covered = -1;
  for (const Rect& place : places) {
    const Rect grown{place.x - pad, place.y - pad, place.width + 2 * pad, place.height + 2 * pad};
    if (std::any_of(taken.begin(), taken.end(), [&](const Rect& t) { return overlap_area(grown, t) > 0; })) continue;
    double here = 0;
    for (const Rect& box : drawn) here += overlap_area(place, box);
    if (covered < 0 || here < covered) {
      covered = here;
      best = place;
    }
    if (here == 0) break;
  }
  return best;
}

// The legend, and a scale bar to read its "1 cm" off (the grid's spacing, as the
// homework's), each where it covers nothing drawn if it can; whether both could.
bool place_legend(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List& list, int width, int height,
                  const std::vector<Rect>& occupied, ForceLayout& layout) {
  const List::Legend& legend = list.legend;
  if ((!(legend.metres > 0) || !(legend.joint || legend.applied)) && legend.rows.empty() && legend.trails.empty() &&
      legend.note.empty())
    return true;
  const double pad = 8 * style.u;
  const Vec2 content = legend_rows(cr, style, camera, legend, Vec2::Zero(), false);
  const double w = std::ceil(content.x() + 2 * pad), h = std::ceil(content.y() + 2 * 0.6 * pad);
  const std::vector<Rect> drawn = drawn_boxes(style, camera, list);
  double covered = 0, bar_covered = 0;
  layout.legend = clear_place(style, w, h, width, height, occupied, drawn, {}, covered);
  const RoundLength spacing = grid_spacing_for(camera, width, height);
  layout.scale_label = describe_length(spacing.mantissa, spacing.exponent);
  layout.scale_px = spacing.metres() * camera.scale();
  const Rect bar = scale_bar_rect(cr, style, layout.scale_label, layout.scale_px, width, height);
  layout.scale_bar =
      clear_place(style, bar.width, bar.height, width, height, occupied, drawn, {layout.legend}, bar_covered);
  return covered == 0 && bar_covered == 0;
}

void paint_legend(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List::Legend& legend,
                  const Rect& rect) {
  if (rect.empty()) return;
  const Theme& theme = *style.theme;
  const double pad = 8 * style.u;
  cairo_new_path(cr);
  cairo_rectangle(cr, rect.x + 0.5, rect.y + 0.5, rect.width - 1, rect.height - 1);
  set_colour(cr, theme.panel);
  cairo_fill_preserve(cr);
  set_colour(cr, theme.panel_edge);
  cairo_set_line_width(cr, std::max(1.0, std::round(0.6 * style.u)));
  cairo_stroke(cr);
  legend_rows(cr, style, camera, legend, {rect.x + pad, rect.y + 0.6 * pad}, true, rect.width - 2 * pad);
}

}  // namespace

LegendFit fit_legend(cairo_t* cr, const DrawStyle& style, const Camera& camera, const MechanismDrawList& list,
                     int width, int height, const std::vector<Rect>& occupied) {
  ForceLayout layout;
  if (!list.shown.has(Element::legend)) return {};
  const bool clear = place_legend(cr, style, camera, list, width, height, occupied, layout);
  return {layout.legend, layout.scale_bar, clear};
}

ForceLayout layout_forces(cairo_t* cr, const DrawStyle& style, const Camera& camera, const MechanismDrawList& list,
                          int width, int height, const std::vector<Rect>& occupied) {
  ForceLayout layout;
  if (list.shown.has(Element::legend)) (void)place_legend(cr, style, camera, list, width, height, occupied, layout);
  Obstacles obstacles;
  obstacles.boxes = occupied;
  if (!layout.legend.empty()) obstacles.boxes.push_back(layout.legend);
  if (!layout.scale_bar.empty()) obstacles.boxes.push_back(layout.scale_bar);
  for (const List::Marker& marker : list.markers) {
    const double r = (marker.kind == List::Marker::Kind::guide ? 9.0 : 5.0) * style.u;
    const Vec2 at = camera.to_pixels(marker.at);
    obstacles.boxes.push_back({at.x() - r, at.y() - r, 2 * r, 2 * r});
  }
  const std::size_t markers = obstacles.boxes.size();
  for (const List::Motor& motor : list.motors) {
    const double r = motor_radius_px(style) + 2 * style.u;
    const Vec2 at = camera.to_pixels(motor.at);
    obstacles.boxes.push_back({at.x() - r, at.y() - r, 2 * r, 2 * r});
  }
  layout.arrows = arrows_apart(style, camera, list);
  for (const Segment& arrow : layout.arrows) obstacles.segments.push_back(arrow);
  // Springs and dashpots, zig-zag by zig-zag: a name on a coil hides it and is hard to read.
  for (const List::Line& line : list.lines)
    if (line.kind == List::Line::Kind::spring || line.kind == List::Line::Kind::dashpot)
      for (std::size_t i = 1; i < line.points.size(); ++i)
        obstacles.coils.push_back({camera.to_pixels(line.points[i - 1]), camera.to_pixels(line.points[i])});
  for (std::size_t i = 0; i < list.labels.size(); ++i) {
    const List::Label& label = list.labels[i];
    const auto on_a_joint = [&](const Rect& b) {
      return std::any_of(obstacles.boxes.begin() + static_cast<std::ptrdiff_t>(markers - list.markers.size()),
                         obstacles.boxes.begin() + static_cast<std::ptrdiff_t>(markers),
                         [&](const Rect& m) { return overlaps(b, m); });
    };
    // At the centre, else halfway to a point of the outline, clear of the joints, the
    // arrows and the other bodies' names; else just below the centre, clear of a joint there (a piston's pin).
    const Vec2 centre = camera.to_pixels(label.at);
    std::vector<Vec2> places{centre};
    if (i < list.outlines.size()) {
      const std::vector<Vec2>& outline = list.outlines[i].points;
      const std::size_t stride = std::max<std::size_t>(1, outline.size() / 8);
      for (std::size_t k = 0; k < outline.size(); k += stride)
        places.push_back(centre + 0.5 * (camera.to_pixels(outline[k]) - centre));
    }
    Rect box = box_around(cr, style, body_font(style), label.text, centre);
    bool placed = false;
    for (const Vec2& at : places) {
      const Rect candidate = box_around(cr, style, body_font(style), label.text, at);
      const bool named_there = std::any_of(layout.body_labels.begin(), layout.body_labels.end(),
                                           [&](const Rect& other) { return overlaps(candidate, other); });
      if (!on_a_joint(candidate) && !named_there && !touches(candidate, obstacles.segments) &&
          !touches(candidate, obstacles.coils)) {
        box = candidate;
        placed = true;
        break;
      }
    }
    if (!placed) {
      // Beside the body, as near its centre as the arrows along it allow.
      const Placement beside =
          place_label(box, centre, {0, -1}, {obstacles.boxes, obstacles.segments, nullptr, {}, obstacles.coils}, style,
                      width, height);
      placed = beside.clear;
      if (placed) box = beside.box;
    }
    for (int step = 1; !placed && step <= 4 && on_a_joint(box); ++step) box.y += 0.5 * box.height;
    layout.body_labels.push_back(box);
    obstacles.boxes.push_back(box);
  }
  for (const List::Torque& torque : list.torques) {
    const std::vector<Vec2> points = arc_points(camera, torque, 12);
    for (std::size_t i = 1; i < points.size(); ++i) obstacles.segments.push_back({points[i - 1], points[i]});
  }
  // The bodies, edge by edge (a point mass's outline is one point: its marker is enough).
  for (const List::Outline& outline : list.outlines)
    for (std::size_t i = 0; outline.points.size() > 2 && i < outline.points.size(); ++i)
      obstacles.segments.push_back({camera.to_pixels(outline.points[i]),
                                    camera.to_pixels(outline.points[(i + 1) % outline.points.size()]),
                                    static_cast<int>(outline.body)});

  const text::Font font = label_font(style);
  const auto add = [&](const std::string& text, const Vec2& head, const Vec2& direction, List::Arrow::Kind kind) {
    if (text.empty()) return;  // labels hidden
    const Rect size = box_around(cr, style, font, text, head);
    const Placement at =
        place_label(size, head, direction, {obstacles.boxes, obstacles.segments, nullptr, {}, obstacles.coils}, style,
                    width, height);
    const bool applied = kind == List::Arrow::Kind::applied;
    PlacedLabel placed{at.box, head, text, applied, at.leader, kind};
    obstacles.boxes.push_back(placed.box);
    layout.labels.push_back(std::move(placed));
  };
  const double tall = shortest_labelled_arrow_px(style);
  for (std::size_t i = 0; i < list.arrows.size(); ++i) {
    const List::Arrow& arrow = list.arrows[i];
    const Vec2 tail = layout.arrows[i].a, tip = layout.arrows[i].b;
    // A stub too short to say whose it is goes unlabelled; an applied load never does.
    if (arrow.kind != List::Arrow::Kind::applied && (tip - tail).norm() < tall) continue;
    const Vec2 along = tip - tail;
    add(arrow.label, tip, along.norm() > 0 ? Vec2(along.normalized()) : Vec2(0, -1), arrow.kind);
  }
  // Each joint's name beside its point, below and to the right as a drawing puts it.
  for (const List::Label& joint : list.joint_labels) {
    const std::size_t before = layout.labels.size();
    add(joint.text, camera.to_pixels(joint.at), Vec2(1, 1).normalized(), List::Arrow::Kind::joint);
    if (layout.labels.size() > before) layout.labels.back().joint = true;
  }
  for (const List::Torque& torque : list.torques) {
    // Outside the arc's middle, away from the body.
    const double middle = torque.start + 0.5 * torque.sweep;
    const Vec2 out(std::cos(middle), std::sin(middle));
    const Vec2 head = camera.to_pixels(torque.centre + torque.radius * out);
    add(torque.label, head, Vec2(out.x(), -out.y()),
        torque.driver ? List::Arrow::Kind::driver : List::Arrow::Kind::applied);
  }
  return layout;
}

double shortest_labelled_arrow_px(const DrawStyle& style) {
  // From the nominal size, not the hinted metrics (not proportional at small sizes), so
  // every quality preset labels the same arrows.
  return kLineHeight * label_font(style).size + 3 * style.u;
}

const Rgba& arrow_colour(const Theme& theme, MechanismDrawList::Arrow::Kind kind) {
  switch (kind) {
    case List::Arrow::Kind::joint:
      return theme.pin_force;
    case List::Arrow::Kind::applied:
    case List::Arrow::Kind::velocity:  // as the homework's; applied loads and velocities are not shown together by
                                       // default
      return theme.velocity;
    case List::Arrow::Kind::gravity:
      return theme.gravity;
    case List::Arrow::Kind::spring:
      return theme.trail;
    case List::Arrow::Kind::acceleration:
      return theme.com;
    case List::Arrow::Kind::driver:
      return theme.motor;
  }
  return theme.pin_force;
}

void paint_forces(cairo_t* cr, const DrawStyle& style, const Camera& camera, const MechanismDrawList& list,
                  const ForceLayout& layout) {
  paint_forces([cr](PaintLayer) { return cr; }, style, camera, list, layout);
}

void paint_forces(const LayerContexts& at, const DrawStyle& style, const Camera& camera, const MechanismDrawList& list,
                  const ForceLayout& layout) {
  const Theme& theme = *style.theme;
  for (const List::Torque& torque : list.torques)
    paint_torque(at(torque.driver ? PaintLayer::torque_driver : PaintLayer::torque_applied), style, camera, torque);
  for (std::size_t i = 0; i < list.arrows.size(); ++i) {
    const List::Arrow& arrow = list.arrows[i];
    cairo_t* cr = at(arrow_layer(arrow.kind));
    const Rgba& colour = arrow_colour(theme, arrow.kind);
    const bool laid_out = layout.arrows.size() == list.arrows.size();
    const Vec2 tail = laid_out ? layout.arrows[i].a : camera.to_pixels(arrow.tail);
    const Vec2 tip = laid_out ? layout.arrows[i].b : camera.to_pixels(arrow.tail + arrow.vector);
    if (arrow.stretched)
      paint_stretched_arrow(cr, style, tail, tip, colour);
    else
      paint_arrow(cr, style, tail, tip, colour);
    if (arrow.cut) paint_cut(cr, style, tail, tip, colour);
  }
  // Labels after every arrow, so no shaft crosses a label.
  const text::Font font = label_font(style);
  for (const PlacedLabel& label : layout.labels) {
    cairo_t* cr = at(label.joint ? PaintLayer::joint_names : label_layer(label.kind));
    const Rgba& colour = label.joint ? theme.text : arrow_colour(theme, label.kind);
    const Vec2 centre = centre_of(label.box);
    if (label.leader) {
      // A thin line from the head to the box's nearest point.
      const Vec2 near(std::clamp(label.head.x(), label.box.x, label.box.x + label.box.width),
                      std::clamp(label.head.y(), label.box.y, label.box.y + label.box.height));
      set_colour(cr, with_alpha(colour, 0.7));
      cairo_set_line_width(cr, 0.8 * style.u);
      cairo_move_to(cr, label.head.x(), label.head.y());
      cairo_line_to(cr, near.x(), near.y());
      cairo_stroke(cr);
    }
    text::draw_centred_with_halo(cr, font, centre.x(), centre.y(), label.text.c_str(), colour, theme.background,
                                 2.5 * style.u);
  }
  cairo_t* cr = at(PaintLayer::legend);
  paint_legend(cr, style, camera, list.legend, layout.legend);
  if (!layout.scale_bar.empty()) paint_scale_bar(cr, style, layout.scale_label, layout.scale_px, layout.scale_bar);
}

}  // namespace linkage
