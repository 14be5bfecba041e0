// Reading lessons: a valid lesson's steps, the inputs each step sees, and one clear
// error with FILE:LINE:COLUMN for each broken lesson in tests/data/lessons.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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

TEST(LessonParse, StepsCarryTheInputsEarlierSetStepsMade) {
  test::TempDir dir;
  const Lesson lesson = parse_text(dir, R"(title = "Sets"
[parameters]
m = 0.2
[[step]]
kind = "say"
text = "m is {{m}} kg"
[[step]]
kind = "set"
g = 0
theta1 = 0.5
[[step]]
kind = "exercise"
question = "I?"
answer = "I_zz_C"
[[step]]
kind = "set"
m = 0.3
[[step]]
kind = "solve"
case = [1, 3]
show = ["numeric", "solution"]
)");
  EXPECT_EQ(lesson.title, "Sets");
  EXPECT_EQ(lesson.name, "lesson");
  ASSERT_EQ(lesson.steps.size(), 5u);
  const InputKey& m = *find_input_key("m");
  const InputKey& g = *find_input_key("g");
  EXPECT_EQ(lesson.steps[0].inputs.value(m), 0.2);
  EXPECT_EQ(lesson.steps[0].inputs.value(g), 9.81);
  EXPECT_EQ(lesson.steps[1].inputs.value(g), 0.0);
  EXPECT_EQ(lesson.steps[2].inputs.value(g), 0.0);
  EXPECT_EQ(lesson.steps[2].inputs.value(m), 0.2);
  EXPECT_EQ(lesson.steps[4].inputs.value(m), 0.3);
  EXPECT_EQ(lesson.steps[4].inputs.value(*find_input_key("theta1")), 0.5);
  const auto& set = std::get<SetStep>(lesson.steps[1].body);
  EXPECT_EQ(set.keys, (std::vector<std::string>{"g", "theta1"}));  // file order
  const auto& exercise = std::get<ExerciseStep>(lesson.steps[2].body);
  EXPECT_EQ(exercise.unit, "kg m^2");
  EXPECT_DOUBLE_EQ(exercise.relative_tolerance, 0.01);
  const auto& solve = std::get<SolveStep>(lesson.steps[4].body);
  EXPECT_EQ(solve.cases, (std::vector<int>{1, 3}));
  EXPECT_FALSE(solve.parts[static_cast<std::size_t>(SolvePart::inputs)]);
  EXPECT_TRUE(solve.parts[static_cast<std::size_t>(SolvePart::numeric)]);
  EXPECT_TRUE(solve.parts[static_cast<std::size_t>(SolvePart::solution)]);
  EXPECT_EQ(lesson.steps[3].where, (dir / "lesson.toml").string() + ":15:1");
}

TEST(LessonParse, RunsInheritTheStepsOptionsAndOverrideInputs) {
  test::TempDir dir;
  const Lesson lesson = parse_text(dir, R"(title = "Runs"
[[step]]
kind = "compare"
out = "drift.csv"
case = 1
duration = 2
runs = [ { stabilize = "none" },
         { stabilize = "baumgarte", label = "Baumgarte" },
         { case = 3, g = 0, integrator = "rk4", dt = 0.01 } ]
columns = ["final_error", "constraint_error"]
plot = "constraint_position_error"
)");
  const auto& c = std::get<CompareStep>(lesson.steps[0].body);
  EXPECT_EQ(c.out, "drift");
  ASSERT_EQ(c.runs.size(), 3u);
  EXPECT_EQ(c.runs[0].options.case_id, 1);
  EXPECT_EQ(c.runs[0].options.duration, 2.0);
  EXPECT_EQ(c.runs[1].options.stabilization, Stabilization::baumgarte);
  EXPECT_EQ(c.runs[1].label, "Baumgarte");
  EXPECT_EQ(c.runs[0].label, "Case 1, dop853, rtol 1e-10, none");
  EXPECT_EQ(c.runs[2].options.case_id, 3);
  EXPECT_EQ(c.runs[2].inputs.value(*find_input_key("g")), 0.0);
  EXPECT_EQ(c.runs[0].inputs.value(*find_input_key("g")), 9.81);
  EXPECT_EQ(c.runs[2].label, "Case 3, rk4, dt 0.01 s, g = 0");
  EXPECT_EQ(c.runs[2].series, "rk4");
  ASSERT_TRUE(c.plot.has_value());
  EXPECT_TRUE(c.plot->log_y);
  EXPECT_DOUBLE_EQ(c.every, 2.0 / 400);
  EXPECT_EQ(step_artifacts(lesson.steps[0]), (std::vector<std::string>{"drift.csv", "drift.png", "drift.svg"}));
}

