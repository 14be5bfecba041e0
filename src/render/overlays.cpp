#include "render/overlays.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numbers>
#include <utility>

#include "render/cairo_util.hpp"
#include "render/scene_painter.hpp"
#include "render/text.hpp"

namespace linkage {
namespace {

constexpr const char* kMinus = "\u2212";

// A rectangle with whole-pixel corners (so cached copies land exactly on pixels).
Rect snapped(double x, double y, double width, double height) {
  const double left = std::floor(x), top = std::floor(y);
  return {left, top, std::ceil(x + width) - left, std::ceil(y + height) - top};
}

void rounded_rect(cairo_t* cr, const Rect& r, double radius) {
  constexpr double quarter = 0.5 * std::numbers::pi;
  cairo_new_sub_path(cr);
  cairo_arc(cr, r.x + r.width - radius, r.y + radius, radius, -quarter, 0);
  cairo_arc(cr, r.x + r.width - radius, r.y + r.height - radius, radius, 0, quarter);
  cairo_arc(cr, r.x + radius, r.y + r.height - radius, radius, quarter, 2 * quarter);
  cairo_arc(cr, r.x + radius, r.y + radius, radius, 2 * quarter, 3 * quarter);
  cairo_close_path(cr);
}

void paint_panel(cairo_t* cr, const DrawStyle& style, const Rect& r) {
  // A whole number of pixels wide, inside the rectangle, on pixel boundaries.
  const double edge = std::max(1.0, std::round(0.6 * style.u));
  paint_box(cr, style, {r.x + 0.5 * edge, r.y + 0.5 * edge, r.width - edge, r.height - edge}, 5 * style.u, edge);
}

// Replaces each ASCII '-' of a NUL-terminated buffer by U+2212 (three bytes), in place.
template <std::size_t N>
void use_minus_signs(std::array<char, N>& buffer) {
  std::array<char, N> copy = buffer;
  std::size_t out = 0;
  for (std::size_t in = 0; in < N && copy[in] != '\0' && out + 4 < N; ++in) {
    if (copy[in] == '-') {
      std::memcpy(buffer.data() + out, kMinus, 3);
      out += 3;
    } else {
      buffer[out++] = copy[in];
    }
  }
  buffer[out] = '\0';
}

double grid_line_width(const DrawStyle& style) { return std::max(1.0, std::round(style.grid_width())); }

// A pixel coordinate moved to where a line of `width` whole pixels draws crisply.
double crisp(double pixel, double width) {
  const double offset = std::fmod(width, 2.0) == 1.0 ? 0.5 : 0.0;
  return std::round(pixel - offset) + offset;
}

// Calls line(k, pixel) for every grid line across one axis of the frame.
template <typename Line>
void for_each_grid_line(double low, double high, double anchor, double spacing, Line line) {
  const double from = std::ceil((low - anchor) / spacing), to = std::floor((high - anchor) / spacing);
  if (!(std::fabs(from) < 1e15 && std::fabs(to) < 1e15)) return;  // a line count no long holds: none drawn
  const auto first = static_cast<long>(from);
  const auto last = static_cast<long>(to);
  for (long k = first; k <= last && k - first < 1000; ++k) line(k, anchor + static_cast<double>(k) * spacing);
}

constexpr double kLegendGlyphWidth = 30;  // in units of DrawStyle::u
constexpr double kTitleHalo = 0.3;        // halo width over font size

// The widest glyph-and-name of the legend's rows, over rows with a note (where the
// notes column starts) or over all rows.
double legend_names_width(cairo_t* cr, const DrawStyle& style, const std::vector<LegendRow>& rows,
                          bool with_notes_only) {
  const text::Font font{style.text_size(), false};
  double names = 0;
  for (const LegendRow& row : rows) {
    if (with_notes_only && row.note.empty()) continue;
    const double glyph = row.glyph == LegendRow::Glyph::none ? 0 : (kLegendGlyphWidth + 8) * style.u;
    names = std::max(names, glyph + text::width(cr, font, row.name.c_str()));
  }
  return names;
}

}  // namespace

RoundLength grid_spacing_for(const Camera& camera, int width, int height, double lines) {
  return round_length_at_least(std::min(width, height) / camera.scale() / lines);
}

void paint_box(cairo_t* cr, const DrawStyle& style, const Rect& r, double radius, double edge) {
  rounded_rect(cr, r, radius);
  set_colour(cr, style.theme->panel);
  cairo_fill_preserve(cr);
  set_colour(cr, style.theme->panel_edge);
  cairo_set_line_width(cr, edge);
  cairo_stroke(cr);
}

void paint_background(cairo_t* cr, const DrawStyle& style, int width, int height) {
  cairo_save(cr);
  cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
  set_colour(cr, style.theme->background);
  cairo_rectangle(cr, 0, 0, width, height);
  cairo_fill(cr);
  cairo_restore(cr);
}

double grid_streak_opacity(double band, double line, double spacing) {
  band = std::fabs(band);
  if (band < 1.0) return 1.0;
  const double ink = 2 * line / (band + line);  // a ramp from 0 holding the still line's ink
  return std::min(1.0, std::max(ink, kGridStreakOpacity * std::min(1.0, spacing / band)));
}

namespace {

// Every line of one axis streaking the same way (the camera moved `moved` px along it in
// the interval; lines `period` px apart, the first now at `first`): as the lines repeat,
// so does their summed coverage, so it is computed once over one period (a 1-px strip,
// each band a ramp from transparent where the line was to `opacity` where it is, the
// line's width included, overlapping bands composited as OVER would) and painted over
// the whole frame in one pass, however many bands overlap.
void paint_streaks(cairo_t* cr, const Rgba& colour, bool vertical, double first, double period, double moved,
                   double line_width, double opacity, int width, int height) {
  const int samples = std::max(2, static_cast<int>(std::ceil(period)));
  const cairo::SurfacePtr strip = vertical ? cairo::image_surface(samples, 1) : cairo::image_surface(1, samples);
  cairo_surface_flush(strip.get());
  unsigned char* data = cairo_image_surface_get_data(strip.get());
  const int stride = cairo_image_surface_get_stride(strip.get());
  const double length = std::fabs(moved) + line_width, direction = moved > 0 ? -1.0 : 1.0;  // towards then
  const auto reach = static_cast<long>(std::ceil(length / period)) + 1;
  for (int i = 0; i < samples; ++i) {
    const double at = (i + 0.5) * period / samples;  // from a line's place now
    double clear = 1;                                // what the bands leave of the background
    for (long k = -reach; k <= reach; ++k) {
      const double along = (at - static_cast<double>(k) * period) * direction + 0.5 * line_width;
      if (along < 0 || along > length) continue;
      clear *= 1 - colour.a * opacity * (1 - along / length);
    }
    const double alpha = 1 - clear;
    const auto byte = [&](double c) { return static_cast<std::uint32_t>(std::lround(255 * c * alpha)); };
    const std::uint32_t pixel = (static_cast<std::uint32_t>(std::lround(255 * alpha)) << 24) | (byte(colour.r) << 16) |
                                (byte(colour.g) << 8) | byte(colour.b);
    std::memcpy(data + (vertical ? 4 * i : stride * i), &pixel, 4);
  }
  cairo_surface_mark_dirty(strip.get());
  std::unique_ptr<cairo_pattern_t, decltype(&cairo_pattern_destroy)> pattern(
      cairo_pattern_create_for_surface(strip.get()), &cairo_pattern_destroy);
  cairo_pattern_set_extend(pattern.get(), CAIRO_EXTEND_REPEAT);
  cairo_pattern_set_filter(pattern.get(), CAIRO_FILTER_BILINEAR);
  // Pixman's transforms are 16.16 fixed point: the offset taken within one period.
  first -= period * std::floor(first / period);
  cairo_matrix_t matrix;
  if (vertical)
    cairo_matrix_init_scale(&matrix, samples / period, 1);
  else
    cairo_matrix_init_scale(&matrix, 1, samples / period);
  cairo_matrix_translate(&matrix, vertical ? -first : 0, vertical ? 0 : -first);
  cairo_pattern_set_matrix(pattern.get(), &matrix);
  // Where the bands go: the whole frame, or (apart) only the bands' rectangles, each
  // `across` long along the lines.
  const bool apart = length + 2 < period;
  const auto cover = [&](cairo_t* c, int across) {
    if (!apart) {
      cairo_paint(c);
      return;
    }
    const double extent = vertical ? width : height, low = moved > 0 ? -moved : 0.0;
    cairo_new_path(c);
    for (double now = first - period; now < extent + period; now += period) {
      const double from = std::floor(now + low - 0.5 * line_width - 1);
      const double size = std::ceil(length + 2);
      if (vertical)
        cairo_rectangle(c, from, 0, size, across);
      else
        cairo_rectangle(c, 0, from, across, size);
    }
    cairo_fill(c);
  };
  // The bands are the same all along the lines: sampled once into one row or column of
  // the frame, over the same rectangles (pixman steps its filtered fetch from each one's
  // start), so it holds the very values the filtered pattern gives every pixel along it;
  // then repeated across without filtering: the same pixels at a fraction of the cost.
  const cairo::SurfacePtr line = vertical ? cairo::image_surface(width, 1) : cairo::image_surface(1, height);
  {
    const cairo::ContextPtr sampler = cairo::context(line.get());
    cairo_set_operator(sampler.get(), CAIRO_OPERATOR_SOURCE);
    cairo_set_source(sampler.get(), pattern.get());
    cover(sampler.get(), 1);
    cairo::check(sampler.get(), "sampling the grid's streaks");
  }
  cairo_surface_flush(line.get());
  std::unique_ptr<cairo_pattern_t, decltype(&cairo_pattern_destroy)> repeated(
      cairo_pattern_create_for_surface(line.get()), &cairo_pattern_destroy);
  cairo_pattern_set_extend(repeated.get(), CAIRO_EXTEND_REPEAT);
  cairo_pattern_set_filter(repeated.get(), CAIRO_FILTER_NEAREST);
  cairo_save(cr);
  cairo_set_source(cr, repeated.get());
  cover(cr, vertical ? height : width);
  cairo_restore(cr);
}

// The same as vector shapes (an SVG or PDF still stays free of bitmaps): one linear
// gradient per line, from where it was (transparent) to where it is.
void paint_streak_bands(cairo_t* cr, const Rgba& colour, bool vertical, double first, double period, double moved,
                        double line_width, double opacity, int width, int height) {
  const double extent = vertical ? width : height;
  const double direction = moved > 0 ? 1.0 : -1.0;  // from then to now
  const long before = static_cast<long>(std::floor((-std::fabs(moved) - line_width - first) / period));
  const long after = static_cast<long>(std::ceil((extent + std::fabs(moved) + line_width - first) / period));
  for (long k = before; k <= after && k - before < 1000; ++k) {
    const double now = first + static_cast<double>(k) * period, then = now - moved;
    const double from = then - direction * 0.5 * line_width, to = now + direction * 0.5 * line_width;
    std::unique_ptr<cairo_pattern_t, decltype(&cairo_pattern_destroy)> ramp(
        vertical ? cairo_pattern_create_linear(from, 0, to, 0) : cairo_pattern_create_linear(0, from, 0, to),
        &cairo_pattern_destroy);
    cairo_pattern_add_color_stop_rgba(ramp.get(), 0, colour.r, colour.g, colour.b, 0);
    cairo_pattern_add_color_stop_rgba(ramp.get(), 1, colour.r, colour.g, colour.b, colour.a * opacity);
    cairo_new_path(cr);
    if (vertical)
      cairo_rectangle(cr, std::min(from, to), 0, std::fabs(to - from), height);
    else
      cairo_rectangle(cr, 0, std::min(from, to), width, std::fabs(to - from));
    cairo_set_source(cr, ramp.get());
    cairo_fill(cr);
  }
}

}  // namespace

void paint_grid(cairo_t* cr, const DrawStyle& style, const Camera& camera, const GridSpec& grid, int width, int height,
                const Camera* earlier) {
  const View visible = camera.visible();
  const double spacing = grid.spacing.metres();
  const double line_width = grid_line_width(style);
  const Rgba& colour = style.theme->grid;
  std::array<double, 2> moved{};  // pixels every line moved along x (vertical lines) and y in the interval
  if (earlier != nullptr) {
    const Vec2 shift = camera.to_pixels(Vec2::Zero()) - earlier->to_pixels(Vec2::Zero());
    moved = {shift.x(), shift.y()};
  }
  const double period = spacing * camera.scale();
  for (const bool vertical : {true, false}) {
    const double shift = moved[vertical ? 0 : 1];
    const double anchor = vertical ? grid.anchor.x() : grid.anchor.y();
    if (std::fabs(shift) >= 1.0 && period >= 2.0) {
      const double first = vertical ? camera.to_pixels({anchor, 0.0}).x() : camera.to_pixels({0.0, anchor}).y();
      const double opacity = grid_streak_opacity(shift, line_width, period);
      if (cairo_surface_get_type(cairo_get_target(cr)) == CAIRO_SURFACE_TYPE_IMAGE)
        paint_streaks(cr, colour, vertical, first, period, shift, line_width, opacity, width, height);
      else
        paint_streak_bands(cr, colour, vertical, first, period, shift, line_width, opacity, width, height);
      continue;
    }
    set_colour(cr, colour);
    cairo_set_line_width(cr, line_width);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    if (vertical)
      for_each_grid_line(visible.xmin, visible.xmax, anchor, spacing, [&](long, double x) {
        const double px = crisp(camera.to_pixels({x, 0.0}).x(), line_width);
        cairo_move_to(cr, px, 0);
        cairo_line_to(cr, px, height);
      });
    else
      for_each_grid_line(visible.ymin, visible.ymax, anchor, spacing, [&](long, double y) {
        const double py = crisp(camera.to_pixels({0.0, y}).y(), line_width);
        cairo_move_to(cr, 0, py);
        cairo_line_to(cr, width, py);
      });
    cairo_stroke(cr);
  }
}

void paint_axes(cairo_t* cr, const DrawStyle& style, const Camera& camera, const GridSpec& grid, int width, int height,
                const std::vector<Rect>& avoid) {
  const View visible = camera.visible();
  const double spacing = grid.spacing.metres();
  const int decimals = std::max(0, -grid.spacing.exponent);
  const text::Font font{style.small_size(), false};
  const double edge = 0.6 * style.padding();
  const double gap = 4 * style.u;
  const text::Metrics m = text::metrics(cr, font);

  struct Tick {
    double at;     // pixel position along the edge
    double value;  // metres
  };
  // A label's box, and whether it stays clear of the frame's edges and of the panels.
  const auto box = [&](bool bottom, double at, const char* s) {
    const double w = text::width(cr, font, s);
    return bottom ? Rect{at - 0.5 * w, height - edge - m.ascent - m.descent, w, m.ascent + m.descent}
                  : Rect{edge, at - 0.5 * (m.ascent + m.descent), w, m.ascent + m.descent};
  };
  const auto clear = [&](const Rect& r) {
    if (r.x < edge || r.y < edge || r.x + r.width > width - edge || r.y + r.height > height - edge) return false;
    return std::none_of(avoid.begin(), avoid.end(), [&](const Rect& o) {
      return !o.empty() && r.x < o.x + o.width + gap && o.x < r.x + r.width + gap && r.y < o.y + o.height + gap &&
             o.y < r.y + r.height + gap;
    });
  };
  std::array<char, 64> label{};
  const auto format = [&](const char* name, double value) {
    if (std::fabs(value) < 0.5 * spacing) value = 0;  // no "-0.0"
    if (name == nullptr)
      std::snprintf(label.data(), label.size(), "%.*f", decimals, value);
    else
      std::snprintf(label.data(), label.size(), "%s = %.*f m", name, decimals, value);
    use_minus_signs(label);
    return label.data();
  };
  struct Ticks {  // fixed capacity: a following camera draws them every frame
    std::array<Tick, 64> at{};
    std::size_t count = 0;
    void push(const Tick& t) {
      if (count < at.size()) at[count++] = t;
    }
  };
  const auto draw_axis = [&](bool bottom, const Ticks& ticks, const char* name) {
    // The last tick with room for it names the axis and the unit ("x = 1.2 m"); the
    // ticks before it show the number alone.
    // With name_every, every label names its line ("y = −44.2 m").
    const bool every = !bottom && grid.name_every;
    std::size_t named = ticks.count;
    for (std::size_t i = ticks.count; !every && i-- > 0;)
      if (clear(box(bottom, ticks.at[i].at, format(name, ticks.at[i].value)))) {
        named = i;
        break;
      }
    for (std::size_t i = 0; i < ticks.count && (every || i <= named); ++i) {
      const char* s = format(every || i == named ? name : nullptr, ticks.at[i].value);
      const Rect r = box(bottom, ticks.at[i].at, s);
      if (!clear(r)) continue;
      text::draw_with_halo(cr, font, r.x, r.y + m.ascent, s, style.theme->text_muted, style.theme->background,
                           0.35 * font.size);
    }
  };
  Ticks ticks;
  if (grid.x_ticks) {
    for_each_grid_line(visible.xmin, visible.xmax, grid.anchor.x(), spacing, [&](long k, double x) {
      ticks.push({camera.to_pixels({x, 0.0}).x(), grid.relative ? static_cast<double>(k) * spacing : x});
    });
    draw_axis(true, ticks, grid.relative ? "\u0394x" : "x");
  }
  ticks.count = 0;
  // Bottom to top, so the named tick is the highest with room.
  for_each_grid_line(visible.ymin, visible.ymax, grid.anchor.y(), spacing, [&](long k, double y) {
    ticks.push({camera.to_pixels({0.0, y}).y(), grid.relative ? static_cast<double>(k) * spacing : y});
  });
  draw_axis(false, ticks, grid.relative ? "\u0394y" : "y");
}

Inset inset_layout(cairo_t* cr, const DrawStyle& style, std::string caption, double top, int width) {
  const text::Font font{style.small_size(), false};
  const double u = style.u;
  const double plot_width = 150 * u, plot_height = 150 * u;
  const double inner_width = std::max(plot_width, text::width(cr, font, caption.c_str()));
  const double caption_height = 1.5 * font.size;
  Inset inset;
  inset.rect = snapped(width - style.padding() - inner_width - 2 * 8 * u, top, inner_width + 2 * 8 * u,
                       caption_height + plot_height + 2 * 6 * u);
  inset.plot = {inset.rect.x + 8 * u, inset.rect.y + 6 * u + caption_height, inset.rect.width - 2 * 8 * u, plot_height};
  inset.caption = std::move(caption);
  return inset;
}

void paint_inset_frame(cairo_t* cr, const DrawStyle& style, const Inset& inset) {
  paint_panel(cr, style, inset.rect);
  const text::Font font{style.small_size(), false};
  const text::Metrics m = text::metrics(cr, font);
  text::draw(cr, font, inset.rect.x + 8 * style.u, inset.rect.y + 6 * style.u + m.ascent, inset.caption.c_str(),
             style.theme->text_muted);
}

PathInset path_inset(Inset inset, std::vector<Vec2> path) {
  Bounds bounds;
  for (const Vec2& p : path) bounds.include(p);
  PathInset out;
  out.camera = Camera(view_of(bounds, 0.06), static_cast<int>(inset.plot.width), static_cast<int>(inset.plot.height));
  out.inset = std::move(inset);
  out.path = std::move(path);
  return out;
}

void paint_path_inset(cairo_t* cr, const DrawStyle& style, const PathInset& inset, const Vec2& now,
                      std::size_t travelled) {
  paint_inset_frame(cr, style, inset.inset);
  const Theme& theme = *style.theme;
  cairo_save(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  // The part behind G strong, the part ahead dotted: at t = 0 the whole parabola to come,
  // G at its start.
  const auto polyline = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) {
      const Vec2 p = inset.to_pixels(inset.path[i]);
      cairo_line_to(cr, p.x(), p.y());
    }
  };
  const std::size_t behind = std::min(travelled, inset.path.size());
  const Vec2 at = inset.to_pixels(now);
  cairo_new_path(cr);
  cairo_move_to(cr, at.x(), at.y());
  polyline(behind, inset.path.size());
  set_colour(cr, theme.text_muted);
  cairo_set_line_width(cr, std::max(1.2, 1.1 * style.u));
  const std::array<double, 2> dots{0.0, 3.5 * style.u};
  cairo_set_dash(cr, dots.data(), 2, 0);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  if (behind > 0) {
    polyline(0, behind);
    cairo_line_to(cr, at.x(), at.y());
    set_colour(cr, theme.trail);
    cairo_set_line_width(cr, style.trail_width());
    cairo_stroke(cr);
  }
  cairo_new_path(cr);
  cairo_restore(cr);
  // The heights of the path's ends, so the inset says how far the fall goes.
  const text::Font font{style.small_size(), false};
  std::array<char, 48> label{};
  for (const Vec2& end : {inset.path.front(), inset.path.back()}) {
    std::snprintf(label.data(), label.size(), "y = %.0f m", std::fabs(end.y()) < 0.5 ? 0.0 : end.y());
    use_minus_signs(label);
    const Vec2 p = inset.to_pixels(end);
    text::draw_with_halo(cr, font, p.x() + style.system_com_radius() + 5 * style.u, p.y() + 0.35 * font.size,
                         label.data(), theme.text_muted, theme.panel, 0.3 * font.size);
  }
  paint_com_symbol(cr, style, at, style.system_com_radius());
}

