#include "render/mechanism_painter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

#include "render/mechanism_forces.hpp"
#include "render/overlays.hpp"
#include "render/scene_painter.hpp"
#include "render/text.hpp"

namespace linkage {
namespace {

using List = MechanismDrawList;

void path_through(cairo_t* cr, const Camera& camera, const std::vector<Vec2>& points, bool closed) {
  cairo_new_path(cr);
  for (const Vec2& world : points) {
    const Vec2 p = camera.to_pixels(world);
    cairo_line_to(cr, p.x(), p.y());
  }
  if (closed) cairo_close_path(cr);
}

void paint_lines(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List& list, List::Line::Kind kind) {
  const Theme& theme = *style.theme;
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const List::Line& line : list.lines) {
    if (line.kind != kind) continue;
    switch (kind) {
      case List::Line::Kind::trail:
        set_colour(cr, theme.trail);
        cairo_set_line_width(cr, style.trail_width());
        break;
      case List::Line::Kind::rail:
      case List::Line::Kind::surface:
      case List::Line::Kind::slot:
        set_colour(cr, theme.text_muted);
        cairo_set_line_width(cr, 1.5 * style.edge_width());
        break;
      case List::Line::Kind::spring:
      case List::Line::Kind::dashpot:
        set_colour(cr, theme.text);
        cairo_set_line_width(cr, style.edge_width());
        break;
      case List::Line::Kind::spin:
        set_colour(cr, theme.block_edge[0]);
        cairo_set_line_width(cr, style.edge_width());
        break;
      case List::Line::Kind::teeth:
        set_colour(cr, theme.text);
        cairo_set_line_width(cr, style.edge_width());
        break;
    }
    if (kind == List::Line::Kind::trail && line.fade.size() == line.points.size()) {
      // Segment by segment, fading with age; butt caps so segments do not double up.
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
      for (std::size_t j = 1; j < line.points.size(); ++j) {
        const Vec2 a = camera.to_pixels(line.points[j - 1]), b = camera.to_pixels(line.points[j]);
        set_colour(cr, with_alpha(theme.trail, trail_alpha(theme, line.fade[j])));
        cairo_move_to(cr, a.x(), a.y());
        cairo_line_to(cr, b.x(), b.y());
        cairo_stroke(cr);
      }
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
      continue;
    }
    path_through(cr, camera, line.points, kind == List::Line::Kind::slot);
    cairo_stroke(cr);
    if (kind == List::Line::Kind::surface && line.points.size() == 2) {
      // Hatching on the right of the line's direction, under the surface (pixels flip y).
      const Vec2 a = camera.to_pixels(line.points[0]), b = camera.to_pixels(line.points[1]);
      const double length = (b - a).norm(), hatch = 6 * style.u;
      if (!(length > 0)) continue;
      const Vec2 along = (b - a) / length, under(-along.y(), along.x());
      for (double x = 0; x <= length; x += hatch) {
        const Vec2 p = a + x * along;
        cairo_move_to(cr, p.x(), p.y());
        cairo_line_to(cr, p.x() - hatch * along.x() + hatch * under.x(), p.y() - hatch * along.y() + hatch * under.y());
      }
      cairo_set_line_width(cr, 0.7 * style.edge_width());
      cairo_stroke(cr);
    }
  }
}

/// The traced point itself, where its trail ends: on top of its body, so a point off the
/// body's outline (a coupler point) shows what draws the curve.
void paint_trail_heads(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List& list) {
  const Theme& theme = *style.theme;
  for (const List::Line& line : list.lines) {
    if (line.kind != List::Line::Kind::trail || line.points.empty()) continue;
    const Vec2 p = camera.to_pixels(line.points.back());
    cairo_new_sub_path(cr);
    cairo_arc(cr, p.x(), p.y(), 2.5 * style.trail_width(), 0, 2 * M_PI);
    set_colour(cr, theme.trail);
    cairo_fill_preserve(cr);
    set_colour(cr, theme.text);
    cairo_set_line_width(cr, 0.5 * style.edge_width());
    cairo_stroke(cr);
  }
}

// A body's outline as the current path: a point mass as a dot, a ring with its hole, any
// other shape closed.
void outline_path(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List::Outline& outline) {
  if (outline.shape == Shape::point) {
    const Vec2 p = camera.to_pixels(outline.points.front());
    cairo_new_path(cr);
    cairo_arc(cr, p.x(), p.y(), 1.6 * style.com_radius(), 0, 2 * std::numbers::pi);
  } else {
    path_through(cr, camera, outline.points, true);
  }
  if (outline.shape == Shape::ring) {  // a rim a fifth of the radius wide: the hole turns the other way
    Vec2 centre = Vec2::Zero();
    double turn = 0;  // twice the signed area in pixels: > 0 turns as cairo_arc does
    for (std::size_t k = 0; k < outline.points.size(); ++k) {
      const Vec2 a = camera.to_pixels(outline.points[k]);
      const Vec2 b = camera.to_pixels(outline.points[(k + 1) % outline.points.size()]);
      centre += a;
      turn += a.x() * b.y() - b.x() * a.y();
    }
    centre /= static_cast<double>(outline.points.size());
    const double hole = 0.8 * (camera.to_pixels(outline.points.front()) - centre).norm();
    cairo_new_sub_path(cr);
    if (turn > 0)
      cairo_arc_negative(cr, centre.x(), centre.y(), hole, 0, -2 * std::numbers::pi);
    else
      cairo_arc(cr, centre.x(), centre.y(), hole, 0, 2 * std::numbers::pi);
  }
}

void paint_bodies(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List& list) {
  const Theme& theme = *style.theme;
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_width(cr, style.edge_width());
  // Larger bodies first, so a short crank under a long rod stays in sight.
  std::vector<const List::Outline*> order;
  for (const List::Outline& outline : list.outlines) order.push_back(&outline);
  const auto size = [](const List::Outline* o) {
    Bounds b;
    for (const Vec2& p : o->points) b.include(p);
    return (b.max - b.min).squaredNorm();
  };
  std::stable_sort(order.begin(), order.end(), [&](const auto* a, const auto* b) { return size(a) > size(b); });
  // Every fill, then every outline: a body under another (a crank along its coupler)
  // keeps its edge in sight over the fill of the one above it.
  for (const List::Outline* drawn : order) {
    outline_path(cr, style, camera, *drawn);
    set_colour(cr, theme.block_fill[drawn->body % 2]);
    cairo_fill(cr);
    // Its slots cut out of its fill, under the smaller bodies filled after it (the crank
    // whose pin runs in the slot); their edges are painted over every body.
    for (const List::Line& line : list.lines)
      if (line.kind == List::Line::Kind::slot && line.body == static_cast<int>(drawn->body)) {
        path_through(cr, camera, line.points, true);
        set_colour(cr, theme.background);
        cairo_fill(cr);
      }
  }
  for (const List::Outline* drawn : order) {
    outline_path(cr, style, camera, *drawn);
    set_colour(cr, theme.block_edge[drawn->body % 2]);
    cairo_stroke(cr);
  }
}

// The ensemble's colour at `ramp` 0..1, from the trail colour to the velocity's (apart from the bodies').
Rgba ensemble_colour(const Theme& theme, double ramp) {
  const Rgba &a = theme.trail, &b = theme.velocity;
  return {a.r + ramp * (b.r - a.r), a.g + ramp * (b.g - a.g), a.b + ramp * (b.b - a.b), 1.0};
}

Rgba compare_colour(const Theme& theme) { return theme.gravity; }

// Other runs' bodies: the ensemble faint behind the main run, the compared run's outlines
// over it (so identical settings trace exactly the main run's edges).
void paint_ghosts(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List& list, bool compare) {
  const Theme& theme = *style.theme;
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const List::Ghost& ghost : list.ghosts) {
    if (ghost.compare != compare) continue;
    const Rgba colour = compare ? compare_colour(theme) : ensemble_colour(theme, ghost.ramp);
    for (const List::Outline& outline : ghost.outlines) {
      outline_path(cr, style, camera, outline);
      // Only the compared run is filled: 200 faint fills would stack into a tint of the main run.
      if (compare) {
        set_colour(cr, with_alpha(colour, 0.15));
        cairo_fill_preserve(cr);
      }
      set_colour(cr, with_alpha(colour, compare ? 0.9 : 0.35));
      cairo_set_line_width(cr, (compare ? 1.5 : 1.0) * style.edge_width());
      cairo_stroke(cr);
    }
  }
}

