// `linkage lesson` end to end: exercises checked from stdin, pauses, the cache (a second
// run makes nothing; a changed parameter re-makes only the steps after it), --only,
// the formats, bad lessons, and a document that links only files that exist.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>

#include "lesson/lesson.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

namespace fs = std::filesystem;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

const char* kExercise = R"(title = "Exercise"
[[step]]
kind = "exercise"
question = "What is the moment of inertia about the pin?"
answer = "I_zz_P"
relative_tolerance = 0.01
hint = "Parallel axes."
explanation = "I_P = I + m D^2."
)";

TEST(LessonExercise, WithoutStepPrintsTheAnswer) {
  TempDir dir;
  write_text(dir / "ex.toml", kExercise);
  const RunResult r = run_linkage({"lesson", (dir / "ex.toml").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Answer: 0.00204333 kg m^2. I_P = I + m D^2."), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("Your answer"), std::string::npos);
}

TEST(LessonExercise, WithStepChecksScriptedAnswers) {
  TempDir dir;
  write_text(dir / "ex.toml", kExercise);
  const std::vector<std::string> args{"lesson", (dir / "ex.toml").string(), "--out", (dir / "out").string(), "--step"};
  {  // wrong, not a number twice (not counted; a pasted minus sign named), then right within 1 %
    const RunResult r = run_linkage(args, "0.000204\nabc\n\u22121\n0.002045\n");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(count(r.out, "Your answer (kg m^2): "), 4) << r.out;
    EXPECT_NE(r.out.find("Not quite. Hint: Parallel axes. (2 tries left)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("'abc' is not a number; type one like"), std::string::npos);
    EXPECT_NE(r.out.find("'\u22121' is not a number; '\u2212' (U+2212): use '-'; type one like"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("Right. The answer is 0.00204333 kg m^2."), std::string::npos) << r.out;
  }
  {  // three wrong answers reveal it
    const RunResult r = run_linkage(args, "1\n2\n3\n");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("(1 try left)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Not quite. The answer is 0.00204333 kg m^2."), std::string::npos) << r.out;
  }
  {  // no input at all: the answer, and the lesson goes on
    const RunResult r = run_linkage(args, "");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("No answer given. The answer is 0.00204333 kg m^2."), std::string::npos) << r.out;
  }
  // The document always holds the answer, folded.
  const std::string doc = read_text(dir / "out" / "lesson.md");
  EXPECT_NE(doc.find("<details><summary>Answer</summary>\n\n0.00204333 kg m^2"), std::string::npos) << doc;
}

TEST(LessonPause, WaitsOnlyWithStep) {
  TempDir dir;
  write_text(dir / "p.toml", R"(title = "Pause"
[[step]]
kind = "say"
text = "before"
[[step]]
kind = "pause"
prompt = "Think about it"
[[step]]
kind = "say"
text = "after"
)");
  const std::string file = (dir / "p.toml").string(), out = (dir / "out").string();
  const RunResult stepped = run_linkage({"lesson", file, "--out", out, "--step"}, "\n");
  ASSERT_EQ(stepped.exit_code, 0) << stepped.err;
  EXPECT_LT(stepped.out.find("before"), stepped.out.find("[Think about it]"));
  EXPECT_LT(stepped.out.find("[Think about it]"), stepped.out.find("after"));
  const RunResult plain = run_linkage({"lesson", file, "--out", out});
  EXPECT_EQ(plain.out.find("Think about it"), std::string::npos);
}

// Two stills and a plot; the second still comes after a set step.
std::string cache_lesson(double m_after) {
  return R"(title = "Cache"
[[step]]
kind = "render"
out = "first.png"
at = 0.2
[[step]]
kind = "plot"
out = "energy"
y = "energy"
duration = 1
[[step]]
kind = "set"
m = )" + std::to_string(m_after) +
         R"(
[[step]]
kind = "render"
out = "second.png"
at = 0.2
)";
}

TEST(LessonCache, SecondRunMakesNothingAndAChangeRemakesOnlyWhatItAffects) {
  TempDir dir;
  const std::string file = (dir / "c.toml").string(), out = (dir / "out").string();
  write_text(file, cache_lesson(0.2));
  const RunResult first = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(count(first.err, "): made "), 3) << first.err;
  const auto first_time = fs::last_write_time(dir / "out" / "first.png");

  const RunResult second = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(count(second.err, "): made "), 0) << second.err;
  EXPECT_EQ(count(second.err, "): reused "), 3) << second.err;
  EXPECT_NE(second.err.find("step 1 (render): reused first.png (unchanged since the last run"), std::string::npos);
  EXPECT_EQ(fs::last_write_time(dir / "out" / "first.png"), first_time);
  EXPECT_EQ(first.out, second.out);  // the same lesson either way

  write_text(file, cache_lesson(0.3));  // the set step changes m for step 4 only
  const RunResult third = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(third.exit_code, 0) << third.err;
  EXPECT_NE(third.err.find("step 1 (render): reused"), std::string::npos) << third.err;
  EXPECT_NE(third.err.find("step 2 (plot): reused"), std::string::npos) << third.err;
  EXPECT_NE(third.err.find("step 4 (render): made second.png"), std::string::npos) << third.err;

  const RunResult draft_to_final = run_linkage({"lesson", file, "--out", out, "--quality", "final", "--only", "1"});
  ASSERT_EQ(draft_to_final.exit_code, 0) << draft_to_final.err;
  EXPECT_NE(draft_to_final.err.find("step 1 (render): made first.png"), std::string::npos) << draft_to_final.err;
  const RunResult final_plot = run_linkage({"lesson", file, "--out", out, "--quality", "final", "--only", "2"});
  ASSERT_EQ(final_plot.exit_code, 0) << final_plot.err;  // a plot does not depend on the quality
  EXPECT_NE(final_plot.err.find("step 2 (plot): reused energy.png"), std::string::npos) << final_plot.err;

  const RunResult forced = run_linkage({"lesson", file, "--out", out, "--force"});
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(count(forced.err, "): made "), 3) << forced.err;
}

// A render that fails leaves no cache record: the next run makes the file again, even
// with the options that made it before.
TEST(LessonCache, AFailedRenderNeverCountsAsCached) {
  TempDir dir;
  const std::string file = (dir / "f.toml").string(), out = (dir / "out").string();
  auto lesson = [](const std::string& at) {
    return "title = \"Fail\"\n[[step]]\nkind = \"render\"\nout = \"still.png\"\nat = " + at + "\n";
  };
  write_text(file, lesson("0.2"));
  const RunResult first = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const fs::path record = dir / "out" / ".still.png.cache.json";
  ASSERT_TRUE(fs::is_regular_file(record));

  // The still cannot be written (a folder stands in its way): the step fails.
  write_text(file, lesson("0.3"));
  fs::remove(dir / "out" / "still.png");
  fs::create_directory(dir / "out" / "still.png");
  const RunResult failed = run_linkage({"lesson", file, "--out", out});
  EXPECT_NE(failed.exit_code, 0);
  EXPECT_NE(failed.err.find(file + ":2:1: step 1 (render): "), std::string::npos) << failed.err;
  EXPECT_FALSE(fs::exists(record));

  fs::remove(dir / "out" / "still.png");
  write_text(file, lesson("0.2"));
  const RunResult again = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("step 1 (render): made still.png"), std::string::npos) << again.err;
}

