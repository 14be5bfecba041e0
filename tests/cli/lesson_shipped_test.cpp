// The shipped course: every lesson in lessons/ runs at draft quality, makes every file
// it declares (each a real PNG, SVG, MP4 or CSV), has at least one clip or still, and
// writes a document that links only files that exist; a second run makes nothing.
// Slow under sanitizers: tests/lesson/labels.cmake gives it the ctest label no-sanitize.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <tuple>

#include "core/number_format.hpp"
#include "lesson/lesson.hpp"
#include "model/mechanism_toml.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_lessons() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(LINKAGE_SOURCE_DIR) / "lessons"))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The file looks like what its extension says.
void expect_real_file(const fs::path& file) {
  ASSERT_TRUE(fs::is_regular_file(file)) << file;
  const std::string bytes = read_text(file);
  ASSERT_GT(bytes.size(), 100u) << file;
  const std::string ext = file.extension().string();
  if (ext == ".png") {
    EXPECT_EQ(bytes.substr(0, 8), "\x89PNG\r\n\x1a\n") << file;
  } else if (ext == ".svg") {
    EXPECT_NE(bytes.find("<svg"), std::string::npos) << file;
  } else if (ext == ".pdf") {
    EXPECT_EQ(bytes.substr(0, 5), "%PDF-") << file;
  } else if (ext == ".mp4") {
    EXPECT_EQ(bytes.substr(4, 4), "ftyp") << file;
  } else {
    EXPECT_EQ(ext, ".csv");
    EXPECT_NE(bytes.find('\n'), std::string::npos) << file;
  }
}

TEST(ShippedLessons, TheCourseIsComplete) {
  std::vector<std::string> names;
  for (const fs::path& file : shipped_lessons()) names.push_back(file.stem().string());
  EXPECT_EQ(
      names,
      (std::vector<std::string>{
          "01-moments-of-inertia", "02-holonomic-constraints", "03-case1-eight-equations", "04-case2-six-equations",
          "05-case3-four-equations", "06-numerical-example", "07-constraint-drift", "08-accuracy-and-cost",
          "09-beyond-the-equations", "10-double-pendulum-chaos", "11-unequal-blocks", "12-slider-crank", "13-four-bar",
          "14-kinematic-analysis", "15-inverse-dynamics", "16-small-vibrations", "17-rolling-and-gearing"}));
}