// A triangle standing on a hatched base, apex at the point: the usual fixed support.
void paint_ground(cairo_t* cr, const DrawStyle& style, const Vec2& at) {
  const Theme& theme = *style.theme;
  const double half = 7 * style.u, drop = 10 * style.u, hatch = 4 * style.u;
  cairo_new_path(cr);
  cairo_move_to(cr, at.x(), at.y());
  cairo_line_to(cr, at.x() - 0.6 * half, at.y() + drop);
  cairo_line_to(cr, at.x() + 0.6 * half, at.y() + drop);
  cairo_close_path(cr);
  set_colour(cr, theme.panel);
  cairo_fill_preserve(cr);
  set_colour(cr, theme.text_muted);
  cairo_set_line_width(cr, style.edge_width());
  cairo_stroke(cr);
  cairo_move_to(cr, at.x() - half, at.y() + drop);
  cairo_line_to(cr, at.x() + half, at.y() + drop);
  for (double x = -half + hatch; x <= half + 1e-9; x += hatch) {
    cairo_move_to(cr, at.x() + x, at.y() + drop);
    cairo_line_to(cr, at.x() + x - hatch, at.y() + drop + hatch);
  }
  cairo_set_line_width(cr, 0.7 * style.edge_width());
  cairo_stroke(cr);
}

