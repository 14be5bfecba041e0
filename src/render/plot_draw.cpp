// draw(): lays a plot out from the sizes of its text, then paints background, grid,
// series, frame, ticks, labels and legend, in that order (data over the grid, text and
// legend over the data).
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numbers>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "render/plot.hpp"
#include "render/plot_data.hpp"
#include "render/plot_text.hpp"
#include "render/plot_ticks.hpp"

namespace linkage::plot {
namespace {

using detail::Box;

struct Colors {
  Rgb background, text, frame, grid;
};

const Colors& theme_colors(Theme theme) {
  static const Colors light{{1, 1, 1}, {0.1, 0.1, 0.1}, {0.3, 0.3, 0.3}, {0.9, 0.9, 0.9}};
  static const Colors dark{{0.125, 0.13, 0.14}, {0.91, 0.91, 0.91}, {0.63, 0.63, 0.63}, {0.24, 0.25, 0.26}};
  return theme == Theme::dark ? dark : light;
}

void set_color(cairo_t* cr, const Rgb& c, double alpha = 1.0) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

/// Every length of the drawing, proportional to the font size (14 at 900 x 600).
struct Metrics {
  explicit Metrics(double font_size)
      : unit(font_size / 14.0),
        tick_font{font_size},
        label_font{1.1 * font_size},
        title_font{1.3 * font_size, true},
        pad(0.9 * font_size),
        tick(0.4 * font_size),
        minor_tick(0.22 * font_size),
        gap(0.35 * font_size),
        line_width(2.0 * unit),
        marker_radius(3.6 * unit) {}
  double unit;
  Font tick_font, label_font, title_font;
  double pad, tick, minor_tick, gap, line_width, marker_radius;
};

/// Centre of a one-unit line on a device pixel, so grid and frame lines are crisp.
double crisp(double v) { return std::floor(v) + 0.5; }

std::size_t color_slot(const Series& series, std::size_t index) { return series.color.value_or(index % palette_size); }

Marker marker_shape(const Series& series, std::size_t index) {
  if (series.marker != Marker::automatic) return series.marker;
  constexpr Marker cycle[] = {Marker::circle,  Marker::square, Marker::triangle,
                              Marker::diamond, Marker::cross,  Marker::plus};
  return cycle[color_slot(series, index) % std::size(cycle)];
}

bool has_line(const Series& s) { return s.style != Style::markers; }
bool has_markers(const Series& s) { return s.style != Style::line; }

// A legend at most this share of the canvas' width may go beside the data.
constexpr double kNarrowLegend = 0.2;
// A legend outside the data must leave it this share of the canvas' height.
constexpr double kLeastDataHeight = 1.0 / 3;

class Drawing {
 public:
  Drawing(cairo_t* cr, const Plot& plot, const Canvas& canvas, const std::string& origin)
      : cr_(cr),
        plot_(plot),
        canvas_(canvas),
        origin_(origin),
        m_(canvas.font_size),
        colors_(theme_colors(plot.theme)),
        data_(detail::clean(plot)),
        data_limits_(detail::resolve_limits(plot, data_)),
        limits_(data_limits_) {}

  Report run() {
    set_plot_font_options(cr_);
    measure_legend();
    legend_place_ = plot_.legend;
    if (legend_entries_.empty()) legend_place_ = LegendPlace::none;
    lay_out();
    if (legend_place_ == LegendPlace::best && !legend_fits_inside() &&
        !place_outside({LegendPlace::outside_right, LegendPlace::above})) {
      legend_place_ = LegendPlace::best;  // no room outside: over the data after all
      lay_out();
    }
    require_room_for_data();
    trace_data();
    if (legend_place_ == LegendPlace::best) {
      const LegendPlace corner = least_occupied_corner();
      legend_place_ = corner;
      if (samples_in(legend_box(corner)) > 0) {  // every corner would hide data: beside it if narrow, else above
        const bool narrow = legend_width_ <= kNarrowLegend * canvas_.width;
        if (!place_outside(narrow ? std::initializer_list<LegendPlace>{LegendPlace::outside_right, LegendPlace::above}
                                  : std::initializer_list<LegendPlace>{LegendPlace::above})) {
          legend_place_ = corner;
          lay_out();
        }
        trace_data();
      }
    }

    paint_background();
    paint_grid();
    paint_series();
    paint_frame_and_ticks();
    paint_labels();
    paint_legend();
    return {g_, data_.dropped_nonpositive, data_.skipped_nonfinite, legend_place_};
  }