TEST(LessonParse, RenderStepsTakeTheRenderOptions) {
  test::TempDir dir;
  const Lesson lesson = parse_text(dir, R"(title = "Render"
[[step]]
kind = "render"
out = "still.svg"
at = 1.5
size = "640x360"
camera = "fixed"
view = "0,1,2,3"
theme = "dark"
show = ["velocity"]
hide = ["hud", "legend"]
title = "A still"
)");
  const auto& r = std::get<RenderStep>(lesson.steps[0].body);
  EXPECT_EQ(r.kind, OutputKind::svg);
  EXPECT_EQ(r.request.settings.width, 640);
  EXPECT_EQ(r.request.settings.height, 360);
  EXPECT_EQ(r.request.settings.at, 1.5);
  EXPECT_EQ(r.request.settings.camera, CameraMode::fixed);
  EXPECT_EQ(r.request.settings.view.xmax, 2.0);
  EXPECT_EQ(r.request.settings.theme, "dark");
  EXPECT_EQ(r.request.settings.title, "A still");
  EXPECT_TRUE(r.request.settings.elements.has(Element::velocity));
  EXPECT_FALSE(r.request.settings.elements.has(Element::hud));
  EXPECT_TRUE(r.request.settings.elements.has(Element::blocks));
  // The clip the step makes is the render command's, at the step's settings.
  const MechanismClip clip = render_clip(r, Quality::final, dir.path()).clip;
  EXPECT_EQ(clip.settings.width, 640);
  EXPECT_EQ(clip.settings.theme, "dark");
  ASSERT_TRUE(clip.out.has_value());
  EXPECT_EQ(*clip.out, dir.path() / "still.svg");
  EXPECT_TRUE(clip.is_still());
  const MechanismClip draft = render_clip(r, Quality::draft, dir.path()).clip;
  EXPECT_EQ(draft.settings.width, kDraftWidth);
  EXPECT_EQ(draft.settings.height, kDraftHeight);
}

TEST(LessonParse, RenderStepsTakeTimedCaptionsAndAPanel) {
  test::TempDir dir;
  const Lesson lesson = parse_text(dir, R"(title = "Captions"
[[step]]
kind = "render"
out = "clip.mp4"
duration = 4
panel = ["theta1", "theta2"]
captions = [{at = 0, text = "The blocks start at rest."}, {at = 2.5, text = "Now watch the pin."}]
)");
  const auto& r = std::get<RenderStep>(lesson.steps[0].body);
  // The homework's names are two-blocks.toml's keys for the clip (its [aliases]).
  EXPECT_EQ(r.request.settings.panel, (std::vector<std::string>{"1.theta", "2.theta"}));
  ASSERT_EQ(r.request.settings.captions.size(), 2u);
  EXPECT_EQ(r.request.settings.captions[1].at, 2.5);
  EXPECT_EQ(r.request.settings.captions[1].text, "Now watch the pin.");
  // The step's clip carries them to the pipeline, at any quality.
  const MechanismClip draft = render_clip(r, Quality::draft, dir.path()).clip;
  EXPECT_EQ(draft.settings.captions.size(), 2u);
  EXPECT_EQ(draft.settings.panel.size(), 2u);
}