// A small box around the slider's point, along the rail.
void paint_guide(cairo_t* cr, const DrawStyle& style, const Vec2& at, const Vec2& direction_world) {
  const Vec2 along = Vec2(direction_world.x(), -direction_world.y()).normalized();  // y flips in pixels
  const Vec2 across(-along.y(), along.x());
  const double a = 9 * style.u, b = 5 * style.u;
  cairo_new_path(cr);
  for (const auto& [s, t] : {std::pair{-a, -b}, {a, -b}, {a, b}, {-a, b}}) {
    const Vec2 p = at + s * along + t * across;
    cairo_line_to(cr, p.x(), p.y());
  }
  cairo_close_path(cr);
  set_colour(cr, with_alpha(style.theme->pin_fill, 0.6));
  cairo_fill_preserve(cr);
  set_colour(cr, style.theme->pin_edge);
  cairo_set_line_width(cr, style.edge_width());
  cairo_stroke(cr);
}

// A weld's bracket: an L-shaped plate with its corner at the point, a leg along each body
// (world directions), a rivet in each leg.
void paint_bracket(cairo_t* cr, const DrawStyle& style, const Vec2& at, const Vec2& first_world,
                   const Vec2& second_world) {
  const Vec2 first = Vec2(first_world.x(), -first_world.y()).normalized();  // y flips in pixels
  const Vec2 second = Vec2(second_world.x(), -second_world.y()).normalized();
  const double leg = 26 * style.u, plate = 9 * style.u;
  const Vec2 ends[] = {at + leg * first, at, at + leg * second};
  const auto trace = [&] {
    cairo_new_path(cr);
    for (const Vec2& p : ends) cairo_line_to(cr, p.x(), p.y());
  };
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_SQUARE);
  trace();
  set_colour(cr, style.theme->pin_edge);
  cairo_set_line_width(cr, plate + 2 * style.edge_width());
  cairo_stroke(cr);
  trace();
  set_colour(cr, style.theme->panel);
  cairo_set_line_width(cr, plate);
  cairo_stroke(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  set_colour(cr, style.theme->pin_edge);
  for (const Vec2& rivet : {Vec2(at + 0.65 * leg * first), Vec2(at + 0.65 * leg * second)}) {
    cairo_new_path(cr);
    cairo_arc(cr, rivet.x(), rivet.y(), 2 * style.u, 0, 2 * std::numbers::pi);
    cairo_fill(cr);
  }
}

