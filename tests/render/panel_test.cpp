// The live plot beside the motion and the caption band: where they go, what the plot
// holds at a frame, and the pixels of its curve, dot and cursor.
#include "render/panel.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "render/cairo_util.hpp"
#include "render/frame_layout.hpp"
#include "render/render_test_support.hpp"
#include "render/text.hpp"

namespace linkage {
namespace {

PanelData ramp(std::size_t n = 101) {
  PanelData data;
  data.t_end = 10;
  data.curves.push_back({"θ_{1}", "rad", {}});
  for (std::size_t i = 0; i < n; ++i) {
    data.t.push_back(0.1 * static_cast<double>(i));
    data.curves[0].values.push_back(0.1 * static_cast<double>(i));
  }
  return data;
}

TEST(PanelLayout, BesideALandscapeFrameBelowAPortraitOne) {
  const PanelLayout wide = panel_layout(1280, 720, true);
  EXPECT_EQ(wide.panel.x, 768);
  EXPECT_EQ(wide.panel.width, 512);
  EXPECT_EQ(wide.panel.height, 720);
  EXPECT_EQ(wide.scene.width, 768);
  const PanelLayout tall = panel_layout(720, 1280, true);
  EXPECT_EQ(tall.panel.y, 768);
  EXPECT_EQ(tall.panel.height, 512);
  EXPECT_EQ(tall.scene.height, 768);
  const PanelLayout none = panel_layout(1280, 720, false);
  EXPECT_TRUE(none.panel.empty());
  EXPECT_EQ(none.scene.width, 1280);
}

TEST(PanelPlot, SolidUpToNowDottedAheadAxesInWords) {
  const plot::Plot p = panel_plot(ramp(), 40, false);
  EXPECT_EQ(p.y.label, "θ_{1} (rad)");
  EXPECT_EQ(p.x.label, "time t (s)");
  ASSERT_EQ(p.series.size(), 2u);
  EXPECT_EQ(p.series[0].points.size(), 41u);
  EXPECT_EQ(p.series[0].dash, plot::Dash::solid);
  EXPECT_EQ(p.series[1].points.size(), 61u);
  EXPECT_EQ(p.series[1].dash, plot::Dash::dotted);
  EXPECT_TRUE(p.series[1].name.empty());  // the future stays out of the legend
  // Limits fixed over the whole curve, so the axes do not move from frame to frame.
  EXPECT_EQ(*p.x.max, 10);
  EXPECT_NEAR(*p.y.min, -0.6, 1e-12);
  EXPECT_NEAR(*p.y.max, 10.6, 1e-12);
  // Several curves: each named in the legend with its unit, the axis by the shared unit.
  PanelData two = ramp();
  two.curves.push_back({"θ_{2}", "rad", two.curves[0].values});
  const plot::Plot q = panel_plot(two, 100, false);
  EXPECT_EQ(q.y.label, "θ_{1}, θ_{2} (rad)");
  EXPECT_EQ(q.series[0].name, "θ_{1} (rad)");
  EXPECT_EQ(q.series.size(), 2u);  // at the last sample nothing lies ahead
}

TEST(PanelPlot, SeveralCurvesShareTheirWordsAndUnitOnTheAxis) {
  EXPECT_EQ(shared_axis_label({"pin force F_{x}", "pin force F_{y}"}, {"N", "N"}), "pin force (N)");
  EXPECT_EQ(shared_axis_label({"momentum error |p_{x} − p_{x0}|", "momentum error |p_{y} − p_{y0} + 2 m g t|"},
                              {"kg m/s", "kg m/s"}),
            "momentum error (kg m/s)");
  EXPECT_EQ(shared_axis_label({"θ_{1}", "θ_{2}"}, {"rad", "rad"}), "θ_{1}, θ_{2} (rad)");
  // A mechanism's force components: the parts after the comma named, no stray comma.
  EXPECT_EQ(shared_axis_label({"force of joint B on body 3, x", "force of joint B on body 3, y"}, {"N", "N"}),
            "force of joint B on body 3, x and y (N)");
  EXPECT_EQ(shared_axis_label(
                {"force of joint A on body 2, x", "force of joint A on body 2, y", "force of joint A on body 2, z"},
                {"N", "N", "N"}),
            "force of joint A on body 2, x, y and z (N)");
  // Too long to name the parts: the shared words alone, still without the comma.
  EXPECT_EQ(shared_axis_label({"force of joint B on body 3, along the slider", "force of joint B on body 3, across it"},
                              {"N", "N"}),
            "force of joint B on body 3 (N)");
  EXPECT_EQ(shared_axis_label({"θ_{1}", "pin force F_{x}"}, {"rad", "N"}), "θ_{1}, pin force F_{x}");
  EXPECT_EQ(shared_axis_label({"relative energy error |E − E_{0}| / E_{scale}", "distance of G from the parabola"},
                              {"", "m"}),
            "value");
}

/// The panel of `data` at sample `index` painted into `rect` of a light width x height frame.
struct Painted {
  Frame frame;
  plot::Report report;
};
Painted painted(const PanelData& data, std::size_t index, int width, int height, const Rect& rect) {
  const Theme theme = load_theme("light", {}, "theme");
  DrawStyle style;
  style.theme = &theme;
  style.u = 1;
  Painted out{Frame(width, height), {}};
  const cairo::SurfacePtr surface = cairo::surface_for(out.frame);
  const cairo::ContextPtr cr = cairo::context(surface.get());
  out.report = paint_panel(cr.get(), style, data, index, rect);
  cairo_surface_flush(surface.get());
  return out;
}

/// Colour slot `slot` of the light palette in 8-bit channels.
test::Rgb8 slot_colour(std::size_t slot) {
  const plot::Rgb c = plot::palette(plot::Theme::light)[slot];
  return {static_cast<int>(std::lround(255 * c.r)), static_cast<int>(std::lround(255 * c.g)),
          static_cast<int>(std::lround(255 * c.b))};
}

TEST(PanelPaint, CursorAndDotAtTheFramesTime) {
  const Rect rect{100, 50, 400, 300};
  const Painted p = painted(ramp(), 50, 500, 400, rect);
  const Frame& frame = p.frame;
  const plot::Geometry& g = p.report.geometry;
  const test::Rgb8 curve = slot_colour(0);
  // The dot on the curve at t = 5 s, in the frame's coordinates (the panel is offset).
  const plot::Point now = g.to_device({5.0, 5.0});
  EXPECT_LE(test::colour_distance(
                test::rgb_at(frame, static_cast<int>(rect.x + now.x), static_cast<int>(rect.y + now.y)), curve),
            40);
  // The solid curve so far at t = 2 s.
  const plot::Point past = g.to_device({2.0, 2.0});
  EXPECT_LE(test::colour_distance(
                test::rgb_at(frame, static_cast<int>(rect.x + past.x), static_cast<int>(rect.y + past.y)), curve),
            60);
  // The cursor: a grey line through the data area at t = 5 s, well away from the curve.
  const int cx = static_cast<int>(std::lround(rect.x + now.x - 0.5));
  const int cy = static_cast<int>(rect.y + g.top + 0.2 * (g.bottom - g.top));
  const test::Rgb8 cursor = test::rgb_at(frame, cx, cy);
  const test::Rgb8 beside = test::rgb_at(frame, cx + 15, cy);
  EXPECT_LT(cursor.r + cursor.g + cursor.b, beside.r + beside.g + beside.b - 150);
  // Nothing outside the panel's rectangle.
  EXPECT_EQ(frame.pixel(50, 20), 0u);
}

// D6: energy (J) and a force (N) never share an axis: one plot per unit, stacked, each
// axis its quantity and unit; the lowest plot (the force's) fills the lower half and its
// dot at the frame's time is in the force's colour slot (1), not the energy's.
TEST(PanelPaint, QuantitiesOfDifferentUnitsGetTheirOwnAxes) {
  PanelData data = ramp();
  data.curves[0] = {"energy E = T + V", "J", {}};
  data.curves.push_back({"force of joint O2 on the ground, x", "N", {}});
  data.curves.push_back({"force of joint O2 on the ground, y", "N", {}});
  for (std::size_t i = 0; i < data.t.size(); ++i) {
    data.curves[0].values.push_back(2.5);
    data.curves[1].values.push_back(std::sin(data.t[i]));
    data.curves[2].values.push_back(-14 * std::cos(data.t[i]));
  }
  const std::vector<std::vector<std::size_t>> groups = unit_groups(data);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0], std::vector<std::size_t>{0});
  EXPECT_EQ(groups[1], (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(panel_index(data, 5.0), 50u);
  EXPECT_EQ(panel_index(data, 5.04), 50u);
  EXPECT_EQ(panel_index(data, -1.0), 0u);
  const Painted p = painted(data, 50, 500, 700, {0, 0, 500, 700});
  const plot::Report& report = p.report;
  const plot::Geometry& g = report.geometry;
  // In the lower plot's own coordinates (drawn 350 down): the forces' limits, padded 6 %.
  EXPECT_NEAR(g.y.min, -14 - 0.06 * 28, 0.01);
  EXPECT_NEAR(g.y.max, 14 + 0.06 * 28, 0.01);
  EXPECT_NE(report.legend, plot::LegendPlace::none);
  // The legend names what tells the forces apart; the axis the words they share.
  const plot::Plot forces = panel_plot(PanelData{data.t, {data.curves[1], data.curves[2]}, data.t_end}, 50, false);
  EXPECT_EQ(forces.y.label, "force of joint O2 on the ground, x and y (N)");
  EXPECT_EQ(forces.series[0].name, "x (N)");
  EXPECT_EQ(forces.series[2].name, "y (N)");
  const plot::Point dot = g.to_device({5.0, std::sin(5.0)});
  EXPECT_LE(test::colour_distance(test::rgb_at(p.frame, static_cast<int>(dot.x), static_cast<int>(350 + dot.y)),
                                  slot_colour(1)),
            40);
}

// Where each stacked plot put its data, in the frame (what a page reads values from): the
// curve of each part is drawn where its maps put it.
TEST(PanelPaint, EachPartsMapsAreWhereItsCurvesAreDrawn) {
  PanelData data = ramp();
  data.curves.push_back({"force F", "N", {}});
  for (const double t : data.t) data.curves[1].values.push_back(-3 * std::cos(t));
  const Rect rect{100, 40, 500, 700};
  const Theme theme = load_theme("light", {}, "theme");
  DrawStyle style;
  style.theme = &theme;
  style.u = 1;
  Frame frame(700, 800);
  const cairo::SurfacePtr surface = cairo::surface_for(frame);
  const cairo::ContextPtr cr = cairo::context(surface.get());
  std::vector<PanelPart> parts;
  (void)paint_panel(cr.get(), style, data, 50, rect, &parts);
  cairo_surface_flush(surface.get());
  ASSERT_EQ(parts.size(), 2U);
  EXPECT_EQ(parts[0].curves, std::vector<std::size_t>{0});
  EXPECT_EQ(parts[1].curves, std::vector<std::size_t>{1});
  EXPECT_LT(parts[0].area.y + parts[0].area.height, parts[1].area.y);  // stacked, top first
  for (const PanelPart& part : parts) {
    EXPECT_GE(part.area.x, rect.x);
    EXPECT_LE(part.area.x + part.area.width, rect.x + rect.width);
    EXPECT_NEAR(part.time(0), part.area.x, 1e-9);
    EXPECT_NEAR(part.time(10), part.area.x + part.area.width, 1e-9);
    // The dot on the curve at the cursor, t = 5 s, in the curve's colour.
    const std::size_t c = part.curves[0];
    const double x = part.time(5.0), y = part.value(data.curves[c].values[50]);
    EXPECT_LE(test::colour_distance(test::rgb_at(frame, static_cast<int>(x), static_cast<int>(y)), slot_colour(c)), 40)
        << "part of curve " << c;
  }
}

TEST(Captions, EachShownFromItsTimeUntilTheNext) {
  const std::vector<Caption> captions{{0.0, "first"}, {2.0, "second"}};
  EXPECT_EQ(caption_at(captions, 0.0), "first");
  EXPECT_EQ(caption_at(captions, 1.99), "first");
  EXPECT_EQ(caption_at(captions, 2.0), "second");
  EXPECT_EQ(caption_at({{1.0, "late"}}, 0.5), "");
}

TEST(Captions, ACaptionWithAnEndGoesAtItsEnd) {
  const std::vector<Caption> captions{{0.0, "dead point", 0.25}, {1.0, "one turn"}};
  EXPECT_EQ(caption_at(captions, 0.2), "dead point");
  EXPECT_EQ(caption_at(captions, 0.25), "");
  EXPECT_EQ(caption_at(captions, 0.9), "");
  EXPECT_EQ(caption_at(captions, 1.0), "one turn");
  EXPECT_EQ(caption_at(captions, 50.0), "one turn");
}

TEST(Captions, AnEndAfterTheNextCaptionOrBeforeItsStartIsRefused) {
  RenderSettings settings;
  settings.captions = {{0.0, "first", 1.5}, {1.0, "second"}};
  EXPECT_THROW(settings.validate(), Error);
  settings.captions = {{0.5, "first", 0.5}};
  EXPECT_THROW(settings.validate(), Error);
  settings.captions = {{0.0, "first", 1.0}, {1.0, "second"}};
  EXPECT_NO_THROW(settings.validate());
  settings.captions = {{0.0, "first"}, {1.0, "second", 2.0}};
  EXPECT_NO_THROW(settings.validate());
}

TEST(Captions, LongTextWrapsAtSpacesWithinTheWidth) {
  const cairo::SurfacePtr surface = cairo::image_surface(1, 1);
  const cairo::ContextPtr cr = cairo::context(surface.get());
  const std::string text = "The centre of mass falls on a parabola while the blocks turn about it at constant rate";
  const std::vector<std::string> lines = wrap_text(cr.get(), 12, text, 200);
  ASSERT_GE(lines.size(), 3u);
  std::string joined;
  for (const std::string& line : lines) {
    EXPECT_LE(text::width(cr.get(), {12, false}, line.c_str()), 200) << line;
    if (!joined.empty()) joined += ' ';
    joined += line;
  }
  EXPECT_EQ(joined, text);
  EXPECT_EQ(wrap_text(cr.get(), 12, "one\ntwo", 1000), (std::vector<std::string>{"one", "two"}));
}

TEST(FrameLayout, SceneThenPanelThenCaptionBandCoverTheFrame) {
  RenderSettings settings;
  settings.width = 640;
  settings.height = 360;
  settings.captions = {{0.0, "The pin force is small next to the weight"}};
  const Theme theme = load_theme("light", {}, "theme");
  FrameLayout layout(settings, theme, ramp());
  const RenderSettings& scene = layout.scene_settings();
  EXPECT_EQ(scene.width % 2, 0);
  EXPECT_EQ(scene.height % 2, 0);
  EXPECT_EQ(layout.panel_rect().x, scene.width);
  EXPECT_EQ(layout.panel_rect().x + layout.panel_rect().width, 640);
  EXPECT_EQ(layout.caption_rect().y, scene.height);
  EXPECT_EQ(layout.caption_rect().y + layout.caption_rect().height, 360);
  EXPECT_GT(layout.caption_rect().height, 15);
  Frame frame(640, 360);
  layout.draw(30, 3.0, frame, [&](Frame& part) {
    EXPECT_EQ(part.width, scene.width);
    for (std::size_t i = 0; i < part.pixels.size(); i += 4) {  // opaque red
      part.pixels[i] = 0;
      part.pixels[i + 1] = 0;
      part.pixels[i + 2] = 255;
      part.pixels[i + 3] = 255;
    }
  });
  const test::Rgb8 red{255, 0, 0};
  EXPECT_EQ(test::colour_distance(test::rgb_at(frame, 10, 10), red), 0);
  EXPECT_EQ(test::colour_distance(test::rgb_at(frame, scene.width - 1, scene.height - 1), red), 0);
  EXPECT_GT(test::colour_distance(test::rgb_at(frame, scene.width + 2, 10), red), 100);
  EXPECT_EQ(test::colour_distance(test::rgb_at(frame, 2, 358), test::rgb8(theme.background)), 0);
  if (const auto folder = test::picture_folder(); !folder.empty()) test::write_png_file(frame, folder / "layout.png");
}

}  // namespace
}  // namespace linkage
