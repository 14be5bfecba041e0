// A plot or compare step's figure: axis words with units, the shared label of a
// mechanism's force components, angles in degrees (values and units, on either axis); and
// `difference`: each run after the first drawn as abs(run - first run), sample by sample.
#include "pipeline/run_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "pipeline/run_support.hpp"

namespace linkage {
namespace {

constexpr double kDegrees = 180 / std::numbers::pi;

Run crank() { return test::mechanism_run("crank", "slider-crank", {"2.theta=0", "2.theta_dot=10"}, 0.3); }

/// The crank turning for 0.3 s, sampled every 0.05 s: `y` against its angle.
plot::Plot crank_plot(const std::vector<std::string>& y, AngleUnit angles) {
  const linkage::Run run = crank();
  Figure f;
  f.x = test::mechanism_column(run, "2.theta");
  for (const std::string& name : y) f.y.push_back(test::mechanism_column(run, name));
  f.every = 0.05;
  f.angles = angles;
  return figure_plot(f, {run});
}

/// The homework for 0.5 s: `y` (its columns' names, x1 for 1.x) against time.
Figure homework_figure(const std::vector<std::string>& y, AngleUnit angles) {
  const linkage::Run run = test::homework_run("", 0.5);
  Figure f;
  f.x = test::named_column(run, "t");
  for (const std::string& name : y) f.y.push_back(test::named_column(run, name));
  f.every = 0.01;
  f.angles = angles;
  return f;
}

TEST(RunPlot, ForceComponentsShareTheirWordsWithoutAStrayComma) {
  const plot::Plot p = crank_plot({"B.force_x", "B.force_y"}, AngleUnit::rad);
  EXPECT_EQ(p.y.label, "force of joint B on body 3, x and y (N)");
  EXPECT_EQ(p.x.label, "angle θ of body 2 (rad)");
  ASSERT_EQ(p.series.size(), 2u);
  EXPECT_EQ(p.series[0].name, "force of joint B on body 3, x");
}

TEST(RunPlot, MechanismAnglesInDegreesOnBothAxes) {
  const plot::Plot rad = crank_plot({"2.theta_dot"}, AngleUnit::rad);
  const plot::Plot deg = crank_plot({"2.theta_dot"}, AngleUnit::deg);
  EXPECT_EQ(rad.y.label, "angular velocity θ̇ of body 2 (rad/s)");
  EXPECT_EQ(deg.x.label, "angle θ of body 2 (deg)");
  EXPECT_EQ(deg.y.label, "angular velocity θ̇ of body 2 (deg/s)");
  EXPECT_TRUE(deg.x.degrees);   // crank-angle ticks at 0, 90, 180 ...
  EXPECT_FALSE(deg.y.degrees);  // a rate: decimal ticks
  EXPECT_FALSE(rad.x.degrees);
  ASSERT_EQ(rad.series.size(), 1u);
  ASSERT_EQ(deg.series.size(), 1u);
  ASSERT_EQ(deg.series[0].points.size(), rad.series[0].points.size());
  ASSERT_EQ(rad.series[0].points.size(), 7u);  // 0, 0.05, ..., 0.3 s
  for (std::size_t i = 0; i < rad.series[0].points.size(); ++i) {
    const plot::Point r = rad.series[0].points[i], d = deg.series[0].points[i];
    EXPECT_NEAR(d.x, kDegrees * r.x, 1e-12 * std::max(1.0, std::fabs(d.x)));
    EXPECT_NEAR(d.y, kDegrees * r.y, 1e-12 * std::max(1.0, std::fabs(d.y)));
  }
  // Starting at 10 rad/s from the outer dead point: at 0 deg, turning at 573 deg/s.
  EXPECT_NEAR(deg.series[0].points[0].x, 0, 1e-9);
  EXPECT_NEAR(deg.series[0].points[0].y, 10 * kDegrees, 1e-6);
}

TEST(RunPlot, LengthsStayInMetresWithAnglesInDegrees) {
  const plot::Plot rad = crank_plot({"S.s"}, AngleUnit::rad);
  const plot::Plot deg = crank_plot({"S.s"}, AngleUnit::deg);
  EXPECT_EQ(deg.y.label, rad.y.label);
  ASSERT_EQ(deg.series[0].points.size(), rad.series[0].points.size());
  for (std::size_t i = 0; i < rad.series[0].points.size(); ++i)
    EXPECT_EQ(deg.series[0].points[i].y, rad.series[0].points[i].y);
}

TEST(RunPlot, HomeworkAnglesInDegrees) {
  const std::vector<linkage::Run> runs{test::homework_run("a", 0.5)};
  const plot::Plot rad = figure_plot(homework_figure({"theta1", "theta2"}, AngleUnit::rad), runs);
  const plot::Plot deg = figure_plot(homework_figure({"theta1", "theta2"}, AngleUnit::deg), runs);
  EXPECT_EQ(rad.y.label, "angle θ of body (rad)");
  EXPECT_EQ(deg.y.label, "angle θ of body (deg)");
  EXPECT_TRUE(deg.y.degrees);
  EXPECT_FALSE(deg.x.degrees);
  EXPECT_EQ(deg.x.label, "time t (s)");
  ASSERT_EQ(deg.series.size(), 2u);
  ASSERT_EQ(rad.series[0].points.size(), 51u);
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t i = 0; i < rad.series[k].points.size(); ++i) {
      EXPECT_EQ(deg.series[k].points[i].x, rad.series[k].points[i].x);  // time stays in s
      EXPECT_NEAR(deg.series[k].points[i].y, kDegrees * rad.series[k].points[i].y, 1e-9);
    }
  // The default start: theta1 = 0.1 rad at t = 0.
  EXPECT_DOUBLE_EQ(rad.series[0].points[0].y, 0.1);
  const plot::Plot rate = figure_plot(homework_figure({"theta1_dot"}, AngleUnit::deg), runs);
  EXPECT_EQ(rate.y.label, "angular velocity θ̇ of body 1 (deg/s)");
}

TEST(RunPlot, RunsByColourAndNamedByLabelAndQuantity) {
  const std::vector<linkage::Run> runs{test::homework_run("a", 0.5), test::homework_run("b", 0.5)};
  const plot::Plot p = figure_plot(homework_figure({"theta1", "theta2"}, AngleUnit::rad), runs);
  ASSERT_EQ(p.series.size(), 4u);
  EXPECT_EQ(p.series[0].name, "a: angle θ of body 1");
  EXPECT_EQ(p.series[3].name, "b: angle θ of body 2");
  EXPECT_EQ(p.series[0].color, p.series[1].color);
  EXPECT_NE(p.series[0].color, p.series[2].color);
  EXPECT_NE(p.series[0].dash, p.series[1].dash);
}

plot::Series series(const std::string& name, std::vector<plot::Point> points) {
  plot::Series s;
  s.name = name;
  s.points = std::move(points);
  return s;
}

TEST(PlotDifference, EachLaterRunLessTheFirstInAbsoluteValue) {
  plot::Plot p;
  p.y.label = "angle θ of body 2 (rad)";
  // Three runs of two series each, run-major as the plot step draws them.
  p.series = {series("a: x", {{0, 1}, {1, 2}}),   series("a: y", {{0, 10}, {1, 20}}),
              series("b: x", {{0, 1.5}, {1, 1}}), series("b: y", {{0, 10}, {1, 23}}),
              series("c: x", {{0, -1}, {1, 2}}),  series("c: y", {{0, 7}, {1, 20}})};
  const plot::Plot d = difference_from_first(p, {"a", "b", "c"}, 2);
  ASSERT_EQ(d.series.size(), 4u);
  EXPECT_EQ(d.y.label, "difference in angle θ of body 2 (rad)");
  EXPECT_EQ(d.series[0].name, "b \u2212 a: x");
  EXPECT_EQ(d.series[3].name, "c \u2212 a: y");
  const double expected[4][2] = {{0.5, 1}, {0, 3}, {2, 0}, {3, 0}};
  for (std::size_t s = 0; s < 4; ++s)
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_DOUBLE_EQ(d.series[s].points[i].x, static_cast<double>(i));
      EXPECT_DOUBLE_EQ(d.series[s].points[i].y, expected[s][i]) << s << " " << i;
    }
  // One colour per compared run, shared by its series.
  EXPECT_EQ(d.series[0].color, d.series[1].color);
  EXPECT_NE(d.series[0].color, d.series[2].color);
}

