// A lesson on a mechanism: every step kind works on it through the commands' general
// machinery (simulate, plot; the trajectory is the command's, byte for byte).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/test_support.hpp"

namespace linkage::test {
namespace {

namespace fs = std::filesystem;

const fs::path kLesson = fs::path(LINKAGE_SOURCE_DIR) / "tests/data/mechanism-lessons/slider-crank-steps.toml";

/// The CSV's rows as numbers, and its header.
std::vector<std::vector<double>> csv_rows(const std::string& text, std::vector<std::string>& header) {
  std::istringstream in(text);
  std::string line, field;
  header.clear();
  std::getline(in, line);
  std::istringstream names(line);
  while (std::getline(names, field, ',')) header.push_back(field);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    rows.emplace_back();
    while (std::getline(fields, field, ',')) rows.back().push_back(std::stod(field));
  }
  return rows;
}

std::size_t index_of(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

class MechanismLesson : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    result_ = new RunResult(run_linkage({"lesson", kLesson.string(), "--out", (out() / "").string()}));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete dir_;
  }
  static fs::path out() { return *dir_ / "out"; }
  static TempDir* dir_;
  static RunResult* result_;
};
TempDir* MechanismLesson::dir_ = nullptr;
RunResult* MechanismLesson::result_ = nullptr;

TEST_F(MechanismLesson, RunsAtDraftQuality) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  EXPECT_NE(result_->out.find("A crank of 0.05 m and a rod of 0.2 m."), std::string::npos) << result_->out;
}

TEST_F(MechanismLesson, SimulateWritesTheCommandsTrajectory) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  // "default" expands to the command's default columns.
  const RunResult cli =
      run_linkage({"simulate", "--mechanism", "slider-crank", "--duration", "0.5", "--every", "0.05", "--columns",
                   "t,2.x,2.y,2.theta,3.x,3.y,3.theta,4.x,4.y,4.theta,S.s,B.force_x,energy_error", "--quiet"});
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  EXPECT_EQ(read_text(out() / "crank.csv"), cli.out);
  // After the set step: its settings, and the step's, as --set.
  const RunResult set =
      run_linkage({"simulate", "--mechanism", "slider-crank", "--set", "2.theta=0.3", "--set", "a=0.08", "--duration",
                   "0.2", "--every", "0.1", "--columns", "2.theta,S.s", "--quiet"});
  ASSERT_EQ(set.exit_code, 0) << set.err;
  EXPECT_EQ(read_text(out() / "crank-0.3.csv"), set.out);
}

TEST_F(MechanismLesson, ThePistonStartsWhereTheLoopCloses) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  std::vector<std::string> header;
  const auto rows = csv_rows(read_text(out() / "crank.csv"), header);
  ASSERT_EQ(rows.size(), 11U);  // 0, 0.05, ..., 0.5
  const double r = 0.05, l = 0.2;
  const double th2 = rows[0][index_of(header, "2.theta")];
  EXPECT_DOUBLE_EQ(th2, 0.5);
  const double piston = r * std::cos(th2) + std::sqrt(l * l - std::pow(r * std::sin(th2), 2));
  EXPECT_NEAR(rows[0][index_of(header, "S.s")], piston, 1e-12 * piston);
  // The summary names the final coordinates in words and units.
  EXPECT_NE(result_->out.find("final position along slider S (S.s)"), std::string::npos) << result_->out;
  EXPECT_NE(result_->out.find("largest energy-balance error"), std::string::npos);
  // The set step's crank angle is where the second run starts.
  const auto set_rows = csv_rows(read_text(out() / "crank-0.3.csv"), header);
  ASSERT_EQ(set_rows.size(), 3U);
  EXPECT_DOUBLE_EQ(set_rows[0][1], 0.3);
  EXPECT_NE(result_->out.find("From here on: a = 0.08 m (was 0.06), 2.theta = 0.3 rad (was 0.5)."), std::string::npos)
      << result_->out;
}

TEST_F(MechanismLesson, PlotsToPngAndSvg) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  EXPECT_GT(fs::file_size(out() / "piston.png"), 1000U);
  EXPECT_GT(fs::file_size(out() / "piston.svg"), 1000U);
  EXPECT_NE(read_text(out() / "lesson.md").find("piston.png"), std::string::npos);
}

