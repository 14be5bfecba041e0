// A plot step's `difference`: each run after the first drawn as abs(run - first run),
// sample by sample, and the lesson refuses it where it would mean nothing.
#include "lesson/plot_difference.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <variant>

#include "core/error.hpp"
#include "lesson/lesson.hpp"
#include "support/test_support.hpp"

namespace linkage::lesson {
namespace {

namespace fs = std::filesystem;

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

std::string plot_lesson(const std::string& keys) {
  return "title = \"d\"\nmechanism = \"double-pendulum\"\n[[step]]\nkind = \"plot\"\nout = \"d\"\ny = \"2.theta\"\n"
         "difference = true\nduration = 1\n" +
         keys;
}

std::string parse_error(const std::string& text) {
  test::TempDir dir;
  const fs::path file = dir / "d.toml";
  test::write_text(file, text);
  try {
    (void)parse_lesson(file);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    return e.what();
  }
  return "";
}

TEST(PlotDifference, TheLessonRefusesItWithoutARunToCompare) {
  EXPECT_NE(parse_error(plot_lesson("")).find("'difference' needs two runs or more"), std::string::npos);
  EXPECT_NE(parse_error(plot_lesson("x = \"1.theta\"\nruns = [{label = \"a\"}, {label = \"b\"}]\n")).find("remove 'x'"),
            std::string::npos);
  // A fixed-step run on another grid samples other times.
  const std::string grids =
      "runs = [{label = \"a\", integrator = \"rk4\", dt = 0.01}, {label = \"b\", integrator = \"rk4\", dt = 0.003}]\n"
      "every = 0.01\n";
  EXPECT_NE(parse_error(plot_lesson(grids)).find("run 'b' is sampled at other times than run 'a'"), std::string::npos);
  // Two runs on the same times: accepted.
  test::TempDir dir;
  test::write_text(dir / "ok.toml",
                   plot_lesson("runs = [{label = \"a\"}, {label = \"b\", set = [\"1.theta=-0.799999\"]}]\n"));
  const Lesson lesson = parse_lesson(dir / "ok.toml");
  const auto& plot_step = std::get<PlotStep>(lesson.steps.at(0).body);
  EXPECT_TRUE(plot_step.figure.difference);
}

}  // namespace
}  // namespace linkage::lesson