TEST(PlotDifference, OneSeriesIsNamedByItsRuns) {
  plot::Plot p;
  p.series = {series("first", {{0, 1}}), series("nudged", {{0, 1.25}})};
  const plot::Plot d = difference_from_first(p, {"first", "nudged"}, 1);
  ASSERT_EQ(d.series.size(), 1u);
  EXPECT_EQ(d.series[0].name, "nudged \u2212 first");
  EXPECT_DOUBLE_EQ(d.series[0].points[0].y, 0.25);
}

TEST(PlotDifference, RefusesOneRunAndOtherSampleTimes) {
  plot::Plot one;
  one.series = {series("a", {{0, 1}})};
  EXPECT_THROW((void)difference_from_first(one, {"a"}, 1), Error);
  plot::Plot shifted;
  shifted.series = {series("a", {{0, 1}, {1, 1}}), series("b", {{0, 1}, {1.5, 1}})};
  EXPECT_THROW((void)difference_from_first(shifted, {"a", "b"}, 1), Error);
}

TEST(PlotDifference, IdenticalRunsPartNowhere) {
  Figure f = homework_figure({"theta1", "theta2"}, AngleUnit::rad);
  f.difference = true;
  const plot::Plot d = runs_plot(f, {test::homework_run("a", 0.5), test::homework_run("b", 0.5)});
  ASSERT_EQ(d.series.size(), 2u);
  EXPECT_EQ(d.y.label, "difference in angle θ of body (rad)");
  for (const plot::Series& s : d.series) {
    ASSERT_EQ(s.points.size(), 51u);
    for (const plot::Point& p : s.points) EXPECT_EQ(p.y, 0) << s.name << " at t = " << p.x;
  }
}

TEST(PlotDifference, NudgedRunsPartAndTheGapGrows) {
  // The double pendulum started 1e-6 rad apart: the gap is 1e-6 at t = 0 and not smaller at the end.
  const linkage::Run a = test::mechanism_run("a", "double-pendulum", {}, 1);
  const linkage::Run b = test::mechanism_run("b", "double-pendulum", {"1.theta=-0.799999"}, 1);
  Figure f;
  f.x = test::mechanism_column(a, "t");
  f.y = {test::mechanism_column(a, "1.theta")};
  f.every = 0.1;
  f.difference = true;
  const plot::Plot d = runs_plot(f, {a, b});
  ASSERT_EQ(d.series.size(), 1u);
  ASSERT_EQ(d.series[0].points.size(), 11u);
  EXPECT_NEAR(d.series[0].points.front().y, 1e-6, 1e-12);
  EXPECT_GT(d.series[0].points.back().y, 1e-7);
}

}  // namespace
}  // namespace linkage