 private:
  // --- layout ----------------------------------------------------------------------

  /// The first of `places` outside the data that leaves the data half the width and a
  /// third of the height at least, laid out; false (and the layout of the last) if none.
  bool place_outside(std::initializer_list<LegendPlace> places) {
    for (const LegendPlace place : places) {
      legend_place_ = place;
      lay_out();
      if (g_.right - g_.left >= 0.5 * canvas_.width && g_.bottom - g_.top >= kLeastDataHeight * canvas_.height)
        return true;
    }
    return false;
  }

  [[nodiscard]] Ticks ticks_for(const Axis& axis, const detail::Limits& limits, int max_ticks) const {
    if (axis.scale == Scale::log) return log_ticks(limits.min, limits.max, max_ticks);
    return axis.degrees ? degree_ticks(limits.min, limits.max, max_ticks)
                        : linear_ticks(limits.min, limits.max, max_ticks);
  }

  /// Ticks for an axis of `length` device units, as many as fit without labels touching.
  template <typename Overlap>
  [[nodiscard]] Ticks fitting_ticks(const Axis& axis, const detail::Limits& limits, double length, double spacing,
                                    Overlap overlap) const {
    int max_ticks = std::clamp(static_cast<int>(length / spacing), 2, 12);
    Ticks ticks = ticks_for(axis, limits, max_ticks);
    while (max_ticks > 2 && overlap(ticks)) ticks = ticks_for(axis, limits, --max_ticks);
    return ticks;
  }

  /// Lays out the plot; at one scale (`equal_scale`), widens the axis whose data is
  /// shorter on the page so a data unit is as long on x as on y, and lays out again with
  /// those limits (tick labels may move the area a little: twice settles it).
  void lay_out() {
    if (!plot_.equal_scale) {
      lay_out_once();
      return;
    }
    limits_ = data_limits_;
    for (int pass = 0; pass < 3; ++pass) {
      lay_out_once();
      const double width = g_.right - g_.left, height = g_.bottom - g_.top;
      if (!(width > 0 && height > 0)) return;
      const detail::Limits& x = data_limits_.x;
      const detail::Limits& y = data_limits_.y;
      const double per_unit = std::max((x.max - x.min) / width, (y.max - y.min) / height);
      const double cx = 0.5 * (x.min + x.max), cy = 0.5 * (y.min + y.max);
      limits_.x = {cx - 0.5 * per_unit * width, cx + 0.5 * per_unit * width};
      limits_.y = {cy - 0.5 * per_unit * height, cy + 0.5 * per_unit * height};
    }
    lay_out_once();
  }

