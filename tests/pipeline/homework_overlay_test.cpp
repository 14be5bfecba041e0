// Other runs over the homework's clip and trajectory files over any clip (--ensemble,
// --compare SETTINGS|FILE): where the ensemble starts, that a trajectory file's poses are
// its rows interpolated linearly in t, that another mechanism's bodies are drawn where
// that mechanism puts them, and that the pictures are the same every time.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.hpp"
#include "model/kinematics.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/clip.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "pipeline/trajectory_csv.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {
namespace fs = std::filesystem;

std::string bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(HomeworkOverlay, EnsembleStartsExactlySpreadKOverNMinusOneApartInTheta1) {
  const State s;
  const std::vector<State> states = homework_ensemble_states(s, 20, 1e-6);
  ASSERT_EQ(states.size(), 19U);
  for (std::size_t k = 0; k < states.size(); ++k) {
    EXPECT_EQ(states[k].theta1, s.theta1 + 1e-6 * static_cast<double>(k + 1) / 19.0);
    EXPECT_EQ(states[k].theta2, s.theta2);
    EXPECT_EQ(states[k].x1, s.x1);
    EXPECT_EQ(states[k].theta1_dot, s.theta1_dot);
  }
  EXPECT_EQ(states.back().theta1, s.theta1 + 1e-6);
}

TEST(HomeworkOverlay, EnsembleRunsAreSimulatedFromThoseStates) {
  Clip clip;
  clip.ensemble = 5;
  clip.spread = 0.2;
  SimulationOptions options;
  options.duration = 1;
  const std::vector<double> times{0.0, 0.5, 1.0};
  ClipResult result;
  const std::vector<OverlayRun> runs = homework_overlays(clip, options, times, result);
  ASSERT_EQ(runs.size(), 4U);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    EXPECT_FALSE(runs[k].compare);
    EXPECT_DOUBLE_EQ(runs[k].ramp, static_cast<double>(k) / 3.0);
    ASSERT_EQ(runs[k].states.size(), times.size());
    EXPECT_DOUBLE_EQ(runs[k].states[0].theta1, clip.inputs.state().theta1 + 0.2 * static_cast<double>(k + 1) / 4);
    Simulation simulation(clip.inputs.params(), homework_ensemble_states(clip.inputs.state(), 5, 0.2)[k], options);
    const BodyState end = simulation.state_at(1.0);
    EXPECT_EQ(runs[k].states[2].theta2, end.theta2);
    EXPECT_EQ(runs[k].states[2].y1, end.y1);
  }
  EXPECT_EQ(result.stats.samples, 4 * 3);
}

TEST(HomeworkOverlay, ComparedSettingsAreTheHomeworksInputNames) {
  const Inputs inputs;
  const SimulationOptions options;
  const HomeworkRun run =
      homework_compared_run({"theta1=0.1000001", "L=0.4", "integrator=rk4", "case=1"}, inputs, options, "--compare");
  EXPECT_EQ(run.inputs.state().theta1, 0.1000001);
  EXPECT_EQ(run.inputs.params().L, 0.4);
  EXPECT_EQ(run.simulation.integrator, IntegratorKind::rk4);
  EXPECT_EQ(run.simulation.case_id, 1);
  EXPECT_EQ(run.label, "theta1=0.1000001, L=0.4, integrator=rk4, case=1");
  EXPECT_EQ(homework_compared_run({"theta1-dot=2"}, inputs, options, "x").inputs.state().theta1_dot, 2.0);
  EXPECT_THROW((void)homework_compared_run({"thta1=2"}, inputs, options, "--compare"), Error);
  EXPECT_THROW((void)homework_compared_run({"L=-1"}, inputs, options, "--compare"), Error);
  EXPECT_THROW((void)homework_compared_run({"case=4"}, inputs, options, "--compare"), Error);
}

// A student's integrator, as its CSV: rows at 0.1 s; frames fall between them.
fs::path write_homework_csv(const test::TempDir& dir, bool with_x2) {
  std::ofstream out(dir / "mine.csv");
  out << "# t,x1,y1,theta1 (deg),theta2" << (with_x2 ? ",x2,y2" : "") << "\n";
  for (int i = 0; i <= 20; ++i) {
    const double t = 0.1 * i;
    out << t << "," << 1 + 0.1 * t << "," << 2 - 4.9 * t * t << "," << 10 * t << "," << 0.2 + t;
    if (with_x2) out << "," << 1.2 + t << "," << 2.1 - 4.9 * t * t;
    out << "\n";
  }
  return dir / "mine.csv";
}