TEST(ShippedLessons, RunAtDraftQualityAndCache) {
  TempDir dir;
  const std::regex link(R"(\]\(([^)\s]+)\)|src="([^"]+)\")");
  for (const fs::path& file : shipped_lessons()) {
    SCOPED_TRACE(file.filename().string());
    const lesson::Lesson parsed = lesson::parse_lesson(file);
    const fs::path out = dir / parsed.name;
    const RunResult first = run_linkage({"lesson", file.string(), "--out", out.string(), "--quality", "draft"});
    ASSERT_EQ(first.exit_code, 0) << first.err;
    EXPECT_EQ(count(first.err, "): reused "), 0) << first.err;

    bool picture = false;
    for (const lesson::Step& step : parsed.steps)
      if (const auto* render = std::get_if<lesson::RenderStep>(&step.body)) {
        picture = true;
        EXPECT_TRUE(render->kind == OutputKind::mp4 || is_still(render->kind));
      }
    EXPECT_TRUE(picture) << "every lesson renders at least one clip or still";
    for (const std::string& artifact : parsed.artifacts()) expect_real_file(out / artifact);

    const std::string doc = read_text(out / "lesson.md");
    EXPECT_EQ(doc.rfind("# " + parsed.title + "\n", 0), 0u);
    int links = 0;
    for (auto it = std::sregex_iterator(doc.begin(), doc.end(), link); it != std::sregex_iterator(); ++it, ++links) {
      const std::string target = (*it)[1].matched ? (*it)[1].str() : (*it)[2].str();
      EXPECT_TRUE(fs::is_regular_file(out / target)) << target;
    }
    EXPECT_GT(links, 0);

    // Everything is cached now: the second run makes nothing.
    const RunResult second = run_linkage({"lesson", file.string(), "--out", out.string(), "--quality", "draft"});
    ASSERT_EQ(second.exit_code, 0) << second.err;
    EXPECT_EQ(count(second.err, "): made "), 0) << second.err;
    EXPECT_EQ(count(second.err, "): reused "), count(first.err, "): made ")) << second.err;
  }
}

double parameter(const Mechanism& mechanism, const std::string& name) {
  for (const Parameter& p : mechanism.parameters)
    if (p.name == name) return p.value;
  ADD_FAILURE() << mechanism.name << " has no parameter " << name;
  return 0;
}

double initial(const Mechanism& mechanism, const std::string& key) {
  for (const InitialValue& v : mechanism.initial)
    if (v.key == key) return v.value;
  ADD_FAILURE() << mechanism.name << " has no initial " << key;
  return 0;
}

/// Runs only `file`'s exercise steps (and, as --only does, every earlier set step) with
/// --step, typing `answers` in order, and returns how many were marked right; every
/// exercise must get an answer.
int right_answers(const std::string& file, const std::vector<double>& answers) {
  const lesson::Lesson parsed = lesson::parse_lesson(file);
  std::string only;
  std::size_t exercises = 0;
  for (std::size_t i = 0; i < parsed.steps.size(); ++i)
    if (std::holds_alternative<lesson::ExerciseStep>(parsed.steps[i].body)) {
      if (!only.empty()) only += ',';
      only += std::to_string(i + 1);
      ++exercises;
    }
  EXPECT_EQ(exercises, answers.size()) << file;
  std::string typed;
  for (double a : answers) typed += format_significant(a, 12) + "\n";
  TempDir dir;
  const RunResult r = run_linkage({"lesson", file, "--out", (dir / "out").string(), "--step", "--only", only}, typed);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return count(r.out, "Right. ");
}

// The slider-crank and four-bar lessons: each exercise, answered with the value worked out
// here from the mechanism file's lengths and start and the lesson's settings, is marked
// right (the tool's answers come from its own solve: joint forces, closed-loop angles).
TEST(ShippedLessons, TheMechanismLessonsAcceptTheAnswersTheFormulasGive) {
  const Mechanism crank = load_mechanism("slider-crank");
  const double r = parameter(crank, "r"), l = parameter(crank, "l"), mp = parameter(crank, "mp");
  const double theta0 = initial(crank, "2.theta");
  const double omega = 10;  // the lesson's set step: g = 0, the crank at 10 rad/s from the outer dead point
  const std::vector<double> slider{2 * r, std::sqrt(l * l - r * r),
                                   r * std::cos(theta0) + std::sqrt(l * l - std::pow(r * std::sin(theta0), 2)),
                                   mp * r * omega * omega * (1 + r / l), (l + r) / (l - r)};
  EXPECT_EQ(right_answers((fs::path(LINKAGE_SOURCE_DIR) / "lessons/12-slider-crank.toml").string(), slider),
            static_cast<int>(slider.size()));

  const Mechanism four = load_mechanism("four-bar");
  const double a = parameter(four, "a"), b = parameter(four, "b"), c = parameter(four, "c"), d = parameter(four, "d");
  const double th2 = initial(four, "2.theta");
  const double deg = 180 / std::acos(-1.0);
  const double a_long = 0.4;  // the lesson's crank that breaks Grashof's condition
  const std::vector<double> grashof{
      (b + c) - (a + d), b + d - c, std::acos((b * b + c * c - (d - a) * (d - a)) / (2 * b * c)) * deg,
      std::acos((b * b + c * c - a * a - d * d + 2 * a * d * std::cos(th2)) / (2 * b * c)) * deg,
      std::acos((a_long * a_long + d * d - (b + c) * (b + c)) / (2 * a_long * d))};
  EXPECT_EQ(right_answers((fs::path(LINKAGE_SOURCE_DIR) / "lessons/13-four-bar.toml").string(), grashof),
            static_cast<int>(grashof.size()));
}

// Every exercise of the course takes its own printed answer: run the exercises alone, read
// each "Answer: VALUE" (the digits a student sees), then answer them with --step and count
// the rights. An answer that does not evaluate, or a tolerance tighter than the printed
// digits, fails here.
TEST(ShippedLessons, EveryExerciseAcceptsItsPrintedAnswer) {
  TempDir dir;
  const std::regex answer_line(R"(Answer: (-?[0-9]+(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?))");
  int total = 0;
  for (const fs::path& file : shipped_lessons()) {
    SCOPED_TRACE(file.filename().string());
    const lesson::Lesson parsed = lesson::parse_lesson(file);
    std::string only;
    int exercises = 0;
    for (const lesson::Step& step : parsed.steps)
      if (std::holds_alternative<lesson::ExerciseStep>(step.body)) {
        if (!only.empty()) only += ',';
        only += std::to_string(step.number);
        ++exercises;
      }
    if (exercises == 0) continue;
    const std::string out = (dir / parsed.name).string();
    const RunResult shown = run_linkage({"lesson", file.string(), "--out", out, "--only", only});
    ASSERT_EQ(shown.exit_code, 0) << shown.err;
    std::string answers;
    int found = 0;
    for (auto it = std::sregex_iterator(shown.out.begin(), shown.out.end(), answer_line); it != std::sregex_iterator();
         ++it, ++found)
      answers += (*it)[1].str() + "\n";
    ASSERT_EQ(found, exercises) << shown.out;
    const RunResult asked = run_linkage({"lesson", file.string(), "--out", out, "--only", only, "--step"}, answers);
    ASSERT_EQ(asked.exit_code, 0) << asked.err;
    EXPECT_EQ(count(asked.out, "Right. The answer is "), exercises) << asked.out;
    total += exercises;
  }
  EXPECT_GE(total, 30);
}

// Lesson 06 prints the spec's worked example: every derived value and every unknown of
// example.json (to the 6 digits the text shows), and its spot-the-mistake answers.
TEST(ShippedLessons, TheNumericalExamplePrintsTheSpecsValues) {
  TempDir dir;
  const std::string file = (fs::path(LINKAGE_SOURCE_DIR) / "lessons/06-numerical-example.toml").string();
  const RunResult r = run_linkage({"lesson", file, "--out", (dir / "out").string(), "--only", "1-11"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json& example = spec_example();
  int checked = 0;
  for (const char* group : {"derived", "solution"})
    for (const auto& [name, value] : example.at(group).items()) {
      EXPECT_NE(r.out.find(format_significant(number(value), 6)), std::string::npos) << name << "\n" << r.out;
      ++checked;
    }
  EXPECT_EQ(checked, 22);
  for (const auto& [group, name, unit] : {std::tuple{"derived", "I_zz_P", " kg m^2."},
                                          {"derived", "x_P", " m."},
                                          {"solution", "x2_ddot", " m/s^2."},
                                          {"solution", "F_x", " N."}}) {
    const std::string answer = "Answer: " + format_significant(number(example.at(group).at(name)), 6) + unit;
    EXPECT_NE(r.out.find(answer), std::string::npos) << answer << "\n" << r.out;
  }
  EXPECT_NE(r.out.find("The cases agree"), std::string::npos);
  EXPECT_NE(r.out.find("Case 3: four equations"), std::string::npos);
}

}  // namespace
}  // namespace linkage::test