void paint_markers(cairo_t* cr, const DrawStyle& style, const Camera& camera, const List& list,
                   List::Marker::Kind kind) {
  for (const List::Marker& marker : list.markers) {
    if (marker.kind != kind) continue;
    const Vec2 at = camera.to_pixels(marker.at);
    switch (kind) {
      case List::Marker::Kind::ground:
        paint_ground(cr, style, at);
        break;
      case List::Marker::Kind::pin:
        paint_pin(cr, style, at);
        break;
      case List::Marker::Kind::guide:
        paint_guide(cr, style, at, marker.direction);
        break;
      case List::Marker::Kind::com:
        paint_com_symbol(cr, style, at, style.com_radius());
        break;
      case List::Marker::Kind::bracket:
        paint_bracket(cr, style, at, marker.direction, marker.across);
        break;
    }
  }
}

// The body names where the layout put them (at the centres, or beside a joint there).
void paint_body_labels(cairo_t* cr, const DrawStyle& style, const List& list, const ForceLayout& layout) {
  const text::Font font{style.block_label_size(), true};  // as mechanism_forces' layout sized them
  for (std::size_t i = 0; i < list.labels.size() && i < layout.body_labels.size(); ++i) {
    const Rect& box = layout.body_labels[i];
    text::draw_centred_with_halo(cr, font, box.x + 0.5 * box.width, box.y + 0.5 * box.height,
                                 list.labels[i].text.c_str(), style.theme->text, style.theme->background,
                                 2.5 * style.u);
  }
}

void fill_hud(HudText& hud, double time, const MechanismLabels& labels, const List::Hud& errors) {
  format_hud(hud, time, errors.energy_error, errors.constraint_error);
  std::snprintf(hud.run.data(), hud.run.size(), "%s", labels.run.c_str());
  const std::size_t end = std::strlen(hud.energy.data());
  std::snprintf(hud.energy.data() + end, hud.energy.size() - end, " J");
  if (!errors.constraint) hud.constraint[0] = '\0';
  if (!errors.energy) hud.energy[0] = '\0';
}

// The HUD's box, one for every frame (its widest time and errors), and the rows under it
// for the other runs (empty when none).
struct HudBoxes {
  Rect box, all;
};
HudBoxes hud_boxes(cairo_t* cr, const DrawStyle& style, const MechanismLabels& labels, const List::Hud& errors,
                   int width) {
  HudText widest;
  List::Hud largest = errors;
  largest.energy_error = -8.8e-88;
  largest.constraint_error = 8.8e-88;
  fill_hud(widest, -std::max(9.99, labels.duration), labels, largest);
  const Rect box = hud_rect(cr, style, widest, width);
  const text::Font small{style.small_size(), false};
  double wide = box.width, under = box.y + box.height + 0.4 * style.padding(), bottom = box.y + box.height;
  for (const std::string* row : {&labels.ensemble, &labels.compare}) {
    if (row->empty()) continue;
    under += 1.4 * style.small_size();
    wide = std::max(wide, text::width(cr, small, row->c_str()) + 1.4 * 0.8 * style.small_size());
    bottom = under + text::metrics(cr, small).descent;
  }
  const double x = width - style.padding();
  return {box, {x - wide, box.y, wide, bottom - box.y}};
}

// The HUD (top right): the time, the run, the energy balance (not of a prescribed motion) and, when the case keeps a
// constraint, its error; under it a row per other run with a swatch of its colour.
void paint_time(cairo_t* cr, const DrawStyle& style, double t, const MechanismLabels& labels, const List::Hud& errors,
                const Rect& box, int width) {
  HudText hud;
  fill_hud(hud, t, labels, errors);
  paint_hud(cr, style, hud, box);
  const text::Font small{style.small_size(), false};
  const double x = width - style.padding();
  const Theme& theme = *style.theme;
  const Rgba ensemble = ensemble_colour(theme, 0.5), compare = compare_colour(theme);
  double under = box.y + box.height + 0.4 * style.padding();
  const std::pair<const std::string*, const Rgba*> rows[] = {{&labels.ensemble, &ensemble},
                                                             {&labels.compare, &compare}};
  for (const auto& [row, swatch] : rows) {
    if (row->empty()) continue;
    under += 1.4 * style.small_size();
    text::draw_with_halo(cr, small, x, under, row->c_str(), theme.text_muted, theme.background, 3 * style.u,
                         text::Align::right);
    const double side = 0.8 * style.small_size();
    const double row_wide = text::width(cr, small, row->c_str()) + 1.4 * side;
    cairo_rectangle(cr, x - row_wide, under - side, side, side);
    set_colour(cr, *swatch);
    cairo_fill(cr);
  }
}