  void lay_out_once() {
    const double f = canvas_.font_size;
    const TextExtent tick_label = measure_text(cr_, "10^{8}", m_.tick_font);
    tick_label_ascent_ = tick_label.ascent;
    double top = m_.pad;
    if (!plot_.title.empty()) top += measure_text(cr_, plot_.title, m_.title_font).height() + 0.7 * f;
    double bottom = canvas_.height - m_.pad - m_.tick - m_.gap - tick_label.height();
    if (!plot_.x.label.empty()) bottom -= measure_text(cr_, plot_.x.label, m_.label_font).height() + 0.45 * f;
    double left = m_.pad;
    if (!plot_.y.label.empty()) left += measure_text(cr_, plot_.y.label, m_.label_font).height() + 0.45 * f;
    double right = canvas_.width - m_.pad;
    if (legend_place_ == LegendPlace::outside_right) right -= legend_width_ + 0.8 * f;
    legend_band_top_ = top;
    if (legend_place_ == LegendPlace::above) top += legend_height_ + 0.6 * f;
    top = std::round(top);
    bottom = std::round(bottom);

    const double cap = cap_height(cr_, m_.tick_font);
    const AxisMap y_map{plot_.y.scale, limits_.y.min, limits_.y.max, bottom, top};
    y_ticks_ = fitting_ticks(plot_.y, limits_.y, bottom - top, 3.2 * f, [&](const Ticks& t) {
      for (std::size_t k = 1; k < t.major.size(); ++k)
        if (y_map(t.major[k - 1].value) - y_map(t.major[k].value) < cap + 0.6 * f) return true;
      return false;
    });
    double widest = 0;
    for (const Tick& t : y_ticks_.major) widest = std::max(widest, measure_text(cr_, t.label, m_.tick_font).width);
    left = std::round(left + widest + m_.gap + m_.tick);

    // The last x label may hang past the data area: reserve half its width on the right.
    for (int pass = 0; pass < 2; ++pass) {
      const double area_right = std::round(std::min(right, canvas_.width - m_.pad - last_x_overhang_));
      g_.x = {plot_.x.scale, limits_.x.min, limits_.x.max, left, area_right};
      x_ticks_ = fitting_ticks(plot_.x, limits_.x, area_right - left, 6.0 * f,
                               [&](const Ticks& t) { return x_labels_overlap(t); });
      last_x_overhang_ = 0;
      if (!x_ticks_.major.empty()) {
        const Tick& last = x_ticks_.major.back();
        last_x_overhang_ = measure_text(cr_, last.label, m_.tick_font).width / 2 - (area_right - g_.x(last.value));
      }
    }
    g_.left = left;
    g_.right = g_.x.to;
    g_.top = top;
    g_.bottom = bottom;
    g_.y = {plot_.y.scale, limits_.y.min, limits_.y.max, bottom, top};
  }

  void require_room_for_data() const {
    const double f = canvas_.font_size;
    if (g_.right - g_.left < 3 * f || g_.bottom - g_.top < 3 * f)
      throw Error::input(
          origin_ + ": a " + format_significant(canvas_.width, 6) + " x " + format_significant(canvas_.height, 6) +
          " canvas is too small for this plot's labels at font size " + format_significant(canvas_.font_size, 6));
  }

  /// `font`, shrunk (to 60 % at most) so that `text` fits in `room`.
  [[nodiscard]] Font fitted(const Font& font, const std::string& text, double room) const {
    const double width = measure_text(cr_, text, font).width;
    if (width <= room) return font;
    return {font.size * std::max(0.6, room / width), font.bold};
  }

  [[nodiscard]] bool x_labels_overlap(const Ticks& ticks) const {
    double previous_end = -1e300;
    for (const Tick& t : ticks.major) {
      const double half = measure_text(cr_, t.label, m_.tick_font).width / 2;
      const double center = g_.x(t.value);
      if (center - half < previous_end + 0.8 * canvas_.font_size) return true;
      previous_end = center + half;
    }
    return false;
  }

  // --- legend ----------------------------------------------------------------------

  void measure_legend() {
    legend_entries_.clear();
    double widest = 0;
    for (std::size_t i = 0; i < plot_.series.size(); ++i) {
      if (plot_.series[i].name.empty()) continue;
      legend_entries_.push_back(i);
      widest = std::max(widest, measure_text(cr_, plot_.series[i].name, m_.tick_font).width);
    }
    legend_row_ = 1.5 * canvas_.font_size;
    legend_sample_ = 2.6 * canvas_.font_size;
    legend_width_ = 2 * legend_inset() + legend_sample_ + 0.6 * canvas_.font_size + widest;
    legend_height_ = 2 * legend_inset() + legend_row_ * static_cast<double>(legend_entries_.size());
  }

