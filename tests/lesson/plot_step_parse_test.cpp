// A plot step as the lesson reads it: `difference` refused where it would mean nothing,
// and `angles` checked against its choices.
#include <gtest/gtest.h>

#include <filesystem>
#include <variant>

#include "core/error.hpp"
#include "lesson/lesson.hpp"
#include "lesson/lesson_text.hpp"
#include "support/test_support.hpp"

namespace linkage::lesson {
namespace {

namespace fs = std::filesystem;
using test_text::error_of;
using test_text::parse_text;

std::string plot_lesson(const std::string& keys) {
  return "title = \"d\"\nmechanism = \"double-pendulum\"\n[[step]]\nkind = \"plot\"\nout = \"d\"\ny = \"2.theta\"\n"
         "difference = true\nduration = 1\n" +
         keys;
}

TEST(PlotStepParse, DifferenceIsRefusedWithoutARunToCompare) {
  EXPECT_NE(error_of(plot_lesson("")).find("'difference' needs two runs or more"), std::string::npos);
  EXPECT_NE(error_of(plot_lesson("x = \"1.theta\"\nruns = [{label = \"a\"}, {label = \"b\"}]\n")).find("remove 'x'"),
            std::string::npos);
  // A fixed-step run on another grid samples other times.
  const std::string grids =
      "runs = [{label = \"a\", integrator = \"rk4\", dt = 0.01}, {label = \"b\", integrator = \"rk4\", dt = 0.003}]\n"
      "every = 0.01\n";
  EXPECT_NE(error_of(plot_lesson(grids)).find("run 'b' is sampled at other times than run 'a'"), std::string::npos);
  // Two runs on the same times: accepted.
  test::TempDir dir;
  test::write_text(dir / "ok.toml",
                   plot_lesson("runs = [{label = \"a\"}, {label = \"b\", set = [\"1.theta=-0.799999\"]}]\n"));
  const Lesson lesson = parse_lesson(dir / "ok.toml");
  const auto& plot_step = std::get<PlotStep>(lesson.steps.at(0).body);
  EXPECT_TRUE(plot_step.figure.difference);
}

TEST(PlotStepParse, AnUnknownAngleUnitNamesItsPlaceAndTheChoices) {
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

// `equal_axes` draws x and y at one scale: accepted for a point's x against its y,
// refused at its place on log axes or in two units (a length against an angle).
TEST(PlotStepParse, EqualAxesNeedsLinearAxesInOneUnit) {
  const std::string head =
      "title = \"d\"\nmechanism = \"four-bar\"\n[[step]]\nkind = \"plot\"\nout = \"d\"\n"
      "duration = 0.1\nequal_axes = true\n";
  test::TempDir dir;
  test::write_text(dir / "ok.toml", head + "x = \"3.P.x\"\ny = \"3.P.y\"\n");
  const Lesson lesson = parse_lesson(dir / "ok.toml");
  const auto& plot_step = std::get<PlotStep>(lesson.steps.at(0).body);
  EXPECT_TRUE(plot_step.figure.equal_axes);
  EXPECT_EQ(plot_step.figure.x.name, "3.P.x");
  const std::string units = error_of(head + "x = \"3.P.x\"\ny = \"2.theta\"\n");
  EXPECT_NE(units.find(":7:"), std::string::npos) << units;  // the line of equal_axes
  EXPECT_NE(units.find("'equal_axes' needs x and y in one unit; x is in 'm', y in 'rad'"), std::string::npos) << units;
  const std::string log = error_of(head + "x = \"3.P.x\"\ny = \"3.P.y\"\nlog_y = true\n");
  EXPECT_NE(log.find("'equal_axes' needs linear axes"), std::string::npos) << log;
}

// A plot's y may define a column; one that reads a parameter the runs set differently is
// refused (it would be evaluated with the first run's value).
TEST(PlotStepParse, ADefinedColumnIsPlottedAndItsParametersMustAgree) {
  test::TempDir dir;
  const std::string head =
      "title = \"d\"\nmechanism = \"double-pendulum\"\n[[step]]\nkind = \"plot\"\nout = \"d\"\nduration = 1\n";
  test::write_text(dir / "ok.toml", head + "y = [\"rel=2.theta-1.theta\", \"tip=l1*1.theta\"]\n");
  const Lesson lesson = parse_lesson(dir / "ok.toml");
  const auto& plot_step = std::get<PlotStep>(lesson.steps.at(0).body);
  ASSERT_EQ(plot_step.figure.y.size(), 2U);
  EXPECT_EQ(plot_step.figure.y[0].unit, "rad");
  EXPECT_EQ(plot_step.figure.y[1].unit, "m");
  const std::string differ =
      error_of(head + "y = \"tip=l1*1.theta\"\nruns = [{label = \"a\"}, {label = \"b\", set = [\"l1=0.4\"]}]\n");
  EXPECT_NE(differ.find("column 'tip' uses 'l1', which run 'b' sets to 0.4 and run 'a' to 0.3"), std::string::npos)
      << differ;
}

}  // namespace
}  // namespace linkage::lesson