std::string com_inset_caption(const MechanismLabels& labels) {
  char caption[96];
  std::snprintf(caption, sizeof caption, "path of the centre of mass, 0\u2013%g s", labels.duration);
  return caption;
}

bool shows_com_inset(const MechanismLabels& labels) {
  return labels.follows && labels.com_path.size() >= 2 && labels.duration > 0;
}

// The inset of the centre of mass's whole path in `inset`, the part travelled by `t`
// drawn strong and the centre of mass now marked on it.
void paint_com_inset(cairo_t* cr, const DrawStyle& style, const MechanismLabels& labels, const Vec2& now, double t,
                     Inset inset) {
  const PathInset path = path_inset(std::move(inset), labels.com_path);
  const double steps = static_cast<double>(labels.com_path.size() - 1);
  const auto travelled = static_cast<std::size_t>(std::floor(std::clamp(t / labels.duration, 0.0, 1.0) * steps)) + 1;
  paint_path_inset(cr, style, path, now, travelled);
}

// Where paint_mechanism_frame puts the HUD, the inset and the title (each empty when not drawn).
struct FramePanels {
  HudBoxes hud;
  Inset inset;
  TitleLayout title;
};
FramePanels frame_panels(cairo_t* cr, const DrawStyle& style, const MechanismDrawList& list,
                         const MechanismLabels& labels, int width) {
  FramePanels panels;
  double inset_top = style.padding();
  if (list.shown.has(Element::hud)) {
    panels.hud = hud_boxes(cr, style, labels, list.hud, width);
    inset_top = panels.hud.all.y + panels.hud.all.height + 0.6 * style.padding();
  }
  if (shows_com_inset(labels)) panels.inset = inset_layout(cr, style, com_inset_caption(labels), inset_top, width);
  if (!labels.title.empty() && list.shown.has(Element::title))
    panels.title = title_layout(cr, style, labels.title, width);
  return panels;
}

std::vector<Rect> occupied_by(const FramePanels& panels) {
  std::vector<Rect> occupied;
  for (const Rect& r : {panels.hud.all, panels.inset.rect, panels.title.rect})
    if (!r.empty()) occupied.push_back(r);
  return occupied;
}

}  // namespace