  [[nodiscard]] double legend_inset() const { return 0.55 * canvas_.font_size; }

  [[nodiscard]] bool legend_fits_inside() const {
    return legend_width_ <= 0.5 * (g_.right - g_.left) && legend_height_ <= 0.6 * (g_.bottom - g_.top);
  }

  [[nodiscard]] Box legend_box(LegendPlace place) const {
    const double margin = 0.6 * canvas_.font_size;
    double x = g_.right - margin - legend_width_;
    double y = g_.top + margin;
    switch (place) {
      case LegendPlace::top_left:
        x = g_.left + margin;
        break;
      case LegendPlace::bottom_left:
        x = g_.left + margin;
        y = g_.bottom - margin - legend_height_;
        break;
      case LegendPlace::bottom_right:
        y = g_.bottom - margin - legend_height_;
        break;
      case LegendPlace::outside_right:
        x = g_.right + 0.8 * canvas_.font_size;
        y = g_.top;
        break;
      case LegendPlace::above:
        x = g_.right - legend_width_;
        y = legend_band_top_;
        break;
      case LegendPlace::top_right:
      case LegendPlace::best:
      case LegendPlace::none:
        break;
    }
    x = std::round(x);
    y = std::round(y);
    return {x, y, x + legend_width_, y + legend_height_};
  }

  /// The data's lines and markers in device space for the current layout.
  void trace_data() {
    polylines_.clear();
    markers_.clear();
    const Box clip_box{g_.left - 4 * m_.line_width, g_.top - 4 * m_.line_width, g_.right + 4 * m_.line_width,
                       g_.bottom + 4 * m_.line_width};
    for (std::size_t i = 0; i < plot_.series.size(); ++i) {
      polylines_.push_back(has_line(plot_.series[i]) ? detail::device_polylines(data_.series[i], g_, clip_box)
                                                     : std::vector<std::vector<Point>>{});
      markers_.push_back(has_markers(plot_.series[i]) ? detail::device_markers(data_.series[i], g_, clip_box)
                                                      : std::vector<Point>{});
    }
  }

  /// How many samples of the data (every half font size along lines, and markers) `b` holds.
  [[nodiscard]] std::size_t samples_in(const Box& b) const {
    const double step = 0.5 * canvas_.font_size;
    std::size_t count = 0;
    for (const auto& lines : polylines_) {
      for (const auto& line : lines) {
        for (std::size_t k = 0; k + 1 < line.size(); ++k) {
          const Point a = line[k];
          const Point c = line[k + 1];
          const double length = std::hypot(c.x - a.x, c.y - a.y);
          const int samples = 1 + static_cast<int>(length / step);
          for (int s = 0; s < samples; ++s) {
            const double t = static_cast<double>(s) / samples;
            count += b.contains({a.x + t * (c.x - a.x), a.y + t * (c.y - a.y)}) ? 1 : 0;
          }
        }
        if (!line.empty()) count += b.contains(line.back()) ? 1 : 0;
      }
    }
    for (const auto& points : markers_)
      for (const Point& p : points) count += b.contains(p) ? 1 : 0;
    return count;
  }

  /// The inside corner whose legend box (with some clearance) would cover the fewest
  /// samples of the data, sampled every half font size along lines; ties keep the first
  /// of top right, top left, bottom left, bottom right.
  [[nodiscard]] LegendPlace least_occupied_corner() const {
    constexpr LegendPlace corners[] = {LegendPlace::top_right, LegendPlace::top_left, LegendPlace::bottom_left,
                                       LegendPlace::bottom_right};
    LegendPlace best = corners[0];
    std::size_t best_count = static_cast<std::size_t>(-1);
    for (const LegendPlace corner : corners) {
      Box b = legend_box(corner);
      const double clearance = 0.6 * canvas_.font_size;  // data just outside the box counts too
      b = {b.left - clearance, b.top - clearance, b.right + clearance, b.bottom + clearance};
      const std::size_t count = samples_in(b);
      if (count < best_count) {
        best = corner;
        best_count = count;
      }
    }
    return best;
  }

