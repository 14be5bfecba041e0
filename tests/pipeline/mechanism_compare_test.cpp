// Trajectory files and other mechanisms compared over any clip (--compare FILE|MECHANISM):
// a trajectory file's poses are its rows interpolated linearly in t, a bad row names its
// file and line, and another mechanism's bodies are drawn where that mechanism puts them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "pipeline/trajectory_csv.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {
namespace fs = std::filesystem;

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

// What a page offers to download (motion_csv) is a trajectory file of the same motion: a
// point mass has no theta column, and the numbers read back exactly.
TEST(TrajectoryCsv, AMotionsTableReadsBackAsTheSameMotion) {
  test::TempDir dir;
  const sym::System system(load_mechanism(test::test_mechanism("slotted-bar-bead.toml")));
  const MechanismGeometry geometry = mechanism_geometry(system);
  SimulationOptions options;
  options.duration = 1;
  const std::vector<double> times{0.0, 0.4, 1.0};
  ClipResult result;
  const MechanismMotion motion =
      sample_mechanism_motion(system, sym::checked_initial_state(system).state, options, times, 1, result);
  const std::string csv = motion_csv(system, motion);
  EXPECT_EQ(test::lines_of(csv).at(0), "t,bar.x,bar.y,bar.theta,bead.x,bead.y");
  EXPECT_EQ(test::lines_of(csv).size(), 4U);
  test::write_text(dir / "motion.csv", csv);
  const TrajectoryTable table = read_trajectory_csv(dir / "motion.csv", mechanism_pose_columns(geometry), "test", 0, 1);
  const MechanismMotion read = table_motion(table, geometry, times);
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_EQ(read.samples[k].pose, motion.samples[k].pose) << k;
  EXPECT_NE(motion.samples[2].pose, motion.samples[0].pose);  // it moved
}

TEST(TrajectoryCsv, BadRowsNameTheFileAndLine) {
  test::TempDir dir;
  // The homework's columns: two-blocks' poses by its [aliases], as `linkage simulate` writes them.
  const sym::System system(load_mechanism("two-blocks"));
  const std::vector<std::string> needed = mechanism_pose_columns(mechanism_geometry(system), &system.mechanism());
  ASSERT_EQ(needed, (std::vector<std::string>{"t", "x1", "y1", "theta1", "x2", "y2", "theta2"}));
  const auto message = [&](const std::string& text, double end = 1.0) -> std::string {
    test::write_text(dir / "x.csv", text);
    try {
      (void)read_trajectory_csv(dir / "x.csv", needed, "drawing", 0.0, end);
    } catch (const Error& e) {
      return e.what();
    }
    return "(read)";
  };
  const std::string file = (dir / "x.csv").string();
  const std::string header = "t,x1,y1,theta1,x2,y2,theta2\n";
  EXPECT_NE(message("t,x1,y1,theta1,x2,y2\n0,1,2,3,4,5\n")
                .find(file + ": no column 'theta2'; drawing needs the columns t, x1"),
            std::string::npos);
  EXPECT_NE(message(header + "\n0,1,2,3,4,5,6\n1,1,2,x,4,5,6\n").find(file + ":4: theta1 = 'x' is not a number"),
            std::string::npos);
  EXPECT_EQ(message("t,x1,y1,theta1,x2,y2,theta2\r\n0,1,2,3,4,5,6\r\n1,1,2,3,4,5,6\r\n"), "(read)");  // CRLF is fine
  EXPECT_EQ(message("t, x1, y1, theta1, x2, y2, theta2\n0, +1, 2e0, 3, 4, 5, 6\n1, 1, 2, 3, 4, 5, 6\n"),
            "(read)");  // spaces, signs
  EXPECT_NE(message(header + "0,1,,3,4,5,6\n").find(file + ":2: y1 = '' is not a number"), std::string::npos);
  EXPECT_NE(message(header + "0,1,2,3,4,5,6\n1,1,2,3,4,5,6\n", 1.5).find(file + ":3: the last row"), std::string::npos);
  EXPECT_NE(message(header + "0,1,2,3,4,5,6\n1,inf,2,3,4,5,6\n").find(file + ":3: x1 is inf"), std::string::npos);
}

}  // namespace
}  // namespace linkage