TitleLayout title_layout(cairo_t* cr, const DrawStyle& style, const std::string& title, int width) {
  if (title.empty()) return {};
  text::Font font{style.title_size(), true};
  const double room = 0.6 * width;
  const double natural = text::width(cr, font, title.c_str());
  if (natural > room) font.size *= room / natural;
  const text::Metrics m = text::metrics(cr, font);
  const double halo = kTitleHalo * font.size;
  return {snapped(style.padding() - halo, style.padding() - halo, text::width(cr, font, title.c_str()) + 2 * halo,
                  m.ascent + m.descent + 2 * halo),
          font.size};
}

void paint_title(cairo_t* cr, const DrawStyle& style, const std::string& title, const TitleLayout& layout) {
  if (layout.rect.empty()) return;
  const text::Font font{layout.font_size, true};
  const text::Metrics m = text::metrics(cr, font);
  const double halo = kTitleHalo * font.size;
  text::draw_with_halo(cr, font, style.padding(), style.padding() + m.ascent, title.c_str(), style.theme->text,
                       style.theme->background, halo);
}

Rect title_ink(cairo_t* cr, const DrawStyle& style, const std::string& title, const TitleLayout& layout) {
  if (layout.rect.empty()) return {};
  cairo_save(cr);
  const text::Font font{layout.font_size, true};
  const text::Metrics m = text::metrics(cr, font);  // and the font set
  cairo_new_path(cr);
  cairo_move_to(cr, style.padding(), style.padding() + m.ascent);  // as paint_title
  cairo_text_path(cr, title.c_str());
  cairo_set_line_width(cr, kTitleHalo * font.size);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0, fx0 = 0, fy0 = 0, fx1 = 0, fy1 = 0;
  cairo_stroke_extents(cr, &x0, &y0, &x1, &y1);
  cairo_fill_extents(cr, &fx0, &fy0, &fx1, &fy1);
  cairo_new_path(cr);
  cairo_restore(cr);
  x0 = std::min(x0, fx0), y0 = std::min(y0, fy0), x1 = std::max(x1, fx1), y1 = std::max(y1, fy1);
  return {x0, y0, x1 - x0, y1 - y0};
}