  // --- painting --------------------------------------------------------------------

  void paint_background() {
    set_color(cr_, colors_.background);
    cairo_rectangle(cr_, 0, 0, canvas_.width, canvas_.height);
    cairo_fill(cr_);
  }

  void stroke_thin(const Rgb& color) {
    set_color(cr_, color);
    cairo_set_line_width(cr_, m_.unit);
    cairo_set_dash(cr_, nullptr, 0, 0);
    cairo_stroke(cr_);
  }

  void paint_grid() {
    for (const Tick& t : x_ticks_.major) {
      const double x = crisp(g_.x(t.value));
      if (x <= g_.left + 1 || x >= g_.right - 1) continue;  // the frame draws the edges
      cairo_move_to(cr_, x, g_.top);
      cairo_line_to(cr_, x, g_.bottom);
    }
    for (const Tick& t : y_ticks_.major) {
      const double y = crisp(g_.y(t.value));
      if (y <= g_.top + 1 || y >= g_.bottom - 1) continue;
      cairo_move_to(cr_, g_.left, y);
      cairo_line_to(cr_, g_.right, y);
    }
    stroke_thin(colors_.grid);
  }

  void set_series_stroke(const Series& series, std::size_t index) {
    set_color(cr_, palette(plot_.theme)[color_slot(series, index)]);
    const double w = m_.line_width;
    cairo_set_line_width(cr_, w);
    cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
    const double dashed[] = {4 * w, 2.5 * w};
    const double dotted[] = {0, 2.2 * w};
    const double dash_dot[] = {4 * w, 2 * w, 0, 2 * w};
    switch (series.dash) {
      case Dash::solid:
        cairo_set_dash(cr_, nullptr, 0, 0);
        break;
      case Dash::dashed:
        cairo_set_dash(cr_, dashed, 2, 0);
        break;
      case Dash::dotted:
        cairo_set_dash(cr_, dotted, 2, 0);
        break;
      case Dash::dash_dot:
        cairo_set_dash(cr_, dash_dot, 4, 0);
        break;
    }
  }

  void marker_path(Marker shape, Point p) {
    const double r = m_.marker_radius;
    switch (shape) {
      case Marker::automatic:
      case Marker::circle:
        cairo_new_sub_path(cr_);
        cairo_arc(cr_, p.x, p.y, r, 0, 2 * std::numbers::pi);
        break;
      case Marker::square:
        cairo_rectangle(cr_, p.x - 0.85 * r, p.y - 0.85 * r, 1.7 * r, 1.7 * r);
        break;
      case Marker::triangle:
        cairo_move_to(cr_, p.x, p.y - 1.2 * r);
        cairo_line_to(cr_, p.x + 1.05 * r, p.y + 0.65 * r);
        cairo_line_to(cr_, p.x - 1.05 * r, p.y + 0.65 * r);
        cairo_close_path(cr_);
        break;
      case Marker::diamond:
        cairo_move_to(cr_, p.x, p.y - 1.25 * r);
        cairo_line_to(cr_, p.x + 1.0 * r, p.y);
        cairo_line_to(cr_, p.x, p.y + 1.25 * r);
        cairo_line_to(cr_, p.x - 1.0 * r, p.y);
        cairo_close_path(cr_);
        break;
      case Marker::cross:
        cairo_move_to(cr_, p.x - r, p.y - r);
        cairo_line_to(cr_, p.x + r, p.y + r);
        cairo_move_to(cr_, p.x - r, p.y + r);
        cairo_line_to(cr_, p.x + r, p.y - r);
        break;
      case Marker::plus:
        cairo_move_to(cr_, p.x - 1.2 * r, p.y);
        cairo_line_to(cr_, p.x + 1.2 * r, p.y);
        cairo_move_to(cr_, p.x, p.y - 1.2 * r);
        cairo_line_to(cr_, p.x, p.y + 1.2 * r);
        break;
    }
  }

