// A plot step's figure: axis words with units, the shared label of a mechanism's force
// components, and angles in degrees (values and units, on either axis) with angles = "deg".
#include "lesson/figure_plot.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

#include "lesson/runner.hpp"
#include "support/test_support.hpp"

namespace linkage::lesson {
namespace {

namespace fs = std::filesystem;

constexpr double kDegrees = 180 / std::numbers::pi;

/// The plot of a lesson with `header` (and its steps) and then a plot step with `keys`.
plot::Plot step_plot(const std::string& header, const std::string& keys) {
  test::TempDir dir;
  const fs::path file = dir / "lesson.toml";
  test::write_text(file, "title = \"Plot\"\n" + header + "\n[[step]]\nkind = \"plot\"\nout = \"p\"\n" + keys);
  const Lesson lesson = parse_lesson(file);
  const auto& s = std::get<PlotStep>(lesson.steps.back().body);
  return figure_plot(s.figure, s.runs);
}

const std::string kCrank =
    "mechanism = \"slider-crank\"\n[[step]]\nkind = \"set\"\nset = [\"2.theta=0\", \"2.theta_dot=10\"]";
const std::string kTurn = "duration = 0.3\nevery = 0.05\nx = \"2.theta\"\n";

TEST(FigurePlot, ForceComponentsShareTheirWordsWithoutAStrayComma) {
  const plot::Plot p = step_plot(kCrank, kTurn + "y = [\"B.force_x\", \"B.force_y\"]\n");
  EXPECT_EQ(p.y.label, "force of joint B on body 3, x and y (N)");
  EXPECT_EQ(p.x.label, "angle θ of body 2 (rad)");
  ASSERT_EQ(p.series.size(), 2u);
  EXPECT_EQ(p.series[0].name, "force of joint B on body 3, x");
}

TEST(FigurePlot, MechanismAnglesInDegreesOnBothAxes) {
  const plot::Plot rad = step_plot(kCrank, kTurn + "y = [\"2.theta_dot\"]\n");
  const plot::Plot deg = step_plot(kCrank, kTurn + "y = [\"2.theta_dot\"]\nangles = \"deg\"\n");
  EXPECT_EQ(rad.y.label, "angular velocity θ̇ of body 2 (rad/s)");
  EXPECT_EQ(deg.x.label, "angle θ of body 2 (deg)");
  EXPECT_EQ(deg.y.label, "angular velocity θ̇ of body 2 (deg/s)");
  EXPECT_TRUE(deg.x.degrees);   // crank-angle ticks at 0, 90, 180 ...
  EXPECT_FALSE(deg.y.degrees);  // a rate: decimal ticks
  EXPECT_FALSE(rad.x.degrees);
  ASSERT_EQ(rad.series.size(), 1u);
  ASSERT_EQ(deg.series.size(), 1u);
  ASSERT_EQ(deg.series[0].points.size(), rad.series[0].points.size());
  ASSERT_GT(rad.series[0].points.size(), 5u);
  for (std::size_t i = 0; i < rad.series[0].points.size(); ++i) {
    const plot::Point r = rad.series[0].points[i], d = deg.series[0].points[i];
    EXPECT_NEAR(d.x, kDegrees * r.x, 1e-12 * std::max(1.0, std::fabs(d.x)));
    EXPECT_NEAR(d.y, kDegrees * r.y, 1e-12 * std::max(1.0, std::fabs(d.y)));
  }
  // Starting at 10 rad/s from the outer dead point: at 0 deg, turning at 573 deg/s.
  EXPECT_NEAR(deg.series[0].points[0].x, 0, 1e-9);
  EXPECT_NEAR(deg.series[0].points[0].y, 10 * kDegrees, 1e-6);
}

TEST(FigurePlot, LengthsStayInMetresWithAnglesInDegrees) {
  const plot::Plot rad = step_plot(kCrank, kTurn + "y = \"S.s\"\n");
  const plot::Plot deg = step_plot(kCrank, kTurn + "y = \"S.s\"\nangles = \"deg\"\n");
  EXPECT_EQ(deg.y.label, rad.y.label);
  ASSERT_EQ(deg.series[0].points.size(), rad.series[0].points.size());
  for (std::size_t i = 0; i < rad.series[0].points.size(); ++i)
    EXPECT_EQ(deg.series[0].points[i].y, rad.series[0].points[i].y);
}

TEST(FigurePlot, HomeworkAnglesInDegrees) {
  const std::string keys = "duration = 0.5\ny = [\"theta1\", \"theta2\"]\n";
  const plot::Plot rad = step_plot("", keys);
  const plot::Plot deg = step_plot("", keys + "angles = \"deg\"\n");
  EXPECT_EQ(rad.y.label, "θ_{1}, θ_{2} (rad)");
  EXPECT_EQ(deg.y.label, "θ_{1}, θ_{2} (deg)");
  EXPECT_TRUE(deg.y.degrees);
  EXPECT_FALSE(deg.x.degrees);
  EXPECT_EQ(deg.x.label, "time t (s)");
  ASSERT_EQ(deg.series.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t i = 0; i < rad.series[k].points.size(); ++i) {
      EXPECT_EQ(deg.series[k].points[i].x, rad.series[k].points[i].x);  // time stays in s
      EXPECT_NEAR(deg.series[k].points[i].y, kDegrees * rad.series[k].points[i].y, 1e-9);
    }
  const plot::Plot rate = step_plot("", "duration = 0.5\ny = \"theta1_dot\"\nangles = \"deg\"\n");
  EXPECT_EQ(rate.y.label, "angular velocity θ̇_{1} (deg/s)");
}

TEST(FigurePlot, AnUnknownAngleUnitNamesItsPlaceAndTheChoices) {
  test::TempDir dir;
  const fs::path file = dir / "lesson.toml";
  test::write_text(file,
                   "title = \"Plot\"\n[[step]]\nkind = \"plot\"\nout = \"p\"\ny = \"theta1\"\nangles = \"grad\"\n");
  try {
    (void)parse_lesson(file);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("lesson.toml:6:"), std::string::npos) << what;
    EXPECT_NE(what.find("grad"), std::string::npos) << what;
    EXPECT_NE(what.find("rad"), std::string::npos) << what;
    EXPECT_NE(what.find("deg"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace linkage::lesson