void title_pen(cairo_t* cr, const DrawStyle& style, const TitleLayout& layout) {
  const text::Font font{layout.font_size, true};
  text::use(cr, font);
  cairo_new_path(cr);
  cairo_set_line_width(cr, kTitleHalo * font.size);  // as text::draw_with_halo leaves it
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  set_colour(cr, style.theme->text);
}

Rect legend_rect(cairo_t* cr, const DrawStyle& style, const std::vector<LegendRow>& rows, int height) {
  if (rows.empty()) return {};
  const text::Font font{style.text_size(), false};
  const double u = style.u;
  double notes = 0;
  for (const LegendRow& row : rows)
    notes = std::max(notes, row.note.empty() ? 0.0 : text::width(cr, font, row.note.c_str()));
  const double inner_width = std::max(legend_names_width(cr, style, rows, false),
                                      notes > 0 ? legend_names_width(cr, style, rows, true) + 16 * u + notes : 0.0);
  const double row_height = 1.6 * font.size;
  const double box_height = static_cast<double>(rows.size()) * row_height + 2 * 6 * u;
  return snapped(style.padding(), height - style.padding() - box_height, inner_width + 2 * 10 * u, box_height);
}

void paint_legend(cairo_t* cr, const DrawStyle& style, const std::vector<LegendRow>& rows, const Rect& rect) {
  if (rect.empty()) return;
  paint_panel(cr, style, rect);
  const Theme& theme = *style.theme;
  const text::Font font{style.text_size(), false};
  const double u = style.u;
  const double row_height = 1.6 * font.size;
  const text::Metrics m = text::metrics(cr, font);
  const double notes_x = rect.x + 10 * u + legend_names_width(cr, style, rows, true) + 16 * u;

  double y = rect.y + 6 * u;
  for (const LegendRow& row : rows) {
    const double centre = y + 0.5 * row_height;
    const double baseline = centre + 0.5 * (m.ascent - m.descent);
    double x = rect.x + 10 * u;
    const double glyph_width = kLegendGlyphWidth * u;
    switch (row.glyph) {
      case LegendRow::Glyph::arrow:
        paint_arrow(cr, style, {x, centre}, {x + glyph_width, centre}, row.colour);
        break;
      case LegendRow::Glyph::stretched_arrow:
        paint_stretched_arrow(cr, style, {x, centre}, {x + glyph_width, centre}, row.colour);
        break;
      case LegendRow::Glyph::com:
        paint_com_symbol(cr, style, {x + 0.5 * glyph_width, centre}, style.com_radius());
        break;
      case LegendRow::Glyph::line: {
        // Fading like the trail: transparent at its old end.
        std::unique_ptr<cairo_pattern_t, decltype(&cairo_pattern_destroy)> fade(
            cairo_pattern_create_linear(x, centre, x + glyph_width, centre), &cairo_pattern_destroy);
        cairo_pattern_add_color_stop_rgba(fade.get(), 0, row.colour.r, row.colour.g, row.colour.b, 0);
        cairo_pattern_add_color_stop_rgba(fade.get(), 1, row.colour.r, row.colour.g, row.colour.b, row.colour.a);
        cairo_set_source(cr, fade.get());
        cairo_set_line_width(cr, style.trail_width());
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
        cairo_move_to(cr, x, centre);
        cairo_line_to(cr, x + glyph_width, centre);
        cairo_stroke(cr);
        break;
      }
      case LegendRow::Glyph::outline:
      case LegendRow::Glyph::dashed_outline: {
        // A block's outline, as the other runs are drawn.
        const std::array<double, 2> dashes{5 * u, 3 * u};
        cairo_rectangle(cr, x + 2 * u, centre - 4 * u, glyph_width - 4 * u, 8 * u);
        set_colour(cr, with_alpha(row.colour, row.glyph == LegendRow::Glyph::outline ? 0.7 : 0.9));
        cairo_set_line_width(cr, 1.3 * style.edge_width());
        if (row.glyph == LegendRow::Glyph::dashed_outline) cairo_set_dash(cr, dashes.data(), 2, 0);
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        break;
      }
      case LegendRow::Glyph::none:
        break;
    }
    if (row.glyph != LegendRow::Glyph::none) x += glyph_width + 8 * u;
    text::draw(cr, font, x, baseline, row.name.c_str(),
               row.glyph == LegendRow::Glyph::none ? theme.text_muted : theme.text);
    if (!row.note.empty()) text::draw(cr, font, notes_x, baseline, row.note.c_str(), theme.text_muted);
    y += row_height;
  }
}