  void paint_markers(const Series& series, std::size_t index, const std::vector<Point>& points) {
    if (points.empty()) return;
    const Marker shape = marker_shape(series, index);
    set_color(cr_, palette(plot_.theme)[color_slot(series, index)]);
    cairo_set_dash(cr_, nullptr, 0, 0);
    cairo_set_line_width(cr_, 0.8 * m_.line_width);
    for (const Point& p : points) marker_path(shape, p);
    if (shape == Marker::cross || shape == Marker::plus)
      cairo_stroke(cr_);
    else
      cairo_fill(cr_);
  }

  void paint_series() {
    cairo_save(cr_);
    cairo_rectangle(cr_, g_.left, g_.top, g_.right - g_.left, g_.bottom - g_.top);
    cairo_clip(cr_);
    for (std::size_t i = 0; i < plot_.series.size(); ++i) {
      const Series& series = plot_.series[i];
      if (!polylines_[i].empty()) {
        set_series_stroke(series, i);
        for (const auto& line : polylines_[i]) {
          cairo_move_to(cr_, line.front().x, line.front().y);
          for (std::size_t k = 1; k < line.size(); ++k) cairo_line_to(cr_, line[k].x, line[k].y);
        }
        cairo_stroke(cr_);
      }
      paint_markers(series, i, markers_[i]);
    }
    cairo_restore(cr_);
  }

  void paint_frame_and_ticks() {
    const double left = crisp(g_.left);
    const double bottom = crisp(g_.bottom);
    cairo_rectangle(cr_, left, crisp(g_.top), crisp(g_.right) - left, bottom - crisp(g_.top));
    for (const Tick& t : x_ticks_.major) {
      cairo_move_to(cr_, crisp(g_.x(t.value)), bottom);
      cairo_rel_line_to(cr_, 0, m_.tick);
    }
    for (const double v : x_ticks_.minor) {
      cairo_move_to(cr_, crisp(g_.x(v)), bottom);
      cairo_rel_line_to(cr_, 0, m_.minor_tick);
    }
    for (const Tick& t : y_ticks_.major) {
      cairo_move_to(cr_, left, crisp(g_.y(t.value)));
      cairo_rel_line_to(cr_, -m_.tick, 0);
    }
    for (const double v : y_ticks_.minor) {
      cairo_move_to(cr_, left, crisp(g_.y(v)));
      cairo_rel_line_to(cr_, -m_.minor_tick, 0);
    }
    stroke_thin(colors_.frame);
  }

  void paint_labels() {
    set_color(cr_, colors_.text);
    const double f = canvas_.font_size;
    const double x_label_top = g_.bottom + m_.tick + m_.gap;
    for (const Tick& t : x_ticks_.major)
      draw_text(cr_, t.label, m_.tick_font, g_.x(t.value), x_label_top + tick_label_ascent_, Align::center);
    const double cap = cap_height(cr_, m_.tick_font);
    for (const Tick& t : y_ticks_.major)
      draw_text(cr_, t.label, m_.tick_font, g_.left - m_.tick - m_.gap, g_.y(t.value) + cap / 2, Align::end);
    const double middle_x = (g_.left + g_.right) / 2;
    // Long labels shrink to their axis' length, a long title to the canvas' width.
    if (!plot_.x.label.empty()) {
      const TextExtent tick_label = measure_text(cr_, "10^{8}", m_.tick_font);
      const Font font = fitted(m_.label_font, plot_.x.label, g_.right - g_.left);
      const TextExtent label = measure_text(cr_, plot_.x.label, m_.label_font);
      draw_text(cr_, plot_.x.label, font, middle_x, x_label_top + tick_label.height() + 0.45 * f + label.ascent,
                Align::center);
    }
    if (!plot_.y.label.empty()) {
      const Font font = fitted(m_.label_font, plot_.y.label, g_.bottom - g_.top);
      const TextExtent label = measure_text(cr_, plot_.y.label, m_.label_font);
      cairo_save(cr_);
      cairo_translate(cr_, m_.pad + label.ascent, (g_.top + g_.bottom) / 2);
      cairo_rotate(cr_, -std::numbers::pi / 2);
      draw_text(cr_, plot_.y.label, font, 0, 0, Align::center);
      cairo_restore(cr_);
    }
    if (!plot_.title.empty()) {
      const Font font = fitted(m_.title_font, plot_.title, canvas_.width - 2 * m_.pad);
      const TextExtent title = measure_text(cr_, plot_.title, m_.title_font);
      const double half = measure_text(cr_, plot_.title, font).width / 2;
      const double x = std::max(m_.pad + half, std::min(middle_x, canvas_.width - m_.pad - half));
      draw_text(cr_, plot_.title, font, x, m_.pad + title.ascent, Align::center);
    }
  }

