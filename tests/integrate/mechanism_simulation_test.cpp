// Motion of any mechanism: every shipped mechanism run by DOP853 at 1e-12 keeps its
// energy balance (springs, dampers and applied loads accounted) to 1e-9 of the energy
// scale over 10 s and every joint within 1e-10 with projection; a free mechanism keeps its
// momenta; RK4 converges at order 4; Baumgarte holds a loop that drifts without it.
#include "integrate/mechanism_simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "columns/mechanism_columns.hpp"
#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

const char* const kShipped[] = {"two-blocks",      "unequal-blocks", "double-pendulum", "triple-pendulum",
                                "spring-pendulum", "slider-crank",   "four-bar",        "welded-pendulum",
                                "rolling-disc",    "gear-train",     "quick-return"};

struct RunResult {
  MechanismStats stats;
  Eigen::VectorXd end;
};

RunResult run(const std::string& name, const SimulationOptions& o, double every = 0.05) {
  const sym::System system(load_mechanism(name));
  const sym::ClosedState closed = sym::checked_initial_state(system);
  MechanismSimulation simulation(system, closed.state, o);
  eval::MechanismSample sample;
  const auto count = static_cast<int>(std::lround(o.duration / every));
  Eigen::VectorXd y;
  for (int i = 0; i <= count; ++i) {
    const double t = std::min(o.duration, i * every);
    y = simulation.state_at(t);
    simulation.sample(t, y, sample);
  }
  return {simulation.stats(), y};
}

SimulationOptions tight(int case_id) {
  SimulationOptions o;
  o.case_id = case_id;
  o.integrator = IntegratorKind::dop853;
  o.rtol = o.atol = 1e-12;
  o.duration = 10;
  o.stabilization = Stabilization::projection;
  return o;
}

class Shipped : public ::testing::TestWithParam<const char*> {};

TEST_P(Shipped, Dop853KeepsTheEnergyBalanceAndTheJoints) {
  for (int c = 1; c <= 3; ++c) {
    const RunResult r = run(GetParam(), tight(c));
    EXPECT_LT(r.stats.max_energy_error, 1e-9) << "Case " << c;
    EXPECT_LT(r.stats.max_constraint_error, 1e-10) << "Case " << c;
    // Stepped through the run, not in one step: gear-train's motion, quadratic in t under
    // constant torques, takes DOP853 8 steps in 10 s.
    EXPECT_GE(r.stats.steps_accepted, 5) << "Case " << c;
  }
}

INSTANTIATE_TEST_SUITE_P(MechanismSimulation, Shipped, ::testing::ValuesIn(kShipped));

// The homework floats: its horizontal momentum and its angular momentum about the centre
// of mass stay what they were; the vertical momentum falls at M g.
TEST(MechanismSimulation, FreeMechanismKeepsItsMomenta) {
  const sym::System system(load_mechanism("two-blocks"));
  const sym::ClosedState closed = sym::checked_initial_state(system);
  SimulationOptions o = tight(3);
  o.duration = 5;
  MechanismSimulation simulation(system, closed.state, o);
  eval::MechanismSample start, end;
  simulation.sample(0, simulation.state_at(0), start);
  simulation.sample(5, simulation.state_at(5), end);
  EXPECT_NEAR(end.momentum_x, start.momentum_x, 1e-12);
  EXPECT_NEAR(end.angular_momentum, start.angular_momentum, 1e-12);
  EXPECT_NEAR(end.momentum_y, start.momentum_y - 0.2 * 9.81 * 5, 1e-10);  // two blocks of 0.1 kg
}

// RK4's error at t = 1 s falls 16-fold when the step halves: order 4, measured against
// DOP853 at 1e-13.
TEST(MechanismSimulation, Rk4ConvergesAtOrderFour) {
  SimulationOptions reference = tight(3);
  reference.rtol = reference.atol = 1e-13;
  reference.duration = 1;
  reference.stabilization = Stabilization::none;
  const Eigen::VectorXd exact = run("double-pendulum", reference, 1.0).end;
  std::vector<double> errors;
  for (double dt : {4e-3, 2e-3, 1e-3}) {
    SimulationOptions o = reference;
    o.integrator = IntegratorKind::rk4;
    o.dt = dt;
    errors.push_back((run("double-pendulum", o, 1.0).end - exact).head(4).norm());
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    EXPECT_NEAR(order, 4.0, 0.3) << "errors " << errors[i - 1] << " -> " << errors[i];
  }
}