TEST(HomeworkOverlay, ATrajectoryFilesPosesAreItsRowsInterpolatedLinearly) {
  test::TempDir dir;
  for (const bool with_x2 : {false, true}) {
    SCOPED_TRACE(with_x2);
    const TrajectoryTable table =
        read_trajectory_csv(write_homework_csv(dir, with_x2), homework_pose_columns(), "test", 0.0, 2.0);
    Clip clip;
    clip.compare =
        HomeworkRun{clip.inputs, clip.simulation, "mine.csv", std::make_shared<const TrajectoryTable>(table)};
    const std::vector<double> times{0.0, 1.0 / 30, 0.25, 1.0, 1.95, 2.0};
    ClipResult result;
    const std::vector<OverlayRun> runs = homework_overlays(clip, clip.simulation, times, result);
    ASSERT_EQ(runs.size(), 1U);
    EXPECT_TRUE(runs[0].compare);
    const double pi = std::acos(-1.0);
    for (std::size_t k = 0; k < times.size(); ++k) {
      const double t = times[k];
      const BodyState& s = runs[0].states[k];
      // Between rows i and i + 1: the straight line between them.
      const double before = std::floor(t / 0.1 + 1e-9) * 0.1, after = std::min(before + 0.1, 2.0);
      const double f = after > before ? (t - before) / (after - before) : 0.0;
      const auto lerp = [&](double a, double b) { return a + f * (b - a); };
      EXPECT_NEAR(s.x1, 1 + 0.1 * t, 1e-12);
      EXPECT_NEAR(s.y1, lerp(2 - 4.9 * before * before, 2 - 4.9 * after * after), 1e-12);
      EXPECT_NEAR(s.theta1, 10 * t * pi / 180, 1e-12);  // written in degrees
      EXPECT_NEAR(s.theta2, 0.2 + t, 1e-12);
      if (with_x2) {
        EXPECT_NEAR(s.x2, 1.2 + t, 1e-12);
        EXPECT_NEAR(s.y2, lerp(2.1 - 4.9 * before * before, 2.1 - 4.9 * after * after), 1e-12);
      } else {  // from the pin
        State q;
        q.x1 = s.x1;
        q.y1 = s.y1;
        q.theta1 = s.theta1;
        q.theta2 = s.theta2;
        const BodyState pinned = body_state(clip.inputs.params(), q);
        EXPECT_NEAR(s.x2, pinned.x2, 1e-12);
        EXPECT_NEAR(s.y2, pinned.y2, 1e-12);
      }
    }
    EXPECT_EQ(result.stats.samples, 0);  // nothing simulated
  }
}

// simulate --mechanism two-blocks writes the same run in the mechanism's names.
TEST(HomeworkOverlay, TheTwoBlocksMechanismsColumnsAreTheHomeworks) {
  test::TempDir dir;
  test::write_text(dir / "tb.csv", "t,1.x,1.y,1.theta,2.x,2.y,2.theta\n0,1,2,0.1,1.2,2.1,0.2\n1,3,4,0.5,3.2,4.1,0.6\n");
  const TrajectoryTable table = read_homework_trajectory(dir / "tb.csv", "--compare", 1.0);
  EXPECT_EQ(table.names, (std::vector<std::string>{"t", "x1", "y1", "theta1", "x2", "y2", "theta2"}));
  EXPECT_DOUBLE_EQ(table.at(*table.find("theta2"), 0.5), 0.4);
  test::write_text(dir / "half.csv", "t,1.x,1.y,1.theta\n0,1,2,0.1\n1,3,4,0.5\n");
  try {
    (void)read_homework_trajectory(dir / "half.csv", "--compare", 1.0);
    ADD_FAILURE() << "read a file without 2.theta";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no column '2.theta'; --compare, to draw the homework's two blocks from "
                                         "two-blocks' columns, needs the columns t, 1.x, 1.y, 1.theta, 2.theta"),
              std::string::npos)
        << e.what();
  }
}

TEST(HomeworkOverlay, FramesWithOverlaysAreTheSameEveryTime) {
  test::TempDir dir;
  Clip clip;
  clip.settings.width = 320;
  clip.settings.height = 180;
  clip.settings.at = 3;
  clip.theme = load_theme("light", {}, "theme");
  clip.out = dir / "plain.png";
  (void)produce_clip(clip);
  clip.ensemble = 8;
  clip.spread = 0.3;
  clip.compare = homework_compared_run({"theta2=0.6", "integrator=rk4"}, clip.inputs, clip.simulation, "test");
  clip.out = dir / "a.png";
  (void)produce_clip(clip);
  clip.out = dir / "b.png";
  (void)produce_clip(clip);
  EXPECT_EQ(bytes(dir / "a.png"), bytes(dir / "b.png"));
  EXPECT_NE(bytes(dir / "a.png"), bytes(dir / "plain.png"));
  // The free-body view refuses them.
  clip.settings.free_body = true;
  EXPECT_THROW(clip.validate(), Error);
}