  void paint_legend() {
    if (legend_place_ == LegendPlace::none) return;
    const Box box = legend_box(legend_place_);
    cairo_rectangle(cr_, box.left + 0.5, box.top + 0.5, legend_width_ - 1, legend_height_ - 1);
    set_color(cr_, colors_.background, 0.88);
    cairo_fill_preserve(cr_);
    stroke_thin(colors_.grid);
    const double cap = cap_height(cr_, m_.tick_font);
    double y = box.top + legend_inset() + legend_row_ / 2;
    for (const std::size_t i : legend_entries_) {
      const Series& series = plot_.series[i];
      const double x = box.left + legend_inset();
      if (has_line(series)) {
        set_series_stroke(series, i);
        cairo_move_to(cr_, x, y);
        cairo_line_to(cr_, x + legend_sample_, y);
        cairo_stroke(cr_);
      }
      if (has_markers(series)) paint_markers(series, i, {{x + legend_sample_ / 2, y}});
      set_color(cr_, colors_.text);
      draw_text(cr_, series.name, m_.tick_font, x + legend_sample_ + 0.6 * canvas_.font_size, y + cap / 2,
                Align::start);
      y += legend_row_;
    }
  }

  cairo_t* cr_;
  const Plot& plot_;
  const Canvas& canvas_;
  const std::string& origin_;
  Metrics m_;
  const Colors& colors_;
  detail::CleanData data_;
  double legend_band_top_ = 0;      // where an `above` legend's band starts
  detail::PlotLimits data_limits_;  // from the data and the fixed limits
  detail::PlotLimits limits_;       // drawn: data_limits_, widened at one scale
  Geometry g_;
  Ticks x_ticks_;
  Ticks y_ticks_;
  double tick_label_ascent_ = 0;
  double last_x_overhang_ = 0;
  std::vector<std::size_t> legend_entries_;
  double legend_row_ = 0, legend_sample_ = 0, legend_width_ = 0, legend_height_ = 0;
  LegendPlace legend_place_ = LegendPlace::none;
  std::vector<std::vector<std::vector<Point>>> polylines_;  // per series, device space
  std::vector<std::vector<Point>> markers_;                 // per series, device space
};

}  // namespace

Report draw(cairo_t* cr, const Plot& plot, const Canvas& canvas, const std::string& origin) {
  validate(plot, canvas, origin);
  if (const cairo_status_t status = cairo_status(cr); status != CAIRO_STATUS_SUCCESS)
    throw Error::failure(origin, "cannot draw plot: " + std::string(cairo_status_to_string(status)));
  cairo_save(cr);
  Report report;
  try {
    report = Drawing(cr, plot, canvas, origin).run();
  } catch (...) {
    cairo_restore(cr);
    throw;
  }
  cairo_restore(cr);
  if (const cairo_status_t status = cairo_status(cr); status != CAIRO_STATUS_SUCCESS)
    throw Error::failure(origin, "cannot draw plot: " + std::string(cairo_status_to_string(status)));
  return report;
}

}  // namespace linkage::plot