Rect scale_bar_rect(cairo_t* cr, const DrawStyle& style, const std::string& label, double length_px, int width,
                    int height) {
  const text::Font font{style.text_size(), false};
  const text::Metrics m = text::metrics(cr, font);
  const double u = style.u;
  const double inner_width = std::max(length_px, text::width(cr, font, label.c_str()));
  const double inner_height = m.ascent + m.descent + 4 * u + 6 * u;
  const double box_width = inner_width + 2 * 10 * u, box_height = inner_height + 2 * 6 * u;
  return snapped(width - style.padding() - box_width, height - style.padding() - box_height, box_width, box_height);
}

void paint_scale_bar(cairo_t* cr, const DrawStyle& style, const std::string& label, double length_px,
                     const Rect& rect) {
  paint_panel(cr, style, rect);
  const text::Font font{style.text_size(), false};
  const text::Metrics m = text::metrics(cr, font);
  const double u = style.u;
  const double centre_x = rect.x + 0.5 * rect.width;
  text::draw(cr, font, centre_x, rect.y + 6 * u + m.ascent, label.c_str(), style.theme->text, text::Align::centre);
  // |-----| : the bar with end ticks, exactly length_px long between the tick centres.
  const double y = rect.y + rect.height - 6 * u - 3 * u;
  const double left = centre_x - 0.5 * length_px, right = centre_x + 0.5 * length_px;
  set_colour(cr, style.theme->text);
  cairo_set_line_width(cr, 1.6 * u);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_move_to(cr, left, y);
  cairo_line_to(cr, right, y);
  cairo_move_to(cr, left, y - 3 * u);
  cairo_line_to(cr, left, y + 3 * u);
  cairo_move_to(cr, right, y - 3 * u);
  cairo_line_to(cr, right, y + 3 * u);
  cairo_stroke(cr);
}

