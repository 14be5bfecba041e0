// The plot library: tick generation, markup, data cleaning and clipping, and the
// written PNG / SVG / PDF files (size, pixels where the axis mapping says, determinism,
// atomic failure).
#include "render/plot.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <tuple>
#include <vector>

#include "core/error.hpp"
#include "render/plot_data.hpp"
#include "render/plot_text.hpp"
#include "render/plot_ticks.hpp"
#include "support/test_support.hpp"

namespace linkage::plot {
namespace {

using linkage::test::TempDir;

const std::string minus = "\u2212";

std::vector<double> values(const std::vector<Tick>& ticks) {
  std::vector<double> out;
  for (const Tick& t : ticks) out.push_back(t.value);
  return out;
}

std::vector<std::string> labels(const std::vector<Tick>& ticks) {
  std::vector<std::string> out;
  for (const Tick& t : ticks) out.push_back(t.label);
  return out;
}

// --- ticks -------------------------------------------------------------------------

TEST(PlotTicks, LinearZeroToNinePointSeven) {
  const Ticks ticks = linear_ticks(0.0, 9.7, 7);
  EXPECT_EQ(values(ticks.major), (std::vector<double>{0, 2, 4, 6, 8}));
  EXPECT_EQ(labels(ticks.major), (std::vector<std::string>{"0", "2", "4", "6", "8"}));
  // A step of 2 is divided in four: minor ticks at 0.5, 1, 1.5, 2.5, ... 9.5.
  ASSERT_EQ(ticks.minor.size(), 15u);
  EXPECT_DOUBLE_EQ(ticks.minor.front(), 0.5);
  EXPECT_DOUBLE_EQ(ticks.minor.back(), 9.5);
}

TEST(PlotTicks, LinearFiner) {
  const Ticks ticks = linear_ticks(0.0, 9.7, 12);
  EXPECT_EQ(values(ticks.major), (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  const Ticks tenths = linear_ticks(0.0, 1.0, 6);
  EXPECT_EQ(labels(tenths.major), (std::vector<std::string>{"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"}));
  EXPECT_EQ(tenths.major[3].value, 0.6);  // 3 x 0.2 computed as 6 / 10, not 0.6000000000000001
}

TEST(PlotTicks, DegreesAtRightAnglesOverATurn) {
  const Ticks turn = degree_ticks(-18, 378, 6);
  EXPECT_EQ(values(turn.major), (std::vector<double>{0, 90, 180, 270, 360}));
  EXPECT_EQ(labels(turn.major), (std::vector<std::string>{"0", "90", "180", "270", "360"}));
  ASSERT_FALSE(turn.minor.empty());
  // Minor ticks every 30 degrees between the major ones.
  EXPECT_DOUBLE_EQ(turn.minor.front(), 30);
  EXPECT_DOUBLE_EQ(turn.minor.back(), 330);
  EXPECT_EQ(turn.minor.size(), 8u);
  const Ticks finer = degree_ticks(-110, 110, 5);
  EXPECT_EQ(values(finer.major), (std::vector<double>{-90, -45, 0, 45, 90}));
  EXPECT_EQ(labels(finer.major).front(), "−90");
  // Too short a range for three multiples of 15: decimal steps.
  EXPECT_EQ(values(degree_ticks(0, 20, 6).major), values(linear_ticks(0, 20, 6).major));
}

TEST(PlotTicks, LinearNegativeUsesMinusSign) {
  const Ticks ticks = linear_ticks(-2.6, 1.1, 8);
  EXPECT_EQ(labels(ticks.major), (std::vector<std::string>{minus + "2.5", minus + "2.0", minus + "1.5", minus + "1.0",
                                                           minus + "0.5", "0.0", "0.5", "1.0"}));
}

TEST(PlotTicks, LinearSmallMagnitudesAreScientific) {
  const Ticks ticks = linear_ticks(0.0, 3.1e-9, 5);
  EXPECT_EQ(labels(ticks.major),
            (std::vector<std::string>{"0", "1×10^{" + minus + "9}", "2×10^{" + minus + "9}", "3×10^{" + minus + "9}"}));
  const Ticks halves = linear_ticks(1e-9, 3e-9, 5);
  EXPECT_EQ(halves.major[1].label, "1.5×10^{" + minus + "9}");
  const Ticks large = linear_ticks(0.0, 2.5e6, 6);
  EXPECT_EQ(large.major[1].label, "5×10^{5}");
  EXPECT_EQ(large.major[2].label, "1×10^{6}");
}

// Over many ranges: at most max_ticks, evenly spaced 1-2-5 steps, all inside the range,
// and the finest such step (the next finer one would give too many ticks).
TEST(PlotTicks, LinearPropertiesOverManyRanges) {
  for (int i = 0; i < 400; ++i) {
    const double span = (1.1 + std::cos(i * 0.3)) * std::pow(10.0, (i % 11) - 5);
    const double lo = std::sin(i * 1.7) * span * std::pow(10.0, (i % 7) - 3);
    const double hi = lo + span;
    for (const int max_ticks : {2, 5, 9}) {
      const Ticks ticks = linear_ticks(lo, hi, max_ticks);
      SCOPED_TRACE(testing::Message() << "[" << lo << ", " << hi << "] max " << max_ticks);
      ASSERT_GE(ticks.major.size(), 1u);
      ASSERT_LE(ticks.major.size(), static_cast<std::size_t>(max_ticks));
      for (const Tick& t : ticks.major) {
        EXPECT_GE(t.value, lo - 1e-9 * span);
        EXPECT_LE(t.value, hi + 1e-9 * span);
      }
      if (ticks.major.size() < 2) continue;
      const double step = ticks.major[1].value - ticks.major[0].value;
      const double tolerance = 1e-9 * step + 1e-15 * std::fabs(lo);
      for (std::size_t k = 1; k < ticks.major.size(); ++k)
        EXPECT_NEAR(ticks.major[k].value - ticks.major[k - 1].value, step, tolerance);
      const double power = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
      const double mantissa = std::round(step / power);
      ASSERT_TRUE(mantissa == 1 || mantissa == 2 || mantissa == 5) << step;
      EXPECT_NEAR(step, mantissa * power, 1e-6 * step);
      const double finer = mantissa == 5 ? 2 * power : mantissa == 2 ? power : 0.5 * power;
      const double finer_count = std::floor(hi / finer + 1e-9) - std::ceil(lo / finer - 1e-9) + 1;
      EXPECT_GT(finer_count, max_ticks);
    }
  }
}

TEST(PlotTicks, LinearInvalidRangeGivesNothing) {
  EXPECT_TRUE(linear_ticks(1.0, 1.0, 5).major.empty());
  EXPECT_TRUE(linear_ticks(2.0, 1.0, 5).major.empty());
  EXPECT_TRUE(linear_ticks(0.0, std::nan(""), 5).major.empty());
}

TEST(PlotTicks, LogDecadesForWorkPrecisionRange) {
  const Ticks ticks = log_ticks(3e-12, 5e-3, 12);
  std::vector<double> expected;
  for (int k = -11; k <= -3; ++k) expected.push_back(std::pow(10.0, k));
  ASSERT_EQ(ticks.major.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_DOUBLE_EQ(ticks.major[i].value, expected[i]);
  EXPECT_EQ(ticks.major.front().label, "10^{" + minus + "11}");
  EXPECT_EQ(ticks.major.back().label, "10^{" + minus + "3}");
  // Minor ticks at 2..9 x 10^k inside the range: 3e-12 .. 9e-12, then 8 per decade, then 2e-3 .. 5e-3.
  EXPECT_EQ(ticks.minor.size(), 7u + 8u * 8u + 4u);
  EXPECT_DOUBLE_EQ(ticks.minor.front(), 3e-12);
  EXPECT_DOUBLE_EQ(ticks.minor.back(), 5e-3);
}

TEST(PlotTicks, LogLabelsEveryNthDecadeWhenCrowded) {
  const Ticks ticks = log_ticks(1e-13, 1e2, 6);
  EXPECT_EQ(labels(ticks.major), (std::vector<std::string>{"10^{" + minus + "12}", "10^{" + minus + "9}",
                                                           "10^{" + minus + "6}", "10^{" + minus + "3}", "10^{0}"}));
  // The unlabelled decades become the minor ticks (16 decades, 5 labelled).
  EXPECT_EQ(ticks.minor.size(), 11u);
}

TEST(PlotTicks, LogWithinTwoDecades) {
  const Ticks ticks = log_ticks(2.0, 30.0, 5);
  EXPECT_EQ(labels(ticks.major), (std::vector<std::string>{"2", "5", "10", "20"}));
  const Ticks narrow = log_ticks(3.0, 7.0, 6);  // no power of ten inside: 3, 4, 5, 6, 7
  EXPECT_EQ(labels(narrow.major), (std::vector<std::string>{"3", "4", "5", "6", "7"}));
  const Ticks tiny = log_ticks(2.1e-9, 2.9e-9, 6);  // no m x 10^k inside: linear ticks
  ASSERT_GE(tiny.major.size(), 2u);
  EXPECT_GE(tiny.major.front().value, 2.1e-9);
}

TEST(PlotTicks, LogInvalidRangeGivesNothing) {
  EXPECT_TRUE(log_ticks(0.0, 1.0, 5).major.empty());
  EXPECT_TRUE(log_ticks(-1.0, 1.0, 5).major.empty());
}

// --- text markup ----------------------------------------------------------------

TEST(PlotText, Markup) {
  const std::vector<TextRun> runs = parse_markup("a (m s^{-2}) x_{1} 2^3 ^{");
  ASSERT_EQ(runs.size(), 5u);
  EXPECT_EQ(runs[0].text, "a (m s");
  EXPECT_EQ(runs[1].text, minus + "2");
  EXPECT_EQ(runs[1].shift, TextRun::Shift::superscript);
  EXPECT_EQ(runs[2].text, ") x");
  EXPECT_EQ(runs[3].text, "1");
  EXPECT_EQ(runs[3].shift, TextRun::Shift::subscript);
  EXPECT_EQ(runs[4].text, " 2^3 ^{");  // no markup without braces, or without a closing one
}

// D7: "θ̇" (θ and U+0307) and "θ̈" (U+0308) get their dots above the letter, in ink
// where plain "θ" has none, and measure as wide as the letter alone.
TEST(PlotText, CombiningDotsAreDrawnOverTheirLetter) {
  auto ink_above = [](const std::string& text) {
    const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 120, 120), &cairo_surface_destroy);
    const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()), &cairo_destroy);
    set_plot_font_options(cr.get());
    const Font font{40, false};
    cairo_set_source_rgb(cr.get(), 0, 0, 0);
    draw_text(cr.get(), "a" + text, font, 10, 100, Align::start);
    cairo_text_extents_t theta{};
    cairo_text_extents(cr.get(), "θ", &theta);
    cairo_surface_flush(surface.get());
    const unsigned char* data = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    const int top = static_cast<int>(std::floor(100 + theta.y_bearing)) - 2;  // above the letter's ink
    int columns_lo = 120, columns_hi = -1, count = 0;
    for (int y = 0; y < top; ++y)
      for (int x = 0; x < 120; ++x)
        if (data[y * stride + 4 * x + 3] > 128) {
          ++count;
          columns_lo = std::min(columns_lo, x);
          columns_hi = std::max(columns_hi, x);
        }
    const double width = measure_text(cr.get(), "a" + text, font).width;
    return std::tuple{count, columns_lo, columns_hi, width};
  };
  const auto [plain, plain_lo, plain_hi, plain_width] = ink_above("θ");
  const auto [dot, dot_lo, dot_hi, dot_width] = ink_above("θ\u0307");
  const auto [two, two_lo, two_hi, two_width] = ink_above("θ\u0308");
  EXPECT_EQ(plain, 0);
  EXPECT_GT(dot, 4);
  EXPECT_GT(two, dot);
  EXPECT_GT(dot_lo, 10 + 0.5 * plain_width / 2);  // over the θ, not the a
  EXPECT_GT(two_hi - two_lo, dot_hi - dot_lo + 3);
  EXPECT_DOUBLE_EQ(dot_width, plain_width);
  EXPECT_DOUBLE_EQ(two_width, plain_width);
  (void)plain_lo;
  (void)plain_hi;
}

// --- data ----------------------------------------------------------------------------

TEST(PlotData, ClipSegment) {
  const detail::Box box{0, 0, 10, 10};
  Point a{-5, 5};
  Point b{15, 5};
  ASSERT_TRUE(detail::clip_segment(a, b, box));
  EXPECT_DOUBLE_EQ(a.x, 0);
  EXPECT_DOUBLE_EQ(b.x, 10);
  Point c{-5, -5};
  Point d{-1, 20};
  EXPECT_FALSE(detail::clip_segment(c, d, box));
}

TEST(PlotData, LimitsPadAllEqualAndEmptyData) {
  Plot plot;
  plot.series.push_back({"flat", {{1, 5}, {2, 5}, {3, 5}}});
  detail::CleanData data = detail::clean(plot);
  detail::PlotLimits limits = detail::resolve_limits(plot, data);
  EXPECT_LT(limits.y.min, 5);
  EXPECT_GT(limits.y.max, 5);
  EXPECT_NEAR(limits.x.min, 1 - 0.08, 1e-12);  // 4 % of the span each side
  plot.series.clear();
  plot.y.scale = Scale::log;
  data = detail::clean(plot);
  limits = detail::resolve_limits(plot, data);
  EXPECT_EQ(limits.y.min, 1.0);
  EXPECT_EQ(limits.y.max, 10.0);
  // Log limits are padded in log space: 4 % of 10 decades each side.
  plot.series.push_back({"", {{0, 1e-12}, {1, 1e-2}}});
  data = detail::clean(plot);
  limits = detail::resolve_limits(plot, data);
  EXPECT_NEAR(std::log10(limits.y.min), -12.4, 1e-9);
  EXPECT_NEAR(std::log10(limits.y.max), -1.6, 1e-9);
  // One value on a log axis: half a decade either side.
  plot.series[0].points = {{0, 1e-5}, {1, 1e-5}};
  data = detail::clean(plot);
  limits = detail::resolve_limits(plot, data);
  EXPECT_NEAR(std::log10(limits.y.min), -5.5, 1e-9);
  EXPECT_NEAR(std::log10(limits.y.max), -4.5, 1e-9);
}

TEST(PlotData, ThinningKeepsLongSeriesSmall) {
  std::vector<Point> points;
  for (int i = 0; i <= 100000; ++i) points.push_back({i / 100000.0, std::sin(i / 100000.0)});
  Geometry g;
  g.x = {Scale::linear, 0, 1, 100, 900};
  g.y = {Scale::linear, -1, 1, 500, 100};
  const auto lines = detail::device_polylines(points, g, {100, 100, 900, 500});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_LT(lines[0].size(), 2000u);
  EXPECT_DOUBLE_EQ(lines[0].front().x, 100);
  EXPECT_NEAR(lines[0].back().x, 900, 1e-9);  // the last point is kept
}

// A fast oscillation, 125 points per device column: at most four vertices per column,
// and each column's vertical extent (what the pixels show) is kept.
TEST(PlotData, ColumnReductionKeepsTheEnvelope) {
  std::vector<Point> points;
  for (int i = 0; i <= 100000; ++i) points.push_back({i / 100000.0, std::sin(i * 0.37)});
  Geometry g;
  g.x = {Scale::linear, 0, 1, 100, 900};
  g.y = {Scale::linear, -1, 1, 500, 100};
  const auto lines = detail::device_polylines(points, g, {0, 0, 1000, 600});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_LE(lines[0].size(), 4u * 801u);
  std::map<int, std::pair<double, double>> all;
  std::map<int, std::pair<double, double>> kept;
  const auto add = [](std::map<int, std::pair<double, double>>& extent, Point d) {
    auto [it, added] = extent.try_emplace(static_cast<int>(std::floor(d.x)), d.y, d.y);
    it->second = {std::min(it->second.first, d.y), std::max(it->second.second, d.y)};
  };
  for (const Point& p : points) add(all, g.to_device(p));
  for (const Point& d : lines[0]) add(kept, d);
  ASSERT_EQ(kept.size(), all.size());
  for (const auto& [column, extent] : all) {
    EXPECT_NEAR(kept[column].first, extent.first, 0.5) << column;
    EXPECT_NEAR(kept[column].second, extent.second, 0.5) << column;
  }
}

// --- files ---------------------------------------------------------------------------

struct Image {
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface{nullptr, &cairo_surface_destroy};
  [[nodiscard]] int width() const { return cairo_image_surface_get_width(surface.get()); }
  [[nodiscard]] int height() const { return cairo_image_surface_get_height(surface.get()); }
  /// Red, green, blue (0..255) of pixel (x, y).
  [[nodiscard]] std::array<int, 3> rgb(int x, int y) const {
    const unsigned char* row = cairo_image_surface_get_data(surface.get()) +
                               static_cast<std::ptrdiff_t>(y) * cairo_image_surface_get_stride(surface.get());
    std::uint32_t v = 0;
    std::memcpy(&v, row + 4 * x, 4);
    return {static_cast<int>((v >> 16) & 255u), static_cast<int>((v >> 8) & 255u), static_cast<int>(v & 255u)};
  }
};

Image read_png(const std::filesystem::path& path) {
  Image image;
  image.surface.reset(cairo_image_surface_create_from_png(path.c_str()));
  EXPECT_EQ(cairo_surface_status(image.surface.get()), CAIRO_STATUS_SUCCESS) << path;
  cairo_surface_flush(image.surface.get());
  return image;
}

std::array<int, 3> bytes(const Rgb& c) {
  return {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
          static_cast<int>(std::lround(c.b * 255))};
}

bool close_to(const std::array<int, 3>& a, const std::array<int, 3>& b, int tolerance) {
  for (std::size_t i = 0; i < 3; ++i)
    if (std::abs(a[i] - b[i]) > tolerance) return false;
  return true;
}

/// Whether a pixel within `radius` of (x, y) has colour `c` (antialiasing makes the
/// exact pixel of a line's centre depend on rounding).
bool colour_near(const Image& image, Point p, const Rgb& c, int radius = 1) {
  const int cx = static_cast<int>(std::floor(p.x));
  const int cy = static_cast<int>(std::floor(p.y));
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      if (close_to(image.rgb(cx + dx, cy + dy), bytes(c), 40)) return true;
  return false;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

Plot sample_plot() {
  Plot plot;
  plot.title = "Energy error, Case 1";
  plot.x = {"time t (s)", Scale::linear, 0.0, 10.0};
  plot.y = {"|E − E_{0}| (J)", Scale::log, std::nullopt, std::nullopt};
  for (int run = 0; run < 3; ++run) {
    Series s{"run " + std::to_string(run + 1),
             {},
             run == 2 ? Style::line_and_markers : Style::line,
             run == 1 ? Dash::dashed : Dash::solid};
    for (int i = 0; i <= 100; ++i) {
      const double t = i / 10.0;
      s.points.push_back({t, std::pow(10.0, -10 + 2 * run) * (1 + t * t) * (1.2 + std::sin(3 * t))});
    }
    plot.series.push_back(std::move(s));
  }
  return plot;
}

TEST(PlotFile, PngHasTheCanvasSize) {
  const TempDir dir;
  write(sample_plot(), dir / "plot.png");
  const Image image = read_png(dir / "plot.png");
  EXPECT_EQ(image.width(), 900);
  EXPECT_EQ(image.height(), 600);
  write(sample_plot(), dir / "small.png", {640, 400, 12});
  const Image small = read_png(dir / "small.png");
  EXPECT_EQ(small.width(), 640);
  EXPECT_EQ(small.height(), 400);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"plot.png", "small.png"}));  // no temporaries left
}

