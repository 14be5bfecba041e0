#include "render/plot_data.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace linkage::plot::detail {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double auto_padding = 0.04;  // fraction of the data span added to a free linear limit
constexpr double thinning = 0.5;       // device units
constexpr double largest = 1e300;      // larger coordinates count as non-finite: spans would overflow

/// Device coordinates stay far inside what Cairo's 24.8 fixed point can hold, and
/// clipping never meets an infinity.
constexpr double device_bound = 1e9;

struct Span {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  [[nodiscard]] bool empty() const { return lo > hi; }
};

/// Limits of one axis from its fixed values and the data span. Works in "t space"
/// (the value itself, or its log10), where padding and degenerate spans are handled
/// alike for both scales.
Limits resolve_axis(const Axis& axis, Span data) {
  const bool log = axis.scale == Scale::log;
  const auto to_t = [log](double v) { return log ? std::log10(v) : v; };
  const auto from_t = [log](double t) { return log ? std::pow(10.0, t) : t; };
  const bool no_data = data.empty();
  if (no_data) data = log ? Span{1.0, 10.0} : Span{0.0, 1.0};  // an empty plot shows [0, 1] or [1, 10]
  const double t_lo = to_t(data.lo);
  const double t_hi = to_t(data.hi);
  const double pad = no_data ? 0.0 : auto_padding * (t_hi - t_lo);
  double lo = axis.min ? to_t(*axis.min) : t_lo - pad;
  double hi = axis.max ? to_t(*axis.max) : t_hi + pad;
  // All-equal data, or data entirely beyond a fixed limit: widen the free side(s) by
  // half a decade on a log axis, by a tenth of the value (or 1 around zero) on a
  // linear one.
  const double scale = std::max(std::fabs(lo), std::fabs(hi));
  if (!(hi - lo > 1e-12 * scale)) {
    const double widen = log ? 0.5 : (scale > 0 ? 0.1 * scale : 1.0);
    if (axis.min && !axis.max) {
      hi = lo + widen;
    } else if (axis.max && !axis.min) {
      lo = hi - widen;
    } else {
      const double middle = (lo + hi) / 2;
      lo = middle - widen;
      hi = middle + widen;
    }
  }
  return {axis.min ? *axis.min : from_t(lo), axis.max ? *axis.max : from_t(hi)};
}

double clamp_device(double v) { return std::clamp(v, -device_bound, device_bound); }

Point device_point(Point p, const Geometry& geometry) {
  const Point d = geometry.to_device(p);
  return {clamp_device(d.x), clamp_device(d.y)};
}

/// Device positions of `points`, gaps kept, reduced column by column: of each run of
/// consecutive points in one device column keep the first, lowest, highest and last,
/// in their order (the "M4" reduction). A line through the kept points covers the same
/// pixels, and a million-point series strokes in milliseconds instead of a minute.
std::vector<Point> reduced_device_points(const std::vector<Point>& points, const Geometry& geometry) {
  std::vector<Point> device;
  device.reserve(points.size());
  for (const Point& p : points) device.push_back(is_gap(p) ? p : device_point(p, geometry));
  std::vector<Point> kept;
  kept.reserve(device.size());
  std::size_t i = 0;
  while (i < device.size()) {
    if (is_gap(device[i])) {
      kept.push_back(device[i++]);
      continue;
    }
    const double column = std::floor(device[i].x);
    std::size_t end = i + 1;
    std::size_t lowest = i;
    std::size_t highest = i;
    for (; end < device.size() && !is_gap(device[end]) && std::floor(device[end].x) == column; ++end) {
      if (device[end].y < device[lowest].y) lowest = end;
      if (device[end].y > device[highest].y) highest = end;
    }
    std::array<std::size_t, 4> picks{i, std::min(lowest, highest), std::max(lowest, highest), end - 1};
    for (std::size_t k = 0; k < picks.size(); ++k)
      if (k == 0 || picks[k] != picks[k - 1]) kept.push_back(device[picks[k]]);
    i = end;
  }
  return kept;
}

bool near(Point a, Point b) { return std::fabs(a.x - b.x) < thinning && std::fabs(a.y - b.y) < thinning; }