void format_hud(HudText& hud, double t, double energy_error, double constraint_error) {
  std::snprintf(hud.time.data(), hud.time.size(), "t = %.2f s", t);
  if (energy_error == 0.0)
    std::snprintf(hud.energy.data(), hud.energy.size(), "0");
  else
    std::snprintf(hud.energy.data(), hud.energy.size(), "%+.1e", energy_error);
  if (constraint_error == 0.0)
    std::snprintf(hud.constraint.data(), hud.constraint.size(), "0 m");
  else
    std::snprintf(hud.constraint.data(), hud.constraint.size(), "%.1e m", constraint_error);
  use_minus_signs(hud.time);
  use_minus_signs(hud.energy);
  use_minus_signs(hud.constraint);
}

namespace {
constexpr const char* kEnergyLabel = "energy error";
constexpr const char* kConstraintLabel = "constraint error";
text::Font hud_time_font(const DrawStyle& style) { return {1.25 * style.text_size(), true}; }
}  // namespace

Rect hud_rect(cairo_t* cr, const DrawStyle& style, const HudText& hud, int width) {
  const text::Font font{style.text_size(), false};
  const double u = style.u;
  const double values =
      std::max(text::width(cr, font, hud.energy.data()), text::width(cr, font, hud.constraint.data()));
  const double labels = std::max(text::width(cr, font, kEnergyLabel), text::width(cr, font, kConstraintLabel));
  const double inner_width = std::max({text::width(cr, hud_time_font(style), hud.time.data()),
                                       text::width(cr, font, hud.run.data()), labels + 14 * u + values});
  // No constraint kept, or a prescribed motion: no constraint row, no energy row.
  const int rows = 1 + (hud.energy[0] == '\0' ? 0 : 1) + (hud.constraint[0] == '\0' ? 0 : 1);
  const double inner_height = 1.5 * hud_time_font(style).size + rows * 1.6 * font.size;
  const double box_width = inner_width + 2 * 10 * u, box_height = inner_height + 2 * 6 * u;
  return snapped(width - style.padding() - box_width, style.padding(), box_width, box_height);
}