TEST(PlotFile, SeriesPixelsWhereTheMappingSays) {
  Plot plot;
  plot.x = {"x (m)", Scale::linear, 0.0, 10.0};
  plot.y = {"y (m)", Scale::linear, 0.0, 4.0};
  plot.legend = LegendPlace::none;
  plot.series.push_back({"line", {{0, 1}, {10, 3}}});                     // slot 0
  plot.series.push_back({"dots", {{2, 3.5}, {8, 0.5}}, Style::markers});  // slot 1
  const TempDir dir;
  const Report report = write(plot, dir / "p.png");
  const Image image = read_png(dir / "p.png");
  const auto& colours = palette(Theme::light);
  for (const double x : {1.0, 3.0, 7.5}) {  // away from the grid lines
    const Point device = report.geometry.to_device({x, 1 + 0.2 * x});
    EXPECT_TRUE(colour_near(image, device, colours[0])) << "line at x = " << x;
    // Well off the line: background.
    const Point off = report.geometry.to_device({x, 1 + 0.2 * x + 0.6});
    EXPECT_TRUE(close_to(image.rgb(static_cast<int>(off.x), static_cast<int>(off.y)), {255, 255, 255}, 3));
  }
  for (const Point p : {Point{2, 3.5}, Point{8, 0.5}})
    EXPECT_TRUE(colour_near(image, report.geometry.to_device(p), colours[1], 0)) << p.x;
  // The mapping itself: data limits at the data area's edges.
  EXPECT_DOUBLE_EQ(report.geometry.x(0.0), report.geometry.left);
  EXPECT_DOUBLE_EQ(report.geometry.y(0.0), report.geometry.bottom);
  EXPECT_DOUBLE_EQ(report.geometry.y(4.0), report.geometry.top);
}

