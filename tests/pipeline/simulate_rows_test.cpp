// The rows of `linkage simulate` (and of a lesson's trajectory): their times, values, names
// with --angles deg, and the refusal of a value that is not finite.
#include "pipeline/simulate_rows.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "core/error.hpp"
#include "pipeline/run_support.hpp"

namespace linkage {
namespace {

struct Table {
  std::vector<double> t;
  std::vector<std::vector<double>> rows;
};

/// The homework (two-blocks.toml from its default inputs) as `linkage simulate` runs it
/// without --mechanism: its columns under the homework's names, 0.3 s in rows 0.1 s apart.
Table homework_table(const std::string& list, AngleUnit angles, Eigen::VectorXd* end) {
  const linkage::Run run = test::homework_run("homework", 0.3);
  const std::vector<MechanismColumn> columns = named_columns(run.built->named_columns(), list, "test");
  MechanismSimulation sim(*run.built->system, run.built->initial, run.options);
  Table table;
  const Eigen::VectorXd last = mechanism_trajectory(sim, 3, TrajectoryRows(0.3, 0.1), columns, angles,
                                                    [&](double t, const std::vector<double>& values) {
                                                      table.t.push_back(t);
                                                      table.rows.push_back(values);
                                                    });
  if (end != nullptr) *end = last;
  return table;
}

TEST(SimulateRows, HomeworkRowsAtTheCommandsTimesAndInDegrees) {
  Eigen::VectorXd end;
  const Table rad = homework_table("t,x1,theta1,theta1_dot", AngleUnit::rad, &end);
  const Table deg = homework_table("t,x1,theta1,theta1_dot", AngleUnit::deg, nullptr);
  // 0.1 does not divide 0.3 in binary: still four rows, the last at the duration.
  EXPECT_EQ(rad.t, (std::vector<double>{0, 0.1, 0.2, 0.3}));
  ASSERT_EQ(rad.rows.size(), 4u);
  EXPECT_EQ(rad.rows[0], (std::vector<double>{0, 1, 0.1, 0.35}));  // the default start
  EXPECT_EQ(rad.rows[3][1], end[0]);                               // y = (x1, y1, theta1, theta2, rates..., W)
  EXPECT_EQ(rad.rows[3][2], end[2]);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(deg.rows[i][0], rad.rows[i][0]);
    EXPECT_EQ(deg.rows[i][1], rad.rows[i][1]);
    EXPECT_DOUBLE_EQ(deg.rows[i][2], rad.rows[i][2] * 180 / std::numbers::pi);
    EXPECT_DOUBLE_EQ(deg.rows[i][3], rad.rows[i][3] * 180 / std::numbers::pi);
  }
  const linkage::Run run = test::homework_run("homework", 0.3);
  const WrittenColumns written =
      written_columns(named_columns(run.built->named_columns(), "t,x1,theta1,theta1_dot", "test"), AngleUnit::deg);
  EXPECT_EQ(written.names, (std::vector<std::string>{"t", "x1", "theta1 (deg)", "theta1_dot (deg/s)"}));
  EXPECT_EQ(written.units, (std::vector<std::string>{"s", "m", "deg", "deg/s"}));
  EXPECT_EQ(joined_names(written.names), "t,x1,theta1 (deg),theta1_dot (deg/s)");
}

TEST(SimulateRows, AValueThatIsNotFiniteStopsTheRunNamingItsCause) {
  const linkage::Run run = test::homework_run("homework", 0.3);
  const std::vector<MechanismColumn> columns = named_columns(run.built->named_columns(), "t,energy", "test");
  MechanismSimulation sim(*run.built->system, run.built->initial, run.options);
  Eigen::VectorXd y = sim.state_at(0);
  y[4] = 1e300;  // x1_dot: the kinetic energy overflows
  eval::MechanismSample sample;
  std::vector<double> values;
  try {
    mechanism_row(sim, 3, 0, y, columns, sample, values);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::diverged);
    EXPECT_EQ(std::string(e.what()), "energy at t = 0 s is not a finite number; the run stopped (Case 3)");
  }
}

TEST(SimulateRows, MechanismRowsAndTheirLastState) {
  const linkage::Run run = test::mechanism_run("crank", "slider-crank", {}, 0.2);
  const std::vector<MechanismColumn> columns =
      select_mechanism_columns(mechanism_columns(*run.built->system), "t,2.theta,S.s", "test");
  MechanismSimulation sim(*run.built->system, run.built->initial, run.options);
  std::vector<std::vector<double>> rows;
  const Eigen::VectorXd end = mechanism_trajectory(sim, 3, TrajectoryRows(0.2, 0.1), columns, AngleUnit::deg,
                                                   [&](double, const std::vector<double>& v) { rows.push_back(v); });
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0][0], 0);
  EXPECT_EQ(rows[2][0], 0.2);
  EXPECT_NEAR(rows[0][1], 0.5 * 180 / std::numbers::pi, 1e-9);  // the shipped start, 2.theta = 0.5 rad
  EXPECT_NEAR(rows[2][1], end[0] * 180 / std::numbers::pi, 1e-9);
  EXPECT_EQ(written_columns(columns, AngleUnit::deg).names, (std::vector<std::string>{"t", "2.theta (deg)", "S.s"}));
}

TEST(SimulateRows, ValuesPrintRoundTrip) {
  EXPECT_EQ(joined_values({0.1, 1e-20, 2}, ","), "0.1,1e-20,2");
  EXPECT_EQ(joined_values({0.30000000000000004, -1}, ", "), "0.30000000000000004, -1");
  EXPECT_EQ(joined_values({}, ","), "");
}

}  // namespace
}  // namespace linkage