TEST(MechanismCompare, ATrajectoryFilesPosesAreItsRowsInterpolatedLinearly) {
  test::TempDir dir;
  const sym::System system(load_mechanism("double-pendulum"));
  const MechanismGeometry geometry = mechanism_geometry(system);
  const std::vector<std::string> needed = mechanism_pose_columns(geometry);
  EXPECT_EQ(needed, (std::vector<std::string>{"t", "1.x", "1.y", "1.theta", "2.x", "2.y", "2.theta"}));
  {
    std::ofstream out(dir / "dp.csv");
    out << "t,1.x,1.y,1.theta,2.x,2.y,2.theta,energy\n0,0,0,0,1,1,1,5\n1,1,2,3,4,5,6,5\n2,0,0,0,0,0,0,5\n";
  }
  const TrajectoryTable table = read_trajectory_csv(dir / "dp.csv", needed, "test", 0.0, 2.0);
  const MechanismMotion motion = table_motion(table, geometry, {0.0, 0.25, 1.0, 1.5});
  EXPECT_EQ(motion.samples[0].pose, (std::vector<double>{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(motion.samples[1].pose, (std::vector<double>{0.25, 0.5, 0.75, 1.75, 2, 2.25}));
  EXPECT_EQ(motion.samples[2].pose, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(motion.samples[3].pose, (std::vector<double>{0.5, 1, 1.5, 2, 2.5, 3}));
  // As overlay_motions gives it, without simulating.
  MechanismClip clip;
  MechanismRun run;
  run.table = std::make_shared<const TrajectoryTable>(table);
  clip.compare = run;
  ClipResult result;
  const auto motions =
      overlay_motions(system, sym::checked_initial_state(system).state, clip, clip.simulation, {0.25, 1.5}, result);
  ASSERT_EQ(motions.size(), 1U);
  EXPECT_EQ(motions[0].samples[0].pose, motion.samples[1].pose);
  EXPECT_EQ(motions[0].samples[1].pose, motion.samples[3].pose);
  EXPECT_EQ(result.stats.samples, 0);
}

TEST(MechanismCompare, AnotherMechanismsBodiesAreWhereThatMechanismPutsThem) {
  const sym::System main(load_mechanism("two-blocks"));
  const sym::System other(load_mechanism("unequal-blocks"));
  const GiNaC::exmap other_initial = sym::checked_initial_state(other).state;
  MechanismClip clip;
  SimulationOptions options;
  options.duration = 2;
  clip.compare = MechanismRun{&other, other_initial, options, "unequal-blocks"};
  const std::vector<double> times{0.0, 1.0, 2.0};
  ClipResult result, alone;
  const auto motions = overlay_motions(main, sym::checked_initial_state(main).state, clip, options, times, result);
  const MechanismMotion expected = sample_mechanism_motion(other, other_initial, options, times, 1, alone);
  ASSERT_EQ(motions.size(), 1U);
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_EQ(motions[0].samples[k].pose, expected.samples[k].pose);
  // Not the main run's: its own parameters and start.
  const MechanismMotion own =
      sample_mechanism_motion(main, sym::checked_initial_state(main).state, options, times, 1, alone);
  EXPECT_NE(motions[0].samples[2].pose, own.samples[2].pose);
}

TEST(TrajectoryCsv, BadRowsNameTheFileAndLine) {
  test::TempDir dir;
  const auto message = [&](const std::string& text, double end = 1.0) -> std::string {
    test::write_text(dir / "x.csv", text);
    try {
      (void)read_trajectory_csv(dir / "x.csv", homework_pose_columns(), "drawing", 0.0, end);
    } catch (const Error& e) {
      return e.what();
    }
    return "(read)";
  };
  const std::string file = (dir / "x.csv").string();
  EXPECT_NE(message("t,x1,y1,theta1\n0,1,2,3\n").find(file + ": no column 'theta2'; drawing needs the columns t, x1"),
            std::string::npos);
  EXPECT_NE(message("t,x1,y1,theta1,theta2\n\n0,1,2,3,4\n1,1,2,x,4\n").find(file + ":4: theta1 = 'x' is not a number"),
            std::string::npos);
  EXPECT_EQ(message("t,x1,y1,theta1,theta2\r\n0,1,2,3,4\r\n1,1,2,3,4\r\n"), "(read)");           // CRLF is fine
  EXPECT_EQ(message("t, x1, y1, theta1, theta2\n0, +1, 2e0, 3, 4\n1, 1, 2, 3, 4\n"), "(read)");  // spaces, signs
  EXPECT_NE(message("t,x1,y1,theta1,theta2\n0,1,,3,4\n").find(file + ":2: y1 = '' is not a number"), std::string::npos);
  EXPECT_NE(message("t,x1,y1,theta1,theta2\n0,1,2,3,4\n1,1,2,3,4\n", 1.5).find(file + ":3: the last row"),
            std::string::npos);
  EXPECT_NE(message("t,x1,y1,theta1,theta2\n0,1,2,3,4\n1,inf,2,3,4\n").find(file + ":3: x1 is inf"), std::string::npos);
}

}  // namespace
}  // namespace linkage