// Each broken lesson's first line says where its error is and what it says:
//   # expect: LINE:COLUMN: message fragment
TEST(LessonParse, BrokenLessonsGiveOneErrorWithFileLineAndColumn) {
  const fs::path folder = fs::path(LINKAGE_SOURCE_DIR) / "tests/data/lessons";
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".toml") continue;
    const std::string file = entry.path().string();
    std::ifstream in(file);
    std::string first;
    std::getline(in, first);
    const std::string tag = "# expect: ";
    ASSERT_EQ(first.rfind(tag, 0), 0u) << file << " lacks an expect line";
    const std::string expected = first.substr(tag.size());
    SCOPED_TRACE(file);
    try {
      (void)parse_lesson(file);
      ADD_FAILURE() << "parsed without an error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::bad_input);
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      const std::string position = expected.substr(0, expected.find(": ") + 2);
      EXPECT_EQ(message.rfind(file + ":" + position, 0), 0u) << message;
      EXPECT_NE(message.find(expected.substr(position.size())), std::string::npos) << message;
    }
    ++checked;
  }
  EXPECT_GE(checked, 23);
}

}  // namespace
}  // namespace linkage::lesson

namespace linkage::lesson {
namespace {

// A lesson that names a mechanism reads its parameters, definitions and inertias in
// {{...}} and answers, at the mechanism's values; its b (0.3) hides the homework's.
TEST(LessonParse, TextAndAnswersUseTheNamesOfTheLessonsMechanism) {
  test::TempDir dir;
  const Lesson lesson = parse_text(dir,
                                   "title = \"T\"\nmechanism = \"four-bar\"\n[[step]]\nkind = \"say\"\n"
                                   "text = \"{{I_3}} = {{mb * b^2 / 12}}, {{ma}} kg\"\n[[step]]\nkind = \"exercise\"\n"
                                   "question = \"Q\"\nanswer = \"I_2\"\n");
  EXPECT_EQ(std::get<SayStep>(lesson.steps[0].body).text.render(), "0.0015 = 0.0015, 0.1 kg");
  EXPECT_DOUBLE_EQ(std::get<ExerciseStep>(lesson.steps[1].body).answer.evaluate(), 0.1 * 0.1 * 0.1 / 12);
  try {
    (void)parse_text(dir, "title = \"T\"\n[[step]]\nkind = \"say\"\ntext = \"{{I_3}}\"\n");
    ADD_FAILURE() << "I_3 without a mechanism";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown name 'I_3'"), std::string::npos) << e.what();
  }
}

// A set step on the lesson's mechanism says what changed with the symbol table's units;
// an exercise's unit is the named symbol's; every number option is a run key.
TEST(LessonParse, MechanismSetStepsAndAnswersTakeTheSymbolsUnits) {
  test::TempDir dir;
  const Lesson lesson = parse_text(dir, R"(title = "T"
mechanism = "four-bar"
[[step]]
kind = "set"
set = ["a=0.12", "2.theta_dot=2"]
[[step]]
kind = "exercise"
question = "Q"
answer = "2.theta_ddot"
[[step]]
kind = "exercise"
question = "Q"
answer = "B.force_x"
[[step]]
kind = "simulate"
dt = 0.002
rtol = 1e-8
atol = 1e-9
duration = 3
baumgarte_alpha = 5
baumgarte_beta = 6
)");
  EXPECT_EQ(std::get<SetStep>(lesson.steps[0].body).changes,
            (std::vector<std::string>{"a = 0.12 m (was 0.1)", "2.theta_dot = 2 rad/s (was 3)"}));
  EXPECT_EQ(std::get<ExerciseStep>(lesson.steps[1].body).unit, "rad/s^2");
  EXPECT_EQ(std::get<ExerciseStep>(lesson.steps[2].body).unit, "N");
  const SimulationOptions& o = std::get<SimulateStep>(lesson.steps[3].body).run.options;
  EXPECT_EQ(o.dt, 0.002);
  EXPECT_EQ(o.rtol, 1e-8);
  EXPECT_EQ(o.atol, 1e-9);
  EXPECT_EQ(o.duration, 3.0);
  EXPECT_EQ(o.baumgarte_alpha, 5.0);
  EXPECT_EQ(o.baumgarte_beta, 6.0);
}

}  // namespace
}  // namespace linkage::lesson
