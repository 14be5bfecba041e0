#pragma once
// The data side of a plot, without Cairo: which points can be drawn, the axis limits
// they call for, and the device-space polylines (clipped and thinned) that draw them.
#include <cstddef>
#include <vector>

#include "render/plot.hpp"

namespace linkage::plot::detail {

/// A point marking a break in a polyline (both coordinates NaN).
[[nodiscard]] Point gap();
[[nodiscard]] bool is_gap(Point p);

/// The drawable points of every series, in plot order: non-finite points (and those
/// beyond +-1e300, whose spans would overflow) skipped and points with a non-positive
/// coordinate on a log axis dropped, each replaced by a gap.
struct CleanData {
  std::vector<std::vector<Point>> series;
  std::size_t dropped_nonpositive = 0;
  std::size_t skipped_nonfinite = 0;
};
[[nodiscard]] CleanData clean(const Plot& plot);

/// Resolved limits of one axis, min < max (both > 0 on a log axis).
struct Limits {
  double min = 0;
  double max = 1;
};

/// Limits for the x and y axes: fixed limits as given, the others from the data (y
/// only from points inside the x limits), padded when the data has no extent.
struct PlotLimits {
  Limits x;
  Limits y;
};
[[nodiscard]] PlotLimits resolve_limits(const Plot& plot, const CleanData& data);

/// An axis-aligned device rectangle.
struct Box {
  double left = 0;
  double top = 0;
  double right = 0;
  double bottom = 0;
  [[nodiscard]] bool contains(Point p) const { return p.x >= left && p.x <= right && p.y >= top && p.y <= bottom; }
};

/// Clips the segment a-b to `box` (Liang-Barsky); false when nothing of it is inside.
[[nodiscard]] bool clip_segment(Point& a, Point& b, const Box& box);

/// The device-space polylines of a cleaned series, clipped to `box` and thinned
/// without visible change: per device column only the first, lowest, highest and last
/// of consecutive points are kept, and a vertex closer than half a device unit to the
/// last one kept is dropped. A million-point series draws in milliseconds.
[[nodiscard]] std::vector<std::vector<Point>> device_polylines(const std::vector<Point>& points,
                                                               const Geometry& geometry, const Box& box);

/// Device positions of the series' points inside `box`, thinned the same way.
[[nodiscard]] std::vector<Point> device_markers(const std::vector<Point>& points, const Geometry& geometry,
                                                const Box& box);

}  // namespace linkage::plot::detail
