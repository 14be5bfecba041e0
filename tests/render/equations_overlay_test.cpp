// --show equations: the case's equations in a band of their own under the motion (and
// the panel), above the caption; the lines drawn are the ones given, their shared
// indentation removed; the font shrinks to fit and a frame too small is an error that
// names a size that fits. (Bodies stay clear of the band: tests/pipeline/two_blocks_clip_test.cpp.)
#include "render/equations_overlay.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "core/error.hpp"
#include "render/cairo_util.hpp"
#include "render/frame_layout.hpp"
#include "render/label_layout.hpp"
#include "render_test_support.hpp"

namespace linkage {
namespace {

// Case 1 of the homework as `linkage solve --case 1` prints it (checked against the
// report in tests/cli/render_equations_test.cpp); the longest rows are 72 columns.
EquationsText case1() {
  return {"Case 1: eight DAEs in maximal coordinates with the pin force",
          {
              "    (1.1)  m ẍ₁ - Fx = 0",
              "    (2.1)  m ÿ₁ - Fy = -m g",
              "    (3.1)  I θ̈₁ + D sin θ₁ Fx - D cos θ₁ Fy = 0",
              "    (4.1)  m ẍ₂ + Fx = 0",
              "    (5.1)  m ÿ₂ + Fy = -m g",
              "    (6.1)  I θ̈₂ + D sin θ₂ Fx - D cos θ₂ Fy = 0",
              "    (7.1)  ẍ₁ - D sin θ₁ θ̈₁ - ẍ₂ - D sin θ₂ θ̈₂ = D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)",
              "    (8.1)  ÿ₁ + D cos θ₁ θ̈₁ - ÿ₂ + D cos θ₂ θ̈₂ = D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂)",
          }};
}

EquationsText case3() {
  return {"Case 3: four equations in generalized coordinates, no pin force",
          {
              "    (1.3)  m D sin θ₁ ẍ₁ - m D cos θ₁ ÿ₁ + I θ̈₁ = m g D cos θ₁",
              "    (2.3)  m D sin θ₂ ẍ₁ - m D cos θ₂ ÿ₁ + I θ̈₂ = m g D cos θ₂",
              "    (3.3)  2 ẍ₁ - D sin θ₁ θ̈₁ - D sin θ₂ θ̈₂ = D (θ̇₁² cos θ₁ + θ̇₂² cos θ₂)",
              "    (4.3)  2 ÿ₁ + D cos θ₁ θ̈₁ + D cos θ₂ θ̈₂ = D (θ̇₁² sin θ₁ + θ̇₂² sin θ₂) - 2 g",
          }};
}

PanelData theta_panel(std::size_t n) {
  PanelData data;
  data.t_end = 10;
  data.curves.push_back({"θ_{1}", "rad", {}});
  for (std::size_t i = 0; i < n; ++i) {
    data.t.push_back(0.25 * static_cast<double>(i));
    data.curves[0].values.push_back(0.1 + 0.35 * data.t.back());
  }
  return data;
}

RenderSettings with_equations(int width, int height) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.elements.show(Element::equations);
  settings.equations = case1();
  return settings;
}

TEST(EquationsOverlay, DrawsTheGivenLinesWithoutTheirSharedIndent) {
  const std::vector<std::string> drawn = equation_lines_drawn(case1());
  ASSERT_EQ(drawn.size(), 8U);
  for (std::size_t i = 0; i < drawn.size(); ++i) EXPECT_EQ("    " + drawn[i], case1().lines[i]);
  // A wrapped row keeps its own indentation past the shared one.
  const EquationsText wrapped{"", {"    (2.2)  a", "               - g"}};
  EXPECT_EQ(equation_lines_drawn(wrapped), (std::vector<std::string>{"(2.2)  a", "           - g"}));
}

TEST(EquationsOverlay, BandUnderSceneAndPanelAboveTheCaptionAcrossTheFrame) {
  const Theme theme = load_theme("light", {}, "theme");
  for (const bool panel : {false, true}) {
    for (const bool caption : {false, true}) {
      SCOPED_TRACE(std::string(panel ? "panel" : "no panel") + (caption ? ", caption" : ""));
      RenderSettings settings = with_equations(854, 480);
      if (caption) settings.captions = {{0.0, "Case 1 keeps the pin force as an unknown"}};
      FrameLayout layout(settings, theme, panel ? theta_panel(41) : PanelData{});
      const Rect& band = layout.equations_rect();
      EXPECT_EQ(layout.equation_lines(), equation_lines_drawn(case1()));
      EXPECT_EQ(band.x, 0);
      EXPECT_EQ(band.width, 854);
      EXPECT_EQ(band.y, layout.scene_rect().height);
      if (panel) {
        EXPECT_EQ(band.y, layout.panel_rect().y + layout.panel_rect().height);
      }
      EXPECT_EQ(band.y + band.height, caption ? layout.caption_rect().y : 480);
      // Legible at the low preset: the frame's text size or a little less; the scene keeps most of the height.
      EXPECT_GE(layout.equations_fit().font_size, kMinEquationFont);
      EXPECT_LE(layout.equations_fit().font_size, 12);
      EXPECT_LE(band.height, kEquationShare * 480 + 1);
      EXPECT_GE(layout.scene_rect().height, 0.4 * 480);
      Frame frame(854, 480);
      layout.draw(0, 0.0, frame, [](Frame& part) { std::fill(part.pixels.begin(), part.pixels.end(), 0); });
      // The band is painted: background at its corners, text ink (dark) inside.
      EXPECT_EQ(
          test::colour_distance(test::rgb_at(frame, 1, static_cast<int>(band.y) + 1), test::rgb8(theme.background)), 0);
      int ink = 0;
      for (int y = static_cast<int>(band.y); y < static_cast<int>(band.y + band.height); ++y)
        for (int x = 0; x < 854; ++x)
          if (test::colour_distance(test::rgb_at(frame, x, y), test::rgb8(theme.text)) < 40) ++ink;
      EXPECT_GT(ink, 500);
      if (const auto folder = test::picture_folder(); !folder.empty())
        test::write_png_file(frame, folder / (std::string("equations") + (panel ? "-panel" : "") +
                                              (caption ? "-caption" : "") + ".png"));
    }
  }
}

TEST(EquationsOverlay, ShrinksToFitThenRefusesNamingASizeThatFits) {
  const cairo::SurfacePtr scratch = cairo::image_surface(1, 1);
  const cairo::ContextPtr cr = cairo::context(scratch.get());
  DrawStyle style;
  style.u = 1.5;  // 1280x720: the text size is 18 px
  const EquationsFit roomy = fit_equations(cr.get(), style, case1(), 1280, 300);
  EXPECT_DOUBLE_EQ(roomy.font_size, 18);
  const EquationsFit narrow = fit_equations(cr.get(), style, case1(), 640, 300);
  // 72 columns of DejaVu Sans Mono (0.602 em each) in 640 px less the box's padding (2 x 19.8 px).
  EXPECT_NEAR(narrow.font_size, (640 - 39.6) / (72 * 0.602), 0.05);
  EXPECT_LE(narrow.height, 300);
  EXPECT_FALSE(fit_equations(cr.get(), style, case1(), 400, 300).fits());

  RenderSettings small = with_equations(480, 270);
  try {
    small.validate();
    ADD_FAILURE() << "480x270 is too small for Case 1's eight rows";
  } catch (const Error& e) {
    EXPECT_EQ(e.setting(), "show");
    EXPECT_NE(e.detail().find("Case 1's equations (8 lines)"), std::string::npos) << e.detail();
    EXPECT_NE(e.detail().find("480x270"), std::string::npos) << e.detail();
    EXPECT_NE(e.detail().find("quality low (854x480)"), std::string::npos) << e.detail();
  }
  EXPECT_NO_THROW(with_equations(854, 480).validate());
  // Where the frame's text is smaller than legible (480x270: 6.75 px) the band takes the
  // legible size if it fits: Case 3's four rows do.
  RenderSettings draft = with_equations(480, 270);
  draft.equations = case3();
  EXPECT_NO_THROW(draft.validate());
  EXPECT_DOUBLE_EQ(frame_bands(draft).equations.font_size, kMinEquationFont);
  small.elements.hide(Element::equations);  // not shown: not checked
  EXPECT_NO_THROW(small.validate());
}

}  // namespace
}  // namespace linkage