TEST(PlotFile, LogAxisDropsNonPositiveValuesAndBreaksTheLine) {
  Plot plot;
  plot.x = {"t (s)", Scale::linear, 0.0, 5.0};
  plot.y = {"error", Scale::log, 1e-3, 1e3};
  plot.legend = LegendPlace::none;
  plot.series.push_back({"e", {{1, 1e-2}, {2, 1e-1}, {3, -5}, {3.5, 0}, {4, 1e2}, {4.5, std::nan("")}}});
  const TempDir dir;
  const Report report = write(plot, dir / "log.png");
  EXPECT_EQ(report.dropped_nonpositive, 2u);
  EXPECT_EQ(report.skipped_nonfinite, 1u);
  EXPECT_NE(report.warning().find("dropped 2"), std::string::npos);
  const Image image = read_png(dir / "log.png");
  const Rgb colour = palette(Theme::light)[0];
  const Geometry& g = report.geometry;
  // Drawn: the segment between the two valid points before the gap.
  EXPECT_TRUE(colour_near(image, g.to_device({1.5, std::sqrt(1e-2 * 1e-1)}), colour));
  // Not drawn: no line across the gap, and nothing at the bottom edge where a
  // clamped non-positive value would land.
  const Point a = g.to_device({2, 1e-1});
  const Point b = g.to_device({4, 1e2});
  EXPECT_FALSE(colour_near(image, {(a.x + b.x) / 2, (a.y + b.y) / 2}, colour, 2));
  for (const double x : {3.0, 3.5}) EXPECT_FALSE(colour_near(image, {g.x(x), g.bottom - 2}, colour, 2));
}