// Without stabilization the four-bar's loop drifts under RK4 at a coarse step; Baumgarte
// pulls it back, projection removes it.
TEST(MechanismSimulation, StabilizationHoldsTheLoop) {
  SimulationOptions o = tight(2);
  o.integrator = IntegratorKind::rk4;
  o.dt = 5e-3;
  o.stabilization = Stabilization::none;
  const double drift = run("four-bar", o).stats.max_constraint_error;
  o.stabilization = Stabilization::baumgarte;
  const double baumgarte = run("four-bar", o).stats.max_constraint_error;
  o.stabilization = Stabilization::projection;
  const double projected = run("four-bar", o).stats.max_constraint_error;
  EXPECT_GT(drift, 1e-7);
  EXPECT_LT(baumgarte, drift / 10);
  EXPECT_LT(projected, 1e-13);
}

// A tree's Case 1 keeps its joints' rows, which drift without stabilization: explicit
// Euler at a coarse step takes the homework's pin far apart, and the run goes on to its
// end, the drift named by the warning (as the homework always did). A loop that opens
// still stops the run.
TEST(MechanismSimulation, ATreeDriftsToItsEndWithAWarningALoopStops) {
  Mechanism two_blocks = load_mechanism("two-blocks");
  apply_setting(two_blocks, "1.theta_dot=20", "test");
  apply_setting(two_blocks, "2.theta_dot=-35", "test");
  const sym::System tree(two_blocks);
  SimulationOptions o;
  o.case_id = 1;
  o.integrator = IntegratorKind::euler;
  o.dt = 0.05;
  o.duration = 10;
  o.stabilization = Stabilization::none;
  MechanismSimulation drifting(tree, sym::checked_initial_state(tree).state, o);
  eval::MechanismSample sample;
  for (int i = 0; i <= 10; ++i) drifting.sample(i, drifting.state_at(i), sample);
  EXPECT_GT(drifting.stats().max_constraint_error, 1.0) << "metres";
  EXPECT_EQ(drifting.stats().drifted_joint, "P");
  const std::string warning = mechanism_result_warning(o, drifting.stats());
  // The energy balance is off too (by 1.6 energy scales on the homework's scale).
  EXPECT_EQ(warning.rfind("the run's numbers do not describe the motion: ", 0), 0U) << warning;
  EXPECT_NE(warning.find("joint P came "), std::string::npos) << warning;
  EXPECT_NE(warning.find(" m apart ("), std::string::npos) << warning;
  EXPECT_NE(warning.find(" of body 1's length L); try stabilization by projection, Case 3 (it cannot drift), "),
            std::string::npos)
      << warning;

  const sym::System loop(load_mechanism("four-bar"));
  o.case_id = 2;
  o.duration = 100;
  MechanismSimulation opening(loop, sym::checked_initial_state(loop).state, o);
  try {
    for (int i = 0; i <= 10; ++i) (void)opening.state_at(10 * i);
    ADD_FAILURE() << "the loop opened without stopping the run";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("(the loop opened)"), std::string::npos) << e.what();
  }
}

// Every integrator runs every shipped mechanism for a second with finite results.
TEST(MechanismSimulation, EveryIntegratorRuns) {
  for (const IntegratorInfo& i : integrators())
    for (const char* name : {"slider-crank", "spring-pendulum"}) {
      SimulationOptions o = tight(3);
      o.integrator = i.kind;
      o.duration = 1;
      o.dt = 1e-3;
      o.rtol = o.atol = 1e-9;
      const RunResult r = run(name, o, 0.1);
      EXPECT_TRUE(r.end.allFinite()) << i.name << " " << name;
      EXPECT_LT(r.stats.max_energy_error, i.order >= 4 ? 1e-6 : 0.05) << i.name << " " << name;
    }
}

