#pragma once
// Two-dimensional line plots drawn with Cairo, for lesson plot/compare steps and the
// bench reports. A Plot is plain data (title, two axes, series, legend place, theme);
// draw() paints it into any Cairo context and write() saves it as PNG, SVG or PDF,
// atomically (a failed write leaves no file). Same input, same bytes.
//
// Text (title, axis labels, series names) may use ^{...} and _{...} for superscripts
// and subscripts, e.g. "energy error |E − E_{0}| (J)" or "a (m s^{-2})".
#include <cairo.h>

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace linkage::plot {

/// How an axis maps values onto the page.
enum class Scale { linear, log };

/// One axis. Unset limits come from the data, padded by 4 % of its span (of the span
/// of its logarithm on a log axis) so markers at the ends show whole.
struct Axis {
  std::string label{};  ///< Quantity and unit, e.g. "time t (s)".
  Scale scale = Scale::linear;
  std::optional<double> min{};  ///< Fixed lower limit (> 0 on a log axis).
  std::optional<double> max{};  ///< Fixed upper limit (> min).
  bool degrees = false;         ///< An angle in degrees: ticks at 90, 180, ... (degree_ticks).
};

/// What is drawn at a series' points.
enum class Style { line, markers, line_and_markers };
/// Stroke pattern of a series' line.
enum class Dash { solid, dashed, dotted, dash_dot };
/// Marker shape; `automatic` picks one by the series' colour slot.
enum class Marker { automatic, circle, square, triangle, diamond, cross, plus };

struct Point {
  double x = 0;
  double y = 0;
};

/// One curve. Non-finite points are skipped and points with a non-positive value on a
/// log axis dropped; the line breaks at either (no line is drawn across the gap).
struct Series {
  std::string name{};  ///< Legend entry; a series with an empty name stays out of the legend.
  std::vector<Point> points{};
  Style style = Style::line;
  Dash dash = Dash::solid;
  Marker marker = Marker::automatic;
  std::optional<std::size_t> color{};  ///< Palette slot (0..7); default: the series' index modulo 8.
};

/// Where the legend goes. `best` takes the inside corner covering the fewest data
/// points, or `outside_right` when the legend is too large for a corner (unless that
/// leaves the data less than half the width); when it would hide data in every corner,
/// `outside_right` if it is narrow (a fifth of the width at most), else `above`: a band
/// between the title and the data, so the data keeps the whole width.
enum class LegendPlace { best, top_left, top_right, bottom_left, bottom_right, outside_right, above, none };

/// Light (white background, the default) or dark colours.
enum class Theme { light, dark };

/// A complete description of one plot.
struct Plot {
  std::string title{};
  Axis x{};
  Axis y{};
  std::vector<Series> series{};
  LegendPlace legend = LegendPlace::best;
  Theme theme = Theme::light;
  /// x and y at one scale: a data unit as long on both axes (a path keeps its shape); the
  /// axis whose data is shorter on the page is widened about its centre. Linear axes only.
  bool equal_scale = false;
};

/// The drawing size and text size. Pixels for PNG (rounded to whole pixels), points
/// for SVG and PDF, user units for draw().
struct Canvas {
  double width = 900;
  double height = 600;
  double font_size = 14;  ///< Tick labels; the title and axis labels are a little larger.
};

struct Rgb {
  double r = 0;
  double g = 0;
  double b = 0;
};

/// Number of colour slots in a palette.
inline constexpr std::size_t palette_size = 8;

/// The Okabe-Ito colour-blind-safe palette ordered for the theme's background (slot i
/// colours series i unless the series names a slot).
[[nodiscard]] const std::array<Rgb, palette_size>& palette(Theme theme);

/// Maps one axis' data limits onto a device span (pixels or points).
struct AxisMap {
  Scale scale = Scale::linear;
  double min = 0;   ///< Data value at `from`.
  double max = 1;   ///< Data value at `to`.
  double from = 0;  ///< Device coordinate of `min`.
  double to = 1;    ///< Device coordinate of `max` (above `from` for a y axis: smaller).
  /// Device coordinate of a data value (for a log axis, of a positive one).
  [[nodiscard]] double operator()(double value) const;
};

/// Where a drawn plot put its data, in device units of the canvas.
struct Geometry {
  double left = 0;  ///< The data area: [left, right] x [top, bottom].
  double top = 0;
  double right = 0;
  double bottom = 0;
  AxisMap x{};
  AxisMap y{};
  [[nodiscard]] Point to_device(Point data) const { return {x(data.x), y(data.y)}; }
};

/// What draw() and write() did with the data.
struct Report {
  Geometry geometry{};
  std::size_t dropped_nonpositive = 0;     ///< Points with x <= 0 or y <= 0 on a log axis.
  std::size_t skipped_nonfinite = 0;       ///< Points with a NaN, infinite or beyond +-1e300 coordinate.
  LegendPlace legend = LegendPlace::none;  ///< Where the legend went (`best` resolved).
  /// One line for the user about dropped or skipped points, empty when none were.
  [[nodiscard]] std::string warning() const;
};

/// Output formats of write().
enum class Format { png, svg, pdf };

/// The format named by a path's extension (.png, .svg, .pdf, any case), if any.
[[nodiscard]] std::optional<Format> format_of(const std::filesystem::path& path);

/// Throws Error::input, starting with `origin` (a flag, or file:line:column), when the
/// plot or canvas is invalid: non-finite or crossed limits, a non-positive limit on a
/// log axis, a colour slot outside the palette, a canvas out of 100..20000 units or a
/// font size out of 4..200.
void validate(const Plot& plot, const Canvas& canvas, const std::string& origin);

/// Validates and paints `plot` into `cr` on the rectangle (0, 0, width, height) of its
/// current user space; restores the context's state. Throws Error::failure on a Cairo
/// error.
Report draw(cairo_t* cr, const Plot& plot, const Canvas& canvas = {}, const std::string& origin = "plot");

/// Validates `plot`, draws it and writes `target` atomically in the format its
/// extension names. Throws Error::input for an invalid plot, an unknown extension or a
/// missing or unwritable folder, and Error::failure for a Cairo or write error; in
/// every failure no file is left behind.
Report write(const Plot& plot, const std::filesystem::path& target, const Canvas& canvas = {},
             const std::string& origin = "plot");

}  // namespace linkage::plot
