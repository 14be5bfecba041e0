// A lesson's render steps on any mechanism: `mechanism` at the top or per step, `set` and
// `trail` as the render command's --set and --trail, `ensemble`, `spread` and `compare` as its
// --ensemble, --spread and --compare, on the homework too (two-blocks.toml); bad keys
// refused at their place.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.hpp"
#include "lesson/lesson.hpp"
#include "lesson/lesson_text.hpp"
#include "lesson/runner.hpp"
#include "support/test_support.hpp"

namespace linkage::lesson {
namespace {

namespace fs = std::filesystem;
using test_text::error_of;
using test_text::parse_text;

TEST(LessonMechanism, TopLevelMechanismReachesRenderStepsAndAStepOverridesIt) {
  test::TempDir dir;
  test::write_text(dir / "pendulum.toml",
                   test::read_text(fs::path(LINKAGE_SOURCE_DIR) / "mechanisms/double-pendulum.toml"));
  const Lesson lesson = parse_text(dir, R"(title = "Mechanisms"
mechanism = "four-bar"
[[step]]
kind = "render"
out = "a.png"
trail = ["3.B"]
set = ["2.theta_dot=3"]
[[step]]
kind = "render"
out = "b.mp4"
duration = 0.5
mechanism = "pendulum.toml"
)");
  ASSERT_EQ(lesson.steps.size(), 2U);
  const auto& a = std::get<RenderStep>(lesson.steps[0].body);
  const auto& b = std::get<RenderStep>(lesson.steps[1].body);
  EXPECT_EQ(a.run.mechanism, "four-bar");
  EXPECT_EQ(a.request.trails, std::vector<std::string>{"3.B"});
  EXPECT_EQ(a.request.settings.title, "Four-bar linkage: a Grashof crank-rocker");
  EXPECT_EQ(fs::path(b.run.mechanism).filename(), "pendulum.toml");
  EXPECT_EQ(b.request.settings.title, "Double pendulum: two uniform rods from a ground pin");
  // The mechanism is part of the cached clip's key.
  EXPECT_NE(lesson.steps[0].canonical.find("mechanism=four-bar"), std::string::npos);
}

TEST(LessonMechanism, BadKeysAreOneLineErrorsAtTheirPlace) {
  EXPECT_NE(
      error_of("title = \"x\"\n[[step]]\nkind = \"render\"\nout = \"a.png\"\ntrail = [\"3.B\"]\n")
          .find("lesson.toml:5:9: step 1 (render): trail: '3' is not a body of the mechanism; valid: ground, 1, 2"),
      std::string::npos);
  EXPECT_NE(error_of("title = \"x\"\nmechanism = \"four-bar\"\n[[step]]\nkind = \"render\"\nout = \"a.png\"\n"
                     "camera = \"fixed\"\n")
                .find("lesson.toml:6:10: step 1 (render): camera: fixed needs view xmin,ymin,xmax,ymax"),
            std::string::npos);
  EXPECT_NE(error_of("title = \"x\"\nmechanism = \"four-bar\"\n[[step]]\nkind = \"render\"\nout = \"a.png\"\n"
                     "trail = [\"3.Q\"]\n")
                .find("'Q' is not a point of 3; valid: A, B, P"),
            std::string::npos);
  EXPECT_NE(error_of("title = \"x\"\nmechanism = \"four-bar\"\n[[step]]\nkind = \"render\"\nout = \"a.png\"\n"
                     "set = [\"zz=1\"]\n")
                .find("'zz'"),
            std::string::npos);
  EXPECT_NE(error_of("title = \"x\"\nmechanism = \"nope.toml\"\n[[step]]\nkind = \"say\"\ntext = \"hi\"\n")
                .find("lesson.toml:2:13: lesson: the file 'nope.toml' does not exist"),
            std::string::npos);
}

// The step runs: the still and the clip come out of `linkage lesson` at draft quality.
TEST(LessonMechanism, RenderStepsMakeTheirFiles) {
  test::TempDir dir;
  test::write_text(dir / "lesson.toml", R"(title = "Mechanisms"
mechanism = "slider-crank"
[[step]]
kind = "render"
out = "a.png"
at = 0.3
[[step]]
kind = "render"
out = "b.mp4"
duration = 0.3
)");
  const test::RunResult r = test::run_linkage(
      {"lesson", (dir / "lesson.toml").string(), "--out", (dir / "out").string(), "--quality", "draft"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(fs::file_size(dir / "out" / "a.png"), 1000U);
  EXPECT_GT(fs::file_size(dir / "out" / "b.mp4"), 1000U);
}

TEST(LessonMechanism, EnsembleAndCompareReachTheClipAsTheRenderFlagsDo) {
  test::TempDir dir;
  const Lesson lesson = parse_text(dir, R"(title = "Chaos"
mechanism = "double-pendulum"
[[step]]
kind = "render"
out = "fan.png"
at = 2
ensemble = 5
spread = 1e-4
compare = ["2.theta=-1.25", "integrator=rk4"]
[[step]]
kind = "render"
out = "case.png"
compare = ["case=1"]
)");
  const auto& fan = std::get<RenderStep>(lesson.steps[0].body);
  EXPECT_EQ(fan.request.ensemble, 5);
  EXPECT_DOUBLE_EQ(fan.request.spread, 1e-4);
  EXPECT_EQ(fan.request.compare, "2.theta=-1.25,integrator=rk4");
  // What they make of the clip is the pipeline's (tests/pipeline/clip_request_test.cpp).
  const auto& by_case = std::get<RenderStep>(lesson.steps[1].body);
  EXPECT_EQ(by_case.request.compare, "case=1");
}

TEST(LessonMechanism, EnsembleAndCompareWorkOnTheHomeworkToo) {
  test::TempDir dir;
  const Lesson lesson = parse_text(dir, R"(title = "Nearby starts"
[[step]]
kind = "render"
out = "fan.png"
at = 2
ensemble = 4
spread = 0.1
compare = ["theta1=0.1000001", "integrator=rk4"]
)");
  const auto& fan = std::get<RenderStep>(lesson.steps[0].body);
  const CheckedMechanismClip checked = render_clip(fan, Quality::draft, dir.path(), {});
  const MechanismClip& clip = checked.clip;
  EXPECT_EQ(clip.ensemble, 4);
  EXPECT_DOUBLE_EQ(clip.spread, 0.1);
  ASSERT_TRUE(clip.compare.has_value());
  // theta1 is two-blocks.toml's 1.theta: the compared run's own system starts there.
  ASSERT_NE(clip.compare->system, nullptr);
  const sym::System& compared = *clip.compare->system;
  EXPECT_EQ(sym::to_double(
                compared.table().find("1.theta")->symbol.subs(clip.compare->initial).subs(compared.parameter_values())),
            0.1000001);
  EXPECT_EQ(clip.compare->simulation.integrator, IntegratorKind::rk4);
  EXPECT_NE(error_of("title = \"x\"\n[[step]]\nkind = \"render\"\nout = \"a.png\"\ncompare = [\"thta1=1\"]\n")
                .find("lesson.toml:5:11: step 1 (render): compare: 'thta1' is not an input (did you mean 'theta1'?)"),
            std::string::npos)
      << error_of("title = \"x\"\n[[step]]\nkind = \"render\"\nout = \"a.png\"\ncompare = [\"thta1=1\"]\n");
}

TEST(LessonMechanism, BadOverlayKeysAreOneLineErrors) {
  const std::string top =
      "title = \"x\"\nmechanism = \"double-pendulum\"\n[[step]]\nkind = \"render\"\nout = \"a.png\"\n";
  EXPECT_NE(error_of(top + "ensemble = 1\n").find("ensemble"), std::string::npos);
  EXPECT_NE(error_of(top + "ensemble = 201\n").find("ensemble"), std::string::npos);
  EXPECT_NE(error_of(top + "spread = 1e-3\n").find("spread: applies only with ensemble N"), std::string::npos);
  EXPECT_NE(error_of(top + "compare = [\"2.theta\"]\n").find("is not NAME=VALUE"), std::string::npos);
  EXPECT_NE(error_of(top + "compare = [\"case=4\"]\n").find("valid: 1, 2, 3"), std::string::npos);
  EXPECT_NE(error_of(top + "compare = [\"integrator=nope\"]\n").find("nope"), std::string::npos);
  // The homework takes them too (its own input names in compare).
  EXPECT_EQ(error_of("title = \"x\"\n[[step]]\nkind = \"render\"\nout = \"a.png\"\nensemble = 3\n"), "");
  EXPECT_NE(error_of("title = \"x\"\n[[step]]\nkind = \"render\"\nout = \"a.png\"\ncompare = [\"2.theta=1\"]\n")
                .find("'2.theta' is not an input"),
            std::string::npos);
}

}  // namespace
}  // namespace linkage::lesson