// The columns follow the contract: t, each body's x, y, theta (none for a point mass), each
// slider's s by default; a misspelt name is refused naming the nearest one.
TEST(MechanismSimulation, ColumnsFollowTheContract) {
  const sym::System system(load_mechanism("slider-crank"));
  const std::vector<MechanismColumn> all = mechanism_columns(system);
  std::vector<std::string> names;
  for (const MechanismColumn& c : select_mechanism_columns(all, "default", "--columns")) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"t", "2.x", "2.y", "2.theta", "3.x", "3.y", "3.theta", "4.x", "4.y",
                                             "4.theta", "S.s"}));
  try {
    (void)select_mechanism_columns(all, "t,B.forcex", "--columns");
    FAIL() << "a misspelt column was accepted";
  } catch (const Error& e) {
    // Too many columns to list: the nearest one's joint's, those of none, and a count.
    EXPECT_EQ(std::string(e.what()),
              "--columns: unknown column 'B.forcex'; nearest 'B.force_x'; valid: default, all, t, B.force_x, "
              "B.force_y, B.constraint_error, B.constraint_velocity_error, constraint_position_error, "
              "constraint_velocity_error, energy, work, energy_error, energy_error_relative, shaking_force_x, "
              "shaking_force_y, shaking_moment and " +
                  std::to_string(all.size() + 2 - 16) +
                  " more (the columns of every body, point and joint; 'all' selects every one)");
  }
  // A list of names (a lesson's): groups anywhere, t once and first; errors at each entry.
  const auto at = [](std::size_t i) { return "entry " + std::to_string(i + 1); };
  const std::vector<MechanismColumn> picked = select_mechanism_columns(all, {"S.moment", "default", "all"}, at);
  ASSERT_EQ(picked.size(), 2 + names.size() - 1 + all.size() - 1);
  EXPECT_EQ(picked[0].name, "t");
  EXPECT_EQ(picked[1].name, "S.moment");
  EXPECT_EQ(picked[2].name, "2.x");
  EXPECT_EQ(select_mechanism_columns(all, {"S.s"}, at).front().name, "t");
  EXPECT_TRUE(select_mechanism_columns(all, std::vector<std::string>{}, at).empty());
  try {
    (void)select_mechanism_columns(all, {"S.s", "S.x"}, at);
    FAIL() << "an unknown column was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("entry 2: unknown column 'S.x'; nearest 'S.s'; valid: default, all, t,"),
              std::string::npos)
        << e.what();
  }
  // One name: of the nearest by edits, the one on the same joint ("S.x": S.s, not 2.x).
  EXPECT_EQ(find_mechanism_column(all, "S.moment", "y").unit, "N m");
  try {
    (void)find_mechanism_column(all, "S.x", "y");
    FAIL() << "an unknown column was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("y: unknown column 'S.x'; nearest 'S.s'; valid: t, S.s, S.s_ddot, S.force_x,"),
              std::string::npos)
        << e.what();
  }
}

/// The named columns at each time of one run (DOP853 at 1e-12), kinematics on request.
std::vector<std::vector<double>> column_values(const std::string& mechanism, int case_id,
                                               const std::vector<double>& times,
                                               const std::vector<std::string>& names) {
  const sym::System system(load_mechanism(mechanism));
  const std::vector<MechanismColumn> all = mechanism_columns(system);
  std::vector<MechanismColumn> columns;
  for (const std::string& name : names) columns.push_back(find_mechanism_column(all, name, "test"));
  SimulationOptions o = tight(case_id);
  o.duration = times.back();
  MechanismSimulation simulation(system, sym::checked_initial_state(system).state, o);
  std::vector<std::vector<double>> out;
  eval::MechanismSample sample;
  for (const double t : times) {
    const Eigen::VectorXd y = simulation.state_at(t);
    simulation.sample(t, y, sample, needs_kinematics(columns));
    out.emplace_back();
    for (const MechanismColumn& c : columns) out.back().push_back(column_value(c, t, y, sample, simulation.origin()));
  }
  return out;
}