void paint_hud(cairo_t* cr, const DrawStyle& style, const HudText& hud, const Rect& rect) {
  paint_panel(cr, style, rect);
  const Theme& theme = *style.theme;
  const text::Font font{style.text_size(), false};
  const text::Font time_font = hud_time_font(style);
  const double u = style.u;
  const double left = rect.x + 10 * u, right = rect.x + rect.width - 10 * u;
  const text::Metrics tm = text::metrics(cr, time_font), m = text::metrics(cr, font);
  double y = rect.y + 6 * u;
  text::draw(cr, time_font, left, y + 0.5 * (1.5 * time_font.size + tm.ascent - tm.descent), hud.time.data(),
             theme.text);
  y += 1.5 * time_font.size;
  const double row = 1.6 * font.size;
  const double offset = 0.5 * (row + m.ascent - m.descent);
  text::draw(cr, font, left, y + offset, hud.run.data(), theme.text_muted);
  y += row;
  if (hud.energy[0] != '\0') {
    text::draw(cr, font, left, y + offset, kEnergyLabel, theme.text_muted);
    text::draw(cr, font, right, y + offset, hud.energy.data(), theme.text, text::Align::right);
    y += row;
  }
  if (hud.constraint[0] == '\0') return;
  text::draw(cr, font, left, y + offset, kConstraintLabel, theme.text_muted);
  text::draw(cr, font, right, y + offset, hud.constraint.data(), theme.text, text::Align::right);
}

}  // namespace linkage