namespace {

// The pixels of `region` on an image surface (flushed), into `out`.
void copy_out(cairo_surface_t* target, const MechanismPaintCache::Region& region, std::vector<std::uint8_t>& out) {
  const unsigned char* data = cairo_image_surface_get_data(target);
  const int stride = cairo_image_surface_get_stride(target);
  const auto row = static_cast<std::size_t>(4 * region.width);
  out.resize(row * static_cast<std::size_t>(region.height));
  for (int y = 0; y < region.height; ++y)
    std::memcpy(out.data() + row * static_cast<std::size_t>(y),
                data + static_cast<std::ptrdiff_t>(region.y + y) * stride + 4 * region.x, row);
}

bool same_as(cairo_surface_t* target, const MechanismPaintCache::Region& region,
             const std::vector<std::uint8_t>& pixels) {
  const unsigned char* data = cairo_image_surface_get_data(target);
  const int stride = cairo_image_surface_get_stride(target);
  const auto row = static_cast<std::size_t>(4 * region.width);
  for (int y = 0; y < region.height; ++y)
    if (std::memcmp(pixels.data() + row * static_cast<std::size_t>(y),
                    data + static_cast<std::ptrdiff_t>(region.y + y) * stride + 4 * region.x, row) != 0)
      return false;
  return true;
}

// Paints the title; or, on an image surface whose pixels under every one the title may touch
// are those it was first drawn over, copies what it drew then: the same pixels, as drawing
// is a function of them. Either way the context is left in the same state.
void paint_title_cached(cairo_t* cr, const DrawStyle& style, const std::string& title, const TitleLayout& layout,
                        MechanismPaintCache* cache) {
  cairo_surface_t* target = cairo_get_target(cr);
  cairo_matrix_t matrix;
  cairo_get_matrix(cr, &matrix);
  const bool identity =
      matrix.xx == 1 && matrix.yy == 1 && matrix.xy == 0 && matrix.yx == 0 && matrix.x0 == 0 && matrix.y0 == 0;
  if (cache == nullptr || !identity || cairo_surface_get_type(target) != CAIRO_SURFACE_TYPE_IMAGE ||
      cairo_image_surface_get_format(target) != CAIRO_FORMAT_ARGB32) {
    paint_title(cr, style, title, layout);
    return;
  }
  MechanismPaintCache::Region& region = cache->title;
  if (region.width < 0) {  // a pixel's margin around the ink, within the surface
    const Rect ink = title_ink(cr, style, title, layout);
    const int right =
        std::min(cairo_image_surface_get_width(target), static_cast<int>(std::ceil(ink.x + ink.width)) + 1);
    const int bottom =
        std::min(cairo_image_surface_get_height(target), static_cast<int>(std::ceil(ink.y + ink.height)) + 1);
    region.x = std::max(0, static_cast<int>(std::floor(ink.x)) - 1);
    region.y = std::max(0, static_cast<int>(std::floor(ink.y)) - 1);
    region.width = std::max(0, right - region.x);
    region.height = std::max(0, bottom - region.y);
  }
  cairo_surface_flush(target);
  if (!region.drawn.empty() && same_as(target, region, region.under)) {
    unsigned char* data = cairo_image_surface_get_data(target);
    const int stride = cairo_image_surface_get_stride(target);
    const auto row = static_cast<std::size_t>(4 * region.width);
    for (int y = 0; y < region.height; ++y)
      std::memcpy(data + static_cast<std::ptrdiff_t>(region.y + y) * stride + 4 * region.x,
                  region.drawn.data() + row * static_cast<std::size_t>(y), row);
    cairo_surface_mark_dirty_rectangle(target, region.x, region.y, region.width, region.height);
    title_pen(cr, style, layout);
    return;
  }
  copy_out(target, region, region.under);
  paint_title(cr, style, title, layout);
  cairo_surface_flush(target);
  copy_out(target, region, region.drawn);
}

// Grid lines fixed in the world: a following camera shows the motion against them, a
// few lines to the frame each named by its height so the fall can be read.
GridSpec frame_grid(const Camera& camera, const ElementSet& shown, const MechanismLabels& labels, int width,
                    int height) {
  GridSpec grid;
  grid.spacing = grid_spacing_for(camera, width, height, labels.follows ? 5 : 10);
  grid.name_every = labels.follows;
  grid.x_ticks = !labels.follows || shown.has(Element::axes);
  return grid;
}

}  // namespace

void paint_mechanism_backdrop(cairo_t* cr, const DrawStyle& style, const Camera& camera, const ElementSet& shown,
                              const MechanismLabels& labels, int width, int height, const Camera* earlier) {
  paint_mechanism_backdrop([cr](PaintLayer) { return cr; }, style, camera, shown, labels, width, height, earlier);
}

void paint_mechanism_backdrop(const LayerContexts& at, const DrawStyle& style, const Camera& camera,
                              const ElementSet& shown, const MechanismLabels& labels, int width, int height,
                              const Camera* earlier) {
  paint_background(at(PaintLayer::backdrop), style, width, height);
  if (shown.has(Element::grid))  // streaking past a following camera
    paint_grid(at(PaintLayer::grid), style, camera, frame_grid(camera, shown, labels, width, height), width, height,
               earlier);
}