// A named point's velocity and acceleration columns are the time derivatives of its
// position columns: five-point central differences with h = 1e-3 s agree to
// h^4 |x^(5)| / 30 and the integration's 1e-12 / h^2, well inside 1e-5 of the values'
// scale (four-bar, P on the coupler; slider-crank, the slider's s'' too), in every case.
TEST(MechanismSimulation, PointColumnsAreTheDerivativesOfTheirPositions) {
  const double h = 1e-3;
  struct Check {
    const char* mechanism;
    std::vector<std::string> names;  // position, its rate, its acceleration; ...
  };
  const Check checks[] = {
      {"four-bar",
       {"3.P.x", "3.P.vx", "3.P.ax", "3.P.y", "3.P.vy", "3.P.ay", "2.theta", "2.theta_dot", "2.theta_ddot"}},
      {"slider-crank", {"S.s", "4.x_dot", "S.s_ddot", "3.x", "3.x_dot", "3.x_ddot"}}};
  for (const Check& check : checks)
    for (int c = 1; c <= 3; ++c)
      for (const double t0 : {0.05, 0.37}) {
        const auto v = column_values(check.mechanism, c, {t0 - 2 * h, t0 - h, t0, t0 + h, t0 + 2 * h}, check.names);
        for (std::size_t k = 0; k + 2 < check.names.size(); k += 3) {
          const double rate = (v[0][k] - 8 * v[1][k] + 8 * v[3][k] - v[4][k]) / (12 * h);
          const double acceleration = (-v[0][k] + 16 * v[1][k] - 30 * v[2][k] + 16 * v[3][k] - v[4][k]) / (12 * h * h);
          const double scale = 1 + std::fabs(v[2][k + 2]);
          EXPECT_NEAR(v[2][k + 1], rate, 1e-5 * scale) << check.mechanism << " Case " << c << " " << check.names[k];
          EXPECT_NEAR(v[2][k + 2], acceleration, 1e-5 * scale)
              << check.mechanism << " Case " << c << " " << check.names[k];
          EXPECT_GT(std::fabs(v[2][k + 1]), 1e-3) << check.names[k + 1] << " is 0: the check could not fail";
        }
      }
}

// The tip A of a pendulum's first rod, pinned at the origin: r = l1 (cos θ, sin θ), its
// velocity l1 θ' (-sin θ, cos θ), its acceleration l1 θ'' (-sin θ, cos θ) - l1 θ'^2 (cos θ,
// sin θ), with θ, θ', θ'' the body's own columns; rod 2's A is the same point.
TEST(MechanismSimulation, PendulumTipColumnsFollowTheClosedForm) {
  const double l1 = 0.3;
  for (int c = 1; c <= 3; ++c) {
    const auto rows = column_values("double-pendulum", c, {0.0, 0.4, 1.3},
                                    {"1.theta", "1.theta_dot", "1.theta_ddot", "1.A.x", "1.A.y", "1.A.vx", "1.A.vy",
                                     "1.A.ax", "1.A.ay", "2.A.x", "2.A.y", "2.A.vx", "2.A.vy", "2.A.ax", "2.A.ay"});
    for (const auto& r : rows) {
      const double th = r[0], w = r[1], al = r[2];
      const double expected[] = {l1 * std::cos(th),
                                 l1 * std::sin(th),
                                 -l1 * w * std::sin(th),
                                 l1 * w * std::cos(th),
                                 -l1 * al * std::sin(th) - l1 * w * w * std::cos(th),
                                 l1 * al * std::cos(th) - l1 * w * w * std::sin(th)};
      for (std::size_t k = 0; k < 6; ++k) {
        EXPECT_NEAR(r[3 + k], expected[k], 1e-9 * (1 + std::fabs(expected[k]))) << "Case " << c << " column " << k;
        EXPECT_NEAR(r[9 + k], expected[k], 1e-9 * (1 + std::fabs(expected[k]))) << "Case " << c << " 2.A " << k;
      }
    }
  }
}

// `all` lists every point's and every acceleration's column; a run that asks for none of
// them does not evaluate them (the sample's kinematics stay empty).
TEST(MechanismSimulation, AllListsThePointAndAccelerationColumns) {
  const sym::System system(load_mechanism("slider-crank"));
  const std::vector<MechanismColumn> all = mechanism_columns(system);
  std::vector<std::string> names;
  for (const MechanismColumn& c : select_mechanism_columns(all, "all", "--columns")) names.push_back(c.name);
  for (const char* expected : {"2.x_ddot", "2.y_ddot", "2.theta_ddot", "4.theta_ddot", "S.s_ddot"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  for (const eval::NamedPoint& p : eval::named_points(system))
    for (const char* suffix : {".x", ".y", ".vx", ".vy", ".ax", ".ay"}) {
      const std::string name = system.bodies()[p.body].name + "." + p.name + suffix;
      EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    }
  EXPECT_FALSE(eval::named_points(system).empty());
  EXPECT_FALSE(needs_kinematics(select_mechanism_columns(all, "default,energy,S.force_x", "--columns")));
  EXPECT_TRUE(needs_kinematics(select_mechanism_columns(all, "t,3.B.ay", "--columns")));
  MechanismSimulation simulation(system, sym::checked_initial_state(system).state, tight(3));
  eval::MechanismSample sample;
  simulation.sample(0, simulation.state_at(0), sample);
  EXPECT_TRUE(sample.points.empty());
  EXPECT_TRUE(sample.accelerations.empty());
}

}  // namespace
}  // namespace linkage