// A record that cannot be read is a miss: one note names it, the step is made again
// and the record replaced, so the next run reuses it.
TEST(LessonCache, AnUnreadableRecordIsMadeAgainWithANote) {
  TempDir dir;
  const std::string file = (dir / "c.toml").string(), out = (dir / "out").string();
  write_text(file, "title = \"Cache\"\n[[step]]\nkind = \"simulate\"\nduration = 0.5\ntrajectory = \"run.csv\"\n");
  const RunResult first = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const fs::path record = dir / "out" / ".run.csv.cache.json";
  ASSERT_TRUE(fs::is_regular_file(record));
  const std::string good = read_text(record);
  const std::vector<std::pair<std::string, std::string>> broken{
      {R"({"hash": 5})", "no \"hash\" string"},
      {"", "it is empty"},
      {good.substr(0, good.size() / 2), "not JSON: a syntax error at byte " + std::to_string(good.size() / 2 + 1)},
      {"\x89PNG garbage", "not JSON: a syntax error at byte 1"},
  };
  for (const auto& [content, reason] : broken) {
    SCOPED_TRACE(reason);
    write_text(record, content);
    const RunResult r = run_linkage({"lesson", file, "--out", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("linkage: note: cache record '" + record.string() + "' is unreadable (" + reason +
                         "); making it again\nlesson: step 1 (simulate): made run.csv in "),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.out.find("final x of body 1's centre of mass (x1)  1.07716 m"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("final y of body 1's centre of mass (y1)  0.899239 m"), std::string::npos) << r.out;
    // The new record holds what this run printed (its run time included).
    const RunResult again = run_linkage({"lesson", file, "--out", out});
    EXPECT_NE(again.err.find("lesson: step 1 (simulate): reused run.csv"), std::string::npos) << again.err;
    EXPECT_EQ(again.err.find("note"), std::string::npos) << again.err;
    EXPECT_EQ(again.out, r.out);
  }

  // A folder with files in it where the record goes is left alone, and the step made
  // every time.
  fs::remove(record);
  fs::create_directory(record);
  write_text(record / "notes.txt", "mine");
  for (int run = 0; run < 2; ++run) {
    const RunResult r = run_linkage({"lesson", file, "--out", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("linkage: note: cache record '" + record.string() +
                         "' is a folder with files in it, not a file; left it as it is, so this step is not cached\n"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("step 1 (simulate): made run.csv"), std::string::npos) << r.err;
  }
  EXPECT_EQ(read_text(record / "notes.txt"), "mine");
}

// A simulate or compare step whose run means nothing says so in one status line, made
// or reused; sound runs say nothing.
TEST(LessonWarnings, MeaninglessRunsAreNamedMadeOrReused) {
  TempDir dir;
  const std::string file = (dir / "w.toml").string(), out = (dir / "out").string();
  write_text(file, R"(title = "Drift"
[[step]]
kind = "simulate"
case = 1
integrator = "euler"
dt = 0.05
theta1_dot = 20
theta2_dot = -35
[[step]]
kind = "compare"
out = "table"
case = 1
integrator = "euler"
dt = 0.05
theta1_dot = 20
theta2_dot = -35
duration = 10
columns = ["constraint_error"]
runs = [{ label = "drifting" }, { label = "sound", integrator = "dop853" }]
[[step]]
kind = "simulate"
)");
  for (int pass = 0; pass < 2; ++pass) {  // the compare step's table is reused the second time
    const RunResult r = run_linkage({"lesson", file, "--out", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(count(r.err, "warning: "), 2) << r.err;
    EXPECT_NE(r.err.find("lesson: step 1 (simulate): warning: the run's numbers do not describe the motion: "),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("lesson: step 2 (compare): warning: run 'drifting': the run's numbers"), std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("'sound'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("step 3 (simulate): warning"), std::string::npos) << r.err;
  }
}

TEST(LessonOnly, KeepsTheStateEarlierSetStepsMade) {
  TempDir dir;
  const std::string file = (dir / "o.toml").string();
  write_text(file, R"(title = "Only"
[[step]]
kind = "say"
text = "m is {{m}} kg at first"
[[step]]
kind = "set"
m = 0.25
[[step]]
kind = "say"
text = "now I is {{I_zz_C}} and m is {{m}} kg"
)");
  const RunResult r = run_linkage({"lesson", file, "--out", (dir / "out").string(), "--only", "3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("at first"), std::string::npos);
  EXPECT_NE(r.out.find("m is 0.25 kg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("I is 0.00208333"), std::string::npos) << r.out;  // 0.25 (0.01 + 0.09) / 12
  EXPECT_NE(r.err.find("ran 1 of 3 steps"), std::string::npos) << r.err;
  // Part of a lesson leaves the whole lesson's document alone (here: none yet).
  EXPECT_NE(r.err.find("lesson.md left as it was (--only ran part of the lesson)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "lesson.md"));
  const RunResult whole = run_linkage({"lesson", file, "--out", (dir / "out").string()});
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const std::string doc = read_text(dir / "out" / "lesson.md");
  EXPECT_NE(doc.find("m is 0.1 kg at first"), std::string::npos) << doc;
  const RunResult again = run_linkage({"lesson", file, "--out", (dir / "out").string(), "--only", "3"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(read_text(dir / "out" / "lesson.md"), doc);
  const RunResult all = run_linkage({"lesson", file, "--out", (dir / "out").string(), "--only", "1-"});
  EXPECT_NE(all.err.find("document "), std::string::npos) << all.err;

  const RunResult bad = run_linkage({"lesson", file, "--only", "4"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err, "linkage: error: --only: step 4 does not exist; the lesson has steps 1 to 3\n");
}

// A solve step prints only the parts it shows, in every format.
// A render step's page (.html) shows the worked equations of its run's case, as
// `linkage render --out clip.html` does.
TEST(LessonRender, APageShowsTheRunsCaseEquations) {
  TempDir dir;
  const std::string file = (dir / "p.toml").string(), out = (dir / "out").string();
  write_text(file, R"(title = "Page"
mechanism = "four-bar"
[[step]]
kind = "render"
out = "four-bar.html"
duration = 0.2
case = 2
)");
  const RunResult r = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = read_text(dir / "out" / "four-bar.html");
  const std::size_t panel = page.find("<details id=\"equations\" open>");
  ASSERT_NE(panel, std::string::npos);
  EXPECT_NE(page.find("<h2>Case 2: eleven equations in generalized coordinates with the joint forces</h2>", panel),
            std::string::npos);
  EXPECT_EQ(page.find("<h2>Case 3", panel), std::string::npos);
  EXPECT_GT(count(page.substr(panel), "<math display=\"block\">"), 10);
  EXPECT_EQ(page.find("<merror>"), std::string::npos);
}

TEST(LessonSolve, ShowsOnlyTheChosenParts) {
  TempDir dir;
  const std::string file = (dir / "s.toml").string(), out = (dir / "out").string();
  write_text(file, R"(title = "Parts"
[[step]]
kind = "solve"
case = [1, 3]
show = ["inertia", "solution"]
)");
  const RunResult r = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("I^P = I + m D² = 0.000833333 + 0.1 × 0.11² = 0.00204333 kg m²"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Case 1: eight DAEs"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Fy   0.000274704  N"), std::string::npos) << r.out;  // Case 1's solution
  EXPECT_NE(r.out.find("θ̈₂  -0.0105512"), std::string::npos) << r.out;
  for (const char* hidden : {"Inputs and definitions", "Joint P:", "E = T + V", "Equations, one per row",
                             "Symbolic A | B", "Numeric A | B", "Residual", "The cases agree"})
    EXPECT_EQ(r.out.find(hidden), std::string::npos) << hidden << "\n" << r.out;

  const RunResult md = run_linkage({"lesson", file, "--out", out, "--format", "markdown"});
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_NE(md.out.find("| $F_y$ | 0.000274704 | N |"), std::string::npos) << md.out;
  EXPECT_EQ(md.out.find("Numerically"), std::string::npos) << md.out;
  EXPECT_EQ(md.out.find("\\begin{bmatrix}"), std::string::npos) << md.out;
  const RunResult tex = run_linkage({"lesson", file, "--out", out, "--format", "latex"});
  ASSERT_EQ(tex.exit_code, 0) << tex.err;
  EXPECT_NE(tex.out.find("Solution:"), std::string::npos) << tex.out;
  EXPECT_EQ(tex.out.find("Numerically"), std::string::npos) << tex.out;
  EXPECT_EQ(tex.out.find("\\kappa"), std::string::npos) << tex.out;
}

TEST(LessonFormats, MarkdownAndLatex) {
  TempDir dir;
  const std::string file = (dir / "f.toml").string(), out = (dir / "out").string();
  write_text(file, R"(title = "Formats"
[[step]]
kind = "say"
heading = "Inertia"
text = "The **centroidal** inertia is θ₁-independent: {{I_zz_C}} kg m²."
[[step]]
kind = "solve"
case = 3
)");
  const RunResult md = run_linkage({"lesson", file, "--out", out, "--format", "markdown"});
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_EQ(md.out.rfind("# Formats\n", 0), 0u);
  EXPECT_NE(md.out.find("## Inertia"), std::string::npos);
  EXPECT_NE(md.out.find("$$"), std::string::npos);
  EXPECT_EQ(md.out, read_text(dir / "out" / "lesson.md"));  // the terminal shows the document
  const RunResult tex = run_linkage({"lesson", file, "--out", out, "--format", "latex"});
  ASSERT_EQ(tex.exit_code, 0) << tex.err;
  EXPECT_NE(tex.out.find("\\section*{Formats}"), std::string::npos);
  EXPECT_NE(tex.out.find("The \\textbf{centroidal} inertia is $\\theta_{1}$-independent: 0.000833333 kg $m^{2}$."),
            std::string::npos)
      << tex.out;
  EXPECT_NE(tex.out.find("\\begin{bmatrix}"), std::string::npos);
  const RunResult bad = run_linkage({"lesson", file, "--format", "html"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err, "linkage: error: --format: 'html' is not a format; valid: text, markdown, latex\n");
}

TEST(LessonErrors, ABrokenLessonMakesNothing) {
  TempDir dir;
  const fs::path broken = fs::path(LINKAGE_SOURCE_DIR) / "tests/data/lessons/unknown-key.toml";
  const fs::path out = dir / "out";
  const RunResult r = run_linkage({"lesson", broken.string(), "--out", out.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err,
            "linkage: error: " + broken.string() +
                ":11:1: step 2 (render): unknown key 'fsp' (did you mean 'fps'?); valid keys: kind, heading, "
                "mechanism, out, caption, quality, size, fps, speed, at, camera, view, show, hide, theme, title, "
                "arrow_scale, panel, angles, trail, trail_length, points, ensemble, spread, compare, mode, amplitude, "
                "nonlinear, modes_sheet, captions, set, case, "
                "integrator, dt, "
                "rtol, atol, duration, stabilize, baumgarte_alpha, baumgarte_beta, evaluator, L, w, b, m, g, x1, y1, "
                "theta1, theta2, x1_dot, y1_dot, theta1_dot, theta2_dot\n");
  EXPECT_FALSE(fs::exists(out));

  const RunResult missing = run_linkage({"lesson", (dir / "nope.toml").string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err, "linkage: error: lesson: file '" + (dir / "nope.toml").string() + "' does not exist\n");
}

/// Every file lesson.md links or embeds, relative to its folder.
std::set<std::string> document_links(const std::string& doc) {
  std::set<std::string> links;
  const std::regex pattern(R"(\]\(([^)\s]+)\)|src="([^"]+)\")");
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), pattern); it != std::sregex_iterator(); ++it)
    links.insert((*it)[1].matched ? (*it)[1].str() : (*it)[2].str());
  return links;
}

TEST(LessonDocument, TheTrajectoryIsTheCommandsByteForByte) {
  // The homework's run is two-blocks.toml's: its rows are `simulate --mechanism
  // two-blocks`'s to the bit, under the homework's names. 0.1 s does not divide 0.3 s in
  // binary: the rows still end once, at the duration.
  TempDir dir;
  const std::string file = (dir / "t.toml").string(), out = (dir / "out").string();
  write_text(file, R"(title = "Trajectory"
[[step]]
kind = "simulate"
duration = 0.3
every = 0.1
integrator = "rk4"
dt = 0.01
columns = ["t", "x1", "theta2_dot", "F_y", "energy"]
trajectory = "motion.csv"
)");
  const RunResult r = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const RunResult cli =
      run_linkage({"simulate", "--mechanism", "two-blocks", "--duration", "0.3", "--every", "0.1", "--integrator",
                   "rk4", "--dt", "0.01", "--columns", "t,1.x,2.theta_dot,P.force_y,energy", "--quiet"});
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  const std::string header = "t,1.x,2.theta_dot,P.force_y,energy\n";
  ASSERT_EQ(cli.out.substr(0, header.size()), header);
  EXPECT_EQ(read_text(dir / "out" / "motion.csv"), "t,x1,theta2_dot,F_y,energy\n" + cli.out.substr(header.size()));
  EXPECT_EQ(std::count(cli.out.begin(), cli.out.end(), '\n'), 5);  // the header and t = 0, 0.1, 0.2, 0.3
}

TEST(LessonDocument, LinksOnlyFilesThatExist) {
  TempDir dir;
  const std::string file = (dir / "d.toml").string(), out = (dir / "out").string();
  write_text(file, R"(title = "Document"
[[step]]
kind = "render"
out = "still.png"
at = 0.1
caption = "The example at t = 0.1 s."
[[step]]
kind = "simulate"
duration = 1
trajectory = "motion.csv"
[[step]]
kind = "compare"
out = "cases"
duration = 1
runs = [{ case = 1, stabilize = "projection" }, { case = 2 }, { case = 3 }]
plot = "energy_error"
)");
  const RunResult r = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string doc = read_text(dir / "out" / "lesson.md");
  const std::set<std::string> links = document_links(doc);
  EXPECT_EQ(links, (std::set<std::string>{"still.png", "motion.csv", "cases.png", "cases.csv"})) << doc;
  for (const std::string& link : links) EXPECT_TRUE(fs::is_regular_file(dir / "out" / link)) << link;
  for (const std::string& artifact : lesson::parse_lesson(file).artifacts())
    EXPECT_GT(fs::file_size(dir / "out" / artifact), 0u) << artifact;

  // A file removed behind the lesson's back is made again, never linked while missing.
  fs::remove(dir / "out" / "cases.png");
  const RunResult again = run_linkage({"lesson", file, "--out", out});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("step 3 (compare): made cases.csv"), std::string::npos) << again.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "cases.png"));
}

}  // namespace
}  // namespace linkage::test