ForceLayout paint_mechanism_frame(cairo_t* cr, const DrawStyle& style, const Camera& camera,
                                  const MechanismDrawList& list, const MechanismLabels& labels, double t, int width,
                                  int height, const Camera* earlier, bool backdrop_painted,
                                  MechanismPaintCache* cache) {
  return paint_mechanism_frame([cr](PaintLayer) { return cr; }, style, camera, list, labels, t, width, height, earlier,
                               backdrop_painted, cache);
}

ForceLayout paint_mechanism_frame(const LayerContexts& at, const DrawStyle& style, const Camera& camera,
                                  const MechanismDrawList& list, const MechanismLabels& labels, double t, int width,
                                  int height, const Camera* earlier, bool backdrop_painted,
                                  MechanismPaintCache* cache) {
  const ElementSet& shown = list.shown;
  const GridSpec grid = frame_grid(camera, shown, labels, width, height);
  if (!backdrop_painted) paint_mechanism_backdrop(at, style, camera, shown, labels, width, height, earlier);
  for (std::size_t i = 0; i < kPaintLayers; ++i)
    cairo_set_antialias(at(static_cast<PaintLayer>(i)), CAIRO_ANTIALIAS_DEFAULT);
  cairo_t* scene = at(PaintLayer::scene);
  paint_lines(at(PaintLayer::trail), style, camera, list, List::Line::Kind::trail);
  paint_lines(scene, style, camera, list, List::Line::Kind::rail);
  paint_lines(scene, style, camera, list, List::Line::Kind::surface);
  paint_lines(scene, style, camera, list, List::Line::Kind::spring);
  paint_lines(scene, style, camera, list, List::Line::Kind::dashpot);
  paint_ghosts(scene, style, camera, list, false);
  paint_bodies(scene, style, camera, list);
  paint_ghosts(scene, style, camera, list, true);
  paint_lines(scene, style, camera, list, List::Line::Kind::slot);
  paint_lines(scene, style, camera, list, List::Line::Kind::spin);
  paint_lines(scene, style, camera, list, List::Line::Kind::teeth);
  paint_trail_heads(at(PaintLayer::trail_head), style, camera, list);
  paint_markers(scene, style, camera, list, List::Marker::Kind::ground);
  paint_markers(scene, style, camera, list, List::Marker::Kind::guide);
  paint_motors(at(PaintLayer::motor), style, camera, list);
  cairo_t* markers = at(PaintLayer::markers);
  paint_markers(markers, style, camera, list, List::Marker::Kind::pin);
  paint_markers(markers, style, camera, list, List::Marker::Kind::bracket);
  paint_markers(markers, style, camera, list, List::Marker::Kind::com);
  cairo_t* hud = at(PaintLayer::hud);
  const FramePanels panels = frame_panels(hud, style, list, labels, width);
  if (!panels.hud.box.empty()) paint_time(hud, style, t, labels, list.hud, panels.hud.box, width);
  if (!panels.inset.rect.empty()) paint_com_inset(hud, style, labels, list.centre_of_mass, t, panels.inset);
  if (!panels.title.rect.empty()) paint_title_cached(at(PaintLayer::title), style, labels.title, panels.title, cache);
  const std::vector<Rect> occupied = occupied_by(panels);
  const ForceLayout layout = layout_forces(hud, style, camera, list, width, height, occupied);
  // The grid's names and the axes' ticks clear of every panel.
  if (shown.has(Element::axes) || (labels.follows && shown.has(Element::grid))) {
    std::vector<Rect> avoid = occupied;
    avoid.push_back(layout.legend);
    avoid.push_back(layout.scale_bar);
    paint_axes(at(PaintLayer::axes), style, camera, grid, width, height, avoid);
  }
  paint_body_labels(at(PaintLayer::body_labels), style, list, layout);
  paint_forces(at, style, camera, list, layout);
  return layout;
}

std::vector<Rect> mechanism_frame_panels(cairo_t* cr, const DrawStyle& style, const MechanismDrawList& list,
                                         const MechanismLabels& labels, int width) {
  return occupied_by(frame_panels(cr, style, list, labels, width));
}

}  // namespace linkage