TEST(PlotFile, SvgIsWellFormed) {
  const TempDir dir;
  write(sample_plot(), dir / "plot.svg", {600, 400});
  const std::string svg = read_bytes(dir / "plot.svg");
  ASSERT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("width=\"600pt\""), std::string::npos);
  EXPECT_EQ(svg.substr(svg.find_last_not_of(" \n") - 5, 6), "</svg>");
  // Every opened tag is closed, in order.
  std::vector<std::string> open;
  for (std::size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
    const std::size_t end = svg.find('>', at);
    ASSERT_NE(end, std::string::npos);
    const std::string tag = svg.substr(at + 1, end - at - 1);
    if (tag.empty() || tag[0] == '?' || tag[0] == '!' || tag.back() == '/') continue;
    const std::string name = tag.substr(tag[0] == '/' ? 1 : 0, tag.find_first_of(" \n\t") - (tag[0] == '/' ? 1 : 0));
    if (tag[0] == '/') {
      ASSERT_FALSE(open.empty()) << name;
      ASSERT_EQ(open.back(), name);
      open.pop_back();
    } else {
      open.push_back(name);
    }
  }
  EXPECT_TRUE(open.empty());
}

TEST(PlotFile, SameInputSameBytes) {
  const TempDir dir;
  for (const std::string extension : {".png", ".svg", ".pdf"}) {
    write(sample_plot(), dir / ("a" + extension));
    write(sample_plot(), dir / ("b" + extension));
    const std::string a = read_bytes(dir / ("a" + extension));
    EXPECT_GT(a.size(), 1000u) << extension;
    EXPECT_TRUE(a == read_bytes(dir / ("b" + extension))) << extension;
  }
}