TEST(MechanismLessonErrors, AnUnknownColumnNamesTheNearestAndTheValidOnes) {
  TempDir dir;
  write_text(dir / "bad.toml", R"(title = "Bad"
mechanism = "slider-crank"
[[step]]
kind = "plot"
out = "p"
y = ["2.theta", "S.x"]
)");
  const RunResult r = run_linkage({"lesson", (dir / "bad.toml").string(), "--out", (dir / "out").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.toml:6:17: step 1 (plot): y: unknown column 'S.x'; nearest 'S.s'; valid: t, S.s, S.s_ddot, "
                       "S.force_x, S.force_y, S.moment, S.constraint_error, S.constraint_velocity_error, "
                       "constraint_position_error, constraint_velocity_error, energy, work, energy_error, "
                       "energy_error_relative, shaking_force_x, shaking_force_y, shaking_moment and 79 more (the "
                       "columns of every body, point and joint; 'all' "
                       "selects every one)\n"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(MechanismLessonErrors, HomeworkInputsAndSettingsAreRefusedWhereTheyDoNotApply) {
  TempDir dir;
  write_text(dir / "a.toml", R"(title = "Bad"
mechanism = "slider-crank"
[[step]]
kind = "simulate"
L = 0.3
)");
  RunResult r = run_linkage({"lesson", (dir / "a.toml").string(), "--check"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a.toml:5:5: step 1 (simulate): 'L' is an input of the homework"), std::string::npos) << r.err;
  write_text(dir / "b.toml", R"(title = "Bad"
[[step]]
kind = "simulate"
set = ["a=0.1"]
)");
  r = run_linkage({"lesson", (dir / "b.toml").string(), "--check"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'set' applies to a mechanism"), std::string::npos) << r.err;
  write_text(dir / "c.toml", R"(title = "Bad"
mechanism = "slider-crank"
[[step]]
kind = "simulate"
set = ["q=0.1"]
)");
  r = run_linkage({"lesson", (dir / "c.toml").string(), "--check"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("c.toml:5:7: step 1 (simulate):"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'q'"), std::string::npos) << r.err;
}

/// The number printed after `lead` (an exercise's "Answer: ", a sentence's words).
double number_after(const std::string& text, const std::string& lead) {
  const std::size_t at = text.find(lead);
  EXPECT_NE(at, std::string::npos) << lead << " in " << text;
  return at == std::string::npos ? std::nan("") : std::stod(text.substr(at + lead.size()));
}

TEST_F(MechanismLesson, AnswersAndValuesAreSolvesNumbersAtTheStepsSettings) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  const RunResult solve = run_linkage({"solve", "--mechanism", "slider-crank", "--set", "2.theta=0.3", "--set",
                                       "a=0.08", "--case", "3", "--format", "json"});
  ASSERT_EQ(solve.exit_code, 0) << solve.err;
  const nlohmann::json json = nlohmann::json::parse(solve.out);
  const double alpha = json["cases"][0]["solution"]["2.theta_ddot"].get<double>();
  EXPECT_NEAR(number_after(result_->out, "Exercise. What is the crank's angular acceleration at the start?\nAnswer: "),
              alpha, 1e-12 * std::fabs(alpha));
  EXPECT_NE(result_->out.find(" rad/s^2\n"), std::string::npos);  // the unit from the name
  EXPECT_DOUBLE_EQ(number_after(result_->out, "the crank turns at "), json["state"]["2.theta_dot"].get<double>());
  const double force = json["cases"][0]["solution"]["B.force_x"].get<double>();
  EXPECT_NEAR(number_after(result_->out, "pushes the piston with "), force, 1e-3 * std::fabs(force));  // 4 digits
  // A step's own mechanism starts from its file's values.
  EXPECT_DOUBLE_EQ(number_after(result_->out, "And the four-bar's first coordinate?\nAnswer: "), 1.0);
}

TEST_F(MechanismLesson, SolvePrintsTheCommandsWorkedSolution) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  const RunResult solve = run_linkage(
      {"solve", "--mechanism", "slider-crank", "--set", "2.theta=0.3", "--set", "a=0.08", "--case", "3", "--unicode"});
  ASSERT_EQ(solve.exit_code, 0) << solve.err;
  // The solution table, line for line as the command prints it.
  const std::size_t begin = solve.out.find("  Solution:\n");
  ASSERT_NE(begin, std::string::npos) << solve.out;
  const std::string table = solve.out.substr(begin, solve.out.find("\n\n", begin) - begin);
  EXPECT_NE(result_->out.find(table), std::string::npos) << table << "\n" << result_->out;
  EXPECT_NE(result_->out.find("Case 3: five equations in generalized coordinates"), std::string::npos);
  EXPECT_EQ(result_->out.find("Numeric A | B"), std::string::npos);  // show = ["solution"]
  // lesson.md has the Markdown form.
  EXPECT_NE(read_text(out() / "lesson.md").find("| $\\ddot{\\theta}_2$ | -228.064 | rad/s² |"), std::string::npos)
      << read_text(out() / "lesson.md");
}

TEST_F(MechanismLesson, CompareMeasuresEveryRunAgainstTheReference) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  std::vector<std::string> header;
  std::istringstream csv(read_text(out() / "methods.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "run,final_error,energy_error,constraint_error,steps,rejected,rhs_evaluations,run_time");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) {
    std::istringstream fields(line);
    rows.emplace_back();
    for (std::string field; std::getline(fields, field, ',');) rows.back().push_back(field);
  }
  ASSERT_EQ(rows.size(), 4U);
  // RK4 is fourth order: half the step, about a sixteenth of the error (at least an eighth).
  const double coarse = std::stod(rows[0][1]), fine = std::stod(rows[1][1]);
  EXPECT_GT(coarse, 8 * fine);
  EXPECT_LT(fine, 1e-4);
  EXPECT_EQ(rows[0][4], "50");   // 0.5 s at 0.01 s
  EXPECT_EQ(rows[0][6], "200");  // four right-hand sides a step
  EXPECT_EQ(rows[3][4], "500");
  // Projection keeps Case 1 on its constraints; the energy balance drifts with Euler.
  EXPECT_LT(std::stod(rows[3][3]), 1e-12);
  EXPECT_GT(std::stod(rows[3][2]), 1e-3);
  for (const char* file :
       {"methods.png", "methods.svg", "methods-cost.png", "methods-cost.svg", "crank-still.png"})  // and the render
    EXPECT_GT(fs::file_size(out() / file), 1000U) << file;
}

}  // namespace
}  // namespace linkage::test