bool same(Point a, Point b) { return a.x == b.x && a.y == b.y; }

}  // namespace

Point gap() { return {nan, nan}; }
bool is_gap(Point p) { return std::isnan(p.x); }

CleanData clean(const Plot& plot) {
  CleanData data;
  const bool log_x = plot.x.scale == Scale::log;
  const bool log_y = plot.y.scale == Scale::log;
  for (const Series& series : plot.series) {
    std::vector<Point>& points = data.series.emplace_back();
    points.reserve(series.points.size());
    for (const Point& p : series.points) {
      if (!(std::fabs(p.x) <= largest) || !(std::fabs(p.y) <= largest)) {
        ++data.skipped_nonfinite;
        points.push_back(gap());
      } else if ((log_x && !(p.x > 0)) || (log_y && !(p.y > 0))) {
        ++data.dropped_nonpositive;
        points.push_back(gap());
      } else {
        points.push_back(p);
      }
    }
  }
  return data;
}

PlotLimits resolve_limits(const Plot& plot, const CleanData& data) {
  Span x_span;
  for (const auto& points : data.series)
    for (const Point& p : points)
      if (!is_gap(p)) x_span.add(p.x);
  PlotLimits limits;
  limits.x = resolve_axis(plot.x, x_span);
  // y from the points the x limits show, so a zoomed x axis zooms y as well.
  Span y_span;
  for (const auto& points : data.series)
    for (const Point& p : points)
      if (!is_gap(p) && p.x >= limits.x.min && p.x <= limits.x.max) y_span.add(p.y);
  limits.y = resolve_axis(plot.y, y_span);
  return limits;
}

bool clip_segment(Point& a, Point& b, const Box& box) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - box.left, box.right - a.x, a.y - box.top, box.bottom - a.y};
  double t0 = 0.0;
  double t1 = 1.0;
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;  // parallel to this edge and outside it
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0.0) {
      if (r > t1) return false;
      t0 = std::max(t0, r);
    } else {
      if (r < t0) return false;
      t1 = std::min(t1, r);
    }
  }
  const Point start = a;
  if (t0 > 0.0) a = {start.x + t0 * dx, start.y + t0 * dy};
  if (t1 < 1.0) b = {start.x + t1 * dx, start.y + t1 * dy};
  return true;
}

std::vector<std::vector<Point>> device_polylines(const std::vector<Point>& points, const Geometry& geometry,
                                                 const Box& box) {
  std::vector<std::vector<Point>> lines;
  std::optional<Point> previous;  // device position of the previous valid data point
  std::optional<Point> pending;   // the open line's true end when thinning skipped it
  bool open = false;              // the last line ends (perhaps pending) at `previous`
  const auto close = [&] {
    if (open && pending) lines.back().push_back(*pending);
    pending.reset();
    open = false;
  };
  for (const Point& here : reduced_device_points(points, geometry)) {
    if (is_gap(here)) {
      close();
      previous.reset();
      continue;
    }
    if (!previous) {
      previous = here;
      continue;
    }
    Point a = *previous;
    Point b = here;
    previous = here;
    const Point start = a;
    if (!clip_segment(a, b, box)) {
      close();
      continue;
    }
    if (!open || !same(a, start)) {  // the line starts, or re-enters the box
      close();
      lines.push_back({a});
    }
    if (!same(b, here)) {  // leaves the box
      lines.back().push_back(b);
      pending.reset();
      open = false;
    } else if (near(b, lines.back().back())) {
      pending = b;
      open = true;
    } else {
      lines.back().push_back(b);
      pending.reset();
      open = true;
    }
  }
  close();
  return lines;
}

std::vector<Point> device_markers(const std::vector<Point>& points, const Geometry& geometry, const Box& box) {
  std::vector<Point> markers;
  for (const Point& p : points) {
    if (is_gap(p)) continue;
    const Point here = device_point(p, geometry);
    if (!box.contains(here)) continue;
    if (!markers.empty() && near(here, markers.back())) continue;
    markers.push_back(here);
  }
  return markers;
}

}  // namespace linkage::plot::detail