TEST(PlotFile, MissingFolderIsAnErrorAndLeavesNoFile) {
  const TempDir dir;
  try {
    write(sample_plot(), dir / "missing" / "plot.png", {}, "--out");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_NE(std::string(e.what()).find("--out"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
  EXPECT_THROW(write(sample_plot(), dir / "plot.jpg"), Error);  // unknown format
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PlotFile, InvalidPlotsAreInputErrorsNamingTheProblem) {
  const TempDir dir;
  const auto message = [&](const Plot& plot, const Canvas& canvas = {}) {
    try {
      write(plot, dir / "bad.png", canvas, "lesson.toml:4:1");
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::bad_input);
      return std::string(e.what());
    }
    return std::string("no error");
  };
  Plot plot = sample_plot();
  plot.y.min = 0.0;
  EXPECT_EQ(message(plot), "lesson.toml:4:1: y axis min 0 must be > 0 on a log axis");
  plot = sample_plot();
  plot.x.min = 10.0;
  EXPECT_EQ(message(plot), "lesson.toml:4:1: x axis min 10 must be below max 10");
  plot = sample_plot();
  plot.series[1].color = 8;
  EXPECT_EQ(message(plot), "lesson.toml:4:1: series 2 'run 2': colour slot 8 is outside the palette 0..7");
  EXPECT_EQ(message(sample_plot(), {50, 600}), "lesson.toml:4:1: plot width 50 is outside 100..20000");
  EXPECT_NE(message(sample_plot(), {120, 100, 40}).find("too small"), std::string::npos);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PlotFile, EmptyAndDegenerateDataDrawWithoutCrashing) {
  const TempDir dir;
  Plot empty;
  EXPECT_NO_THROW(write(empty, dir / "empty.png"));
  Plot degenerate;
  degenerate.y.scale = Scale::log;
  degenerate.series.push_back({"nothing", {}});
  degenerate.series.push_back({"one value", {{1, 1e-5}, {2, 1e-5}}});
  degenerate.series.push_back({"all bad", {{std::nan(""), 1}, {1, -1}, {INFINITY, 2}}});
  const Report report = write(degenerate, dir / "degenerate.svg");
  EXPECT_EQ(report.dropped_nonpositive, 1u);
  EXPECT_EQ(report.skipped_nonfinite, 2u);
  EXPECT_LT(report.geometry.y.min, 1e-5);
  EXPECT_GT(report.geometry.y.max, 1e-5);
  EXPECT_LT(report.geometry.x.min, 1.0);
  EXPECT_GT(report.geometry.x.max, 2.0);
}

TEST(PlotFile, LegendAvoidsTheData) {
  Plot plot;
  plot.x.min = 0.0;
  plot.x.max = 1.0;
  plot.y.min = 0.0;
  plot.y.max = 1.0;
  // A rising diagonal fills the top-right and bottom-left corners.
  plot.series.push_back({"diagonal", {{0, 0}, {1, 1}}});
  const TempDir dir;
  EXPECT_EQ(write(plot, dir / "a.png").legend, LegendPlace::top_left);
  // A falling one: top right is free again.
  plot.series[0].points = {{0, 1}, {1, 0}};
  EXPECT_EQ(write(plot, dir / "b.png").legend, LegendPlace::top_right);
  plot.legend = LegendPlace::bottom_left;
  EXPECT_EQ(write(plot, dir / "c.png").legend, LegendPlace::bottom_left);
  // Too many entries for a corner: outside, and the data area narrows to make room.
  plot.legend = LegendPlace::best;
  const double wide = write(plot, dir / "d.png").geometry.right;
  for (int i = 0; i < 20; ++i) plot.series.push_back({"series number " + std::to_string(i), {{0.5, 0.5}}});
  const Report crowded = write(plot, dir / "e.png");
  EXPECT_EQ(crowded.legend, LegendPlace::outside_right);
  EXPECT_LT(crowded.geometry.right, wide - 100);
}

/// A zigzag between the bottom and the top: it fills every corner.
Series zigzag(const std::string& name) {
  Series out{name, {}};
  for (int i = 0; i <= 40; ++i) out.points.push_back({i / 40.0, static_cast<double>(i % 2)});
  return out;
}

TEST(PlotFile, ALegendThatWouldHideDataInEveryCornerGoesBesideIt) {
  Plot plot;
  plot.series.push_back(zigzag("zigzag"));
  const TempDir dir;
  const Report report = write(plot, dir / "zigzag.png");
  EXPECT_EQ(report.legend, LegendPlace::outside_right);
  // One corner still free: the legend stays inside, in it.
  plot.series[0].points = {{0, 0}, {1, 1}};
  EXPECT_EQ(write(plot, dir / "diagonal.png").legend, LegendPlace::top_left);
}

// A wide legend that would hide data in every corner goes above the data, in a band of
// its own: the data keeps the whole width (beside it, it kept 60 % of a lesson's plot).
TEST(PlotFile, AWideLegendThatWouldHideDataInEveryCornerGoesAboveIt) {
  Plot plot;
  plot.title = "The crank's speed over one turn";
  plot.series.push_back(zigzag("crank at 10 rad/s from θ = 0, g = 0"));
  const TempDir dir;
  const Report wide = write(plot, dir / "wide.png");
  EXPECT_EQ(wide.legend, LegendPlace::above);
  plot.legend = LegendPlace::none;
  const Report none = write(plot, dir / "none.png");
  EXPECT_DOUBLE_EQ(wide.geometry.left, none.geometry.left);
  EXPECT_DOUBLE_EQ(wide.geometry.right, none.geometry.right);
  EXPECT_GT(wide.geometry.top, none.geometry.top + 20);  // the band
  EXPECT_GT(wide.geometry.bottom - wide.geometry.top, 0.6 * 600);
}

TEST(PlotFile, LongTextFitsASmallCanvas) {
  Plot plot = sample_plot();
  plot.title = "Accuracy against cost: Case 1, Case 2 and Case 3 with every integrator and step size";
  plot.y.label = "final error (largest of |Δx_{1}|, |Δy_{1}|, |Δθ_{1}|, |Δθ_{2}|)";
  for (Series& s : plot.series) s.name = "a rather long legend entry for " + s.name;
  const TempDir dir;
  const Report report = write(plot, dir / "long.png", {640, 400, 12});
  // Too wide to sit beside the data without halving it: the legend goes in a corner.
  EXPECT_NE(report.legend, LegendPlace::outside_right);
  EXPECT_GT(report.geometry.right - report.geometry.left, 0.6 * 640);
}

TEST(PlotFile, DarkThemeBackground) {
  Plot plot = sample_plot();
  plot.theme = Theme::dark;
  const TempDir dir;
  write(plot, dir / "dark.png");
  const Image image = read_png(dir / "dark.png");
  const auto corner = image.rgb(2, 2);
  EXPECT_LT(corner[0] + corner[1] + corner[2], 3 * 60);
}

TEST(PlotDraw, DrawsIntoACallersContextAndRestoresIt) {
  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 500, 300), &cairo_surface_destroy);
  const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()), &cairo_destroy);
  cairo_set_line_width(cr.get(), 7.0);
  const Report report = draw(cr.get(), sample_plot(), {500, 300, 11});
  EXPECT_EQ(cairo_get_line_width(cr.get()), 7.0);
  EXPECT_LT(report.geometry.right, 500);
  EXPECT_GT(report.geometry.left, 0);
  EXPECT_EQ(cairo_status(cr.get()), CAIRO_STATUS_SUCCESS);
}

