// --angles deg: the panel plots the homework's angles and rates in degrees, its axis
// saying so; other quantities keep their units.
#include <gtest/gtest.h>

#include <numbers>

#include "integrate/simulation.hpp"
#include "pipeline/clip.hpp"
#include "pipeline/panel_data.hpp"
#include "render/frame_layout.hpp"
#include "scene/motion.hpp"

namespace linkage {
namespace {

TEST(PanelAngles, DegreesOnTheAxisDataAndInItsWords) {
  const Inputs inputs;
  SimulationOptions options;
  options.duration = 0.2;
  Simulation sim(inputs.params(), inputs.state(), options);
  const Motion motion = sample_motion(sim, {0.0, 0.1, 0.2}, false);
  PanelData data = homework_panel({"theta1", "theta1_dot", "y1"}, sim, motion, inputs.params(),
                                  body_state(inputs.params(), inputs.state()), 0.2);
  ASSERT_EQ(data.curves[0].values[0], 0.1);  // rad, the default state
  const double rate = data.curves[1].values[2];
  const double height = data.curves[2].values[2];

  RenderSettings settings;
  settings.width = 854;
  settings.height = 480;
  settings.angles = AngleUnit::deg;
  const FrameLayout layout(settings, load_theme("light", {}, "theme"), data);
  const PanelData& shown = layout.panel();
  EXPECT_NEAR(shown.curves[0].values[0], 5.72958, 1e-5);  // 0.1 rad
  EXPECT_EQ(shown.curves[0].unit, "deg");
  EXPECT_NEAR(shown.curves[1].values[2], rate * 180 / std::numbers::pi, 1e-12);
  EXPECT_EQ(shown.curves[1].unit, "deg/s");
  EXPECT_EQ(shown.curves[2].values[2], height);  // metres stay metres
  EXPECT_EQ(shown.curves[2].unit, "m");

  // What the plot draws: the first point of θ1 at 5.7296 and the unit in the legend.
  const plot::Plot plot = panel_plot(shown, 0, false);
  ASSERT_FALSE(plot.series.empty());
  ASSERT_FALSE(plot.series[0].points.empty());
  EXPECT_NEAR(plot.series[0].points[0].y, 5.72958, 1e-5);
  EXPECT_NE(plot.series[0].name.find("(deg)"), std::string::npos) << plot.series[0].name;

  // In radians (the default) nothing changes.
  settings.angles = AngleUnit::rad;
  const FrameLayout plain(settings, load_theme("light", {}, "theme"), data);
  EXPECT_EQ(plain.panel().curves[0].values[0], 0.1);
  EXPECT_EQ(plain.panel().curves[0].unit, "rad");
}

}  // namespace
}  // namespace linkage
