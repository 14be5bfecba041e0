// Columns defined as NAME=EXPRESSION (columns/expression_column.hpp) on the shipped
// four-bar: their values against the columns they name, sample by sample, their units,
// a definition using one before it, and the errors of a bad name or expression.
#include "columns/expression_column.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "integrate/mechanism_simulation.hpp"
#include "model/mechanism_toml.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

using test::input_error_of;

class ExpressionColumns : public ::testing::Test {
 protected:
  sym::System system{load_mechanism("four-bar")};
  std::vector<MechanismColumn> all = mechanism_columns(system);

  std::vector<MechanismColumn> select(const std::string& spec) {
    return select_mechanism_columns(all, spec, "--columns", &system);
  }
};

// Each defined column equals its expression at the named columns' values, at every sample
// of a run (the same doubles: sum and product of two numbers are correctly rounded).
TEST_F(ExpressionColumns, TakeTheirValuesFromTheColumnsTheyName) {
  const std::vector<MechanismColumn> columns = select(
      "t,gamma=4.theta-3.theta,F=hypot(B.force_x, B.force_y),r=a*2.theta,twice=2*gamma,"
      "4.theta,3.theta,B.force_x,B.force_y,2.theta,P=O2.force_x*3.P.ax");
  ASSERT_EQ(columns.size(), 11U);
  EXPECT_TRUE(needs_kinematics(columns));  // P uses a point's acceleration
  const sym::ClosedState closed = sym::checked_initial_state(system);
  SimulationOptions o;
  o.rtol = o.atol = 1e-10;
  o.duration = 0.5;
  o.kinematics = true;
  MechanismSimulation simulation(system, closed.state, o);
  eval::MechanismSample sample;
  const MechanismColumn ax = find_mechanism_column(all, "3.P.ax", "test");
  const MechanismColumn fx = find_mechanism_column(all, "O2.force_x", "test");
  for (int i = 0; i <= 10; ++i) {
    const double t = 0.05 * i;
    const Eigen::VectorXd& y = simulation.state_at(t);
    simulation.sample(t, y, sample, true);
    std::vector<double> v;
    for (const MechanismColumn& c : columns) v.push_back(column_value(c, t, y, sample, simulation.origin()));
    EXPECT_EQ(v[0], t);
    EXPECT_EQ(v[1], v[5] - v[6]) << "t " << t;
    EXPECT_NEAR(v[2], std::hypot(v[7], v[8]), 1e-15 * std::hypot(v[7], v[8])) << "t " << t;
    EXPECT_EQ(v[3], 0.1 * v[9]) << "t " << t;  // a = 0.1 m
    EXPECT_EQ(v[4], 2 * v[1]) << "t " << t;
    const double p =
        column_value(fx, t, y, sample, simulation.origin()) * column_value(ax, t, y, sample, simulation.origin());
    EXPECT_EQ(v[10], p) << "t " << t;
    EXPECT_NE(v[10], 0);
  }
}

// An angle stays in rad (so --angles deg converts it), a sum of one unit keeps it, and
// the rest follows by dimensional analysis; unknown when the units disagree.
TEST_F(ExpressionColumns, CarryTheUnitOfWhatTheyCompute) {
  const auto unit = [&](const std::string& spec) { return expression_column(all, &system, spec, "test").unit; };
  EXPECT_EQ(unit("gamma=4.theta-3.theta"), "rad");
  EXPECT_EQ(unit("mu=pi/2-acos(cos(4.theta-3.theta))"), "rad");
  EXPECT_EQ(unit("phi=atan2(B.force_y, B.force_x)"), "rad");
  EXPECT_EQ(unit("w=4.theta_dot-3.theta_dot"), "rad/s");
  EXPECT_EQ(unit("F=hypot(B.force_x, B.force_y)"), "N");
  EXPECT_EQ(unit("Fs=B.force_x+O2.force_x"), "N");
  EXPECT_EQ(unit("power=B.force_x*3.B.vx+B.force_y*3.B.vy"), "W");
  EXPECT_EQ(unit("r=a*2.theta"), "m");
  EXPECT_EQ(unit("tip=3.P.x/b"), "");
  EXPECT_EQ(unit("k=4.theta^2"), "");
  EXPECT_EQ(unit("bad=4.theta+a"), "");  // rad plus m: no unit claimed
  EXPECT_EQ(unit("E=energy/2"), "J");
}

TEST_F(ExpressionColumns, RefuseABadNameOrExpressionInOneLine) {
  const auto error = [&](const std::string& spec) { return input_error_of([&] { (void)select(spec); }); };
  EXPECT_EQ(error("t,1x=2.theta").rfind("--columns: '1x' in '1x=2.theta' is not a name for a column", 0), 0U)
      << error("t,1x=2.theta");
  EXPECT_NE(error("t,energy=2.theta").find("'energy' in 'energy=2.theta' is already a column"), std::string::npos);
  EXPECT_NE(error("t,g=2.theta,g=3.theta").find("'g' in 'g=3.theta' is already a column"), std::string::npos);
  EXPECT_NE(error("t,all=2.theta").find("names a group of columns"), std::string::npos);
  const std::string unknown = error("t,w=2.thet_dot");
  EXPECT_NE(unknown.find("--columns: column 'w': unknown name '2.thet_dot'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("did you mean '2.theta_dot'"), std::string::npos) << unknown;
  EXPECT_NE(error("t,w=2.theta*").find("column 'w'"), std::string::npos);
  EXPECT_EQ(error("t,w=2.theta*").find('\n'), std::string::npos);
}

// A value that is not a number at a sample stops the run with the time, never a NaN row.
TEST_F(ExpressionColumns, ANonNumberAtASampleIsAnErrorNamingTheTime) {
  const std::vector<MechanismColumn> columns = select("t,root=sqrt(2.theta-1.2)");
  const sym::ClosedState closed = sym::checked_initial_state(system);
  SimulationOptions o;
  o.duration = 1;
  MechanismSimulation simulation(system, closed.state, o);
  eval::MechanismSample sample;
  const Eigen::VectorXd& y = simulation.state_at(0);
  simulation.sample(0, y, sample, false);
  const std::string error = input_error_of([&] { (void)column_value(columns[1], 0, y, sample, simulation.origin()); });
  EXPECT_EQ(error,
            "--columns: column 'root' = sqrt(2.theta-1.2) is not a number at t = 0 s; valid: an expression defined "
            "all along the run (check divisions, sqrt, log, asin, acos)");
}

}  // namespace
}  // namespace linkage