// At one scale a data unit is as many pixels on x as on y, whatever the canvas' shape and
// the data's extents; the data stays inside the widened limits, centred; log axes refuse.
TEST(PlotFile, EqualScaleGivesBothAxesThePixelsPerUnit) {
  for (const Canvas canvas : {Canvas{900, 600, 14}, Canvas{500, 800, 12}})
    for (const double tall : {0.05, 3.0}) {  // data wider than tall, then taller than wide
      Plot plot;
      plot.x.label = "x of point 3.P (m)";
      plot.y.label = "y of point 3.P (m)";
      plot.equal_scale = true;
      Series ellipse{"P"};
      for (int k = 0; k <= 200; ++k) {
        const double a = 2 * std::numbers::pi * k / 200;
        ellipse.points.push_back({0.12 + 0.3 * std::cos(a), 0.25 + tall * std::sin(a)});
      }
      plot.series.push_back(ellipse);
      const TempDir dir;
      const Report report = write(plot, dir / "p.png", canvas);
      const Geometry& g = report.geometry;
      const double x_per_unit = (g.x.to - g.x.from) / (g.x.max - g.x.min);
      const double y_per_unit = (g.y.from - g.y.to) / (g.y.max - g.y.min);
      EXPECT_NEAR(x_per_unit / y_per_unit, 1.0, 1e-9) << canvas.width << " " << tall;
      EXPECT_LE(g.x.min, 0.12 - 0.3);
      EXPECT_GE(g.x.max, 0.12 + 0.3);
      EXPECT_LE(g.y.min, 0.25 - tall);
      EXPECT_GE(g.y.max, 0.25 + tall);
      EXPECT_NEAR(0.5 * (g.x.min + g.x.max), 0.12, 1e-9);
      EXPECT_NEAR(0.5 * (g.y.min + g.y.max), 0.25, 1e-9);
      // Without it the same data fills the area: the scales differ.
      plot.equal_scale = false;
      const Geometry free = write(plot, dir / "q.png", canvas).geometry;
      EXPECT_GT(std::fabs((free.x.to - free.x.from) / (free.x.max - free.x.min) /
                              ((free.y.from - free.y.to) / (free.y.max - free.y.min)) -
                          1),
                0.1);
    }
  Plot log;
  log.equal_scale = true;
  log.y.scale = Scale::log;
  log.series.push_back({"a", {{1, 1}, {2, 10}}});
  try {
    (void)write(log, TempDir() / "log.png");
    FAIL() << "one scale on a log axis was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("linear"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace linkage::plot
