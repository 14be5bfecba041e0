// The columns of the centre of mass, the invariants' errors and the relative energy
// error, on the homework (two-blocks.toml at its defaults: L = 0.3, w = 0.1, m = 0.1,
// g = 9.81, both blocks' masses equal) where each has a closed form, and the energy scale:
// T + m g (|y1| + |y2| + L) there, the homework's own.
#include "columns/mechanism_columns.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "integrate/mechanism_simulation.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

constexpr double kL = 0.3, kW = 0.1, kM = 0.1, kG = 9.81;

/// Every column of a mechanism at the sample times, by name; the run's figures.
struct Table {
  std::map<std::string, std::vector<double>> values;
  MechanismStats stats;
};

Table run_all(const std::string& name, double duration, double every, int case_id = 3) {
  const sym::System system(load_mechanism(name));
  const sym::ClosedState closed = sym::checked_initial_state(system);
  SimulationOptions o;
  o.case_id = case_id;
  o.integrator = IntegratorKind::dop853;
  o.rtol = o.atol = 1e-12;
  o.duration = duration;
  MechanismSimulation simulation(system, closed.state, o);
  const std::vector<MechanismColumn> columns = mechanism_columns(system);
  Table out;
  eval::MechanismSample sample;
  for (int i = 0; i <= static_cast<int>(std::lround(duration / every)); ++i) {
    const double t = std::min(duration, i * every);
    const Eigen::VectorXd& y = simulation.state_at(t);
    simulation.sample(t, y, sample, true);
    for (const MechanismColumn& c : columns)
      out.values[c.name].push_back(column_value(c, t, y, sample, simulation.origin()));
  }
  out.stats = simulation.stats();
  return out;
}

TEST(MechanismColumns, TheHomeworksCentreOfMassIsTheMidpointOfItsBlocks) {
  const Table r = run_all("two-blocks", 2, 0.1);
  const auto& v = r.values;
  for (std::size_t i = 0; i < v.at("t").size(); ++i) {
    const double x_com = (v.at("1.x")[i] + v.at("2.x")[i]) / 2, y_com = (v.at("1.y")[i] + v.at("2.y")[i]) / 2;
    EXPECT_NEAR(v.at("com.x")[i], x_com, 1e-14);
    EXPECT_NEAR(v.at("com.y")[i], y_com, 1e-14);
    EXPECT_NEAR(v.at("com.x_dot")[i], (v.at("1.x_dot")[i] + v.at("2.x_dot")[i]) / 2, 1e-14);
    EXPECT_NEAR(v.at("com.y_dot")[i], (v.at("1.y_dot")[i] + v.at("2.y_dot")[i]) / 2, 1e-14);
    EXPECT_NEAR(v.at("1.x_from_com")[i], v.at("1.x")[i] - x_com, 1e-14);
    EXPECT_NEAR(v.at("2.y_from_com")[i], v.at("2.y")[i] - y_com, 1e-14);
  }
  // G falls freely: from (x_com0, y_com0) with the initial velocity, 2 s later.
  const double t = 2, x0 = v.at("com.x")[0], y0 = v.at("com.y")[0];
  EXPECT_NEAR(v.at("com.x").back(), x0 + v.at("com.x_dot")[0] * t, 1e-9);
  EXPECT_NEAR(v.at("com.y").back(), y0 + v.at("com.y_dot")[0] * t - kG * t * t / 2, 1e-9);
  EXPECT_NEAR(v.at("com.y_dot").back(), v.at("com.y_dot")[0] - kG * t, 1e-9);
}

TEST(MechanismColumns, TheInvariantsErrorsStartAtZeroAndStaySmall) {
  const Table r = run_all("two-blocks", 2, 0.1);
  for (const char* name : {"momentum_x_error", "momentum_y_error", "angular_momentum_error", "com_parabola_error",
                           "energy_error_relative", "constraint_position_error", "constraint_velocity_error"}) {
    const std::vector<double>& v = r.values.at(name);
    EXPECT_EQ(v.front(), 0) << name;
    for (const double x : v) EXPECT_LT(x, 1e-9) << name;
  }
  // momentum_y itself changes by M g t (here 2 m g over 2 s): the error subtracts exactly that.
  const std::vector<double>& p = r.values.at("momentum_y");
  EXPECT_NEAR(p.back() - p.front(), -2 * kM * kG * 2, 1e-9);
  // The relative error is |energy_error| over the run's energy scale.
  const std::vector<double>& e = r.values.at("energy_error");
  const std::vector<double>& rel = r.values.at("energy_error_relative");
  for (std::size_t i = 0; i < e.size(); ++i) EXPECT_DOUBLE_EQ(rel[i], std::fabs(e[i]) / r.stats.energy_scale);
}

TEST(MechanismColumns, ConstraintErrorsOfAllJointsTogetherInCase1) {
  const Table r = run_all("two-blocks", 1, 0.1, 1);
  const std::vector<double>& all = r.values.at("constraint_position_error");
  const std::vector<double>& pin = r.values.at("P.constraint_error");
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], pin[i]);  // one joint: its own |C|
}

TEST(MechanismColumns, TheEnergyScaleOnTheHomeworkIsItsOwn) {
  // T + m g (|y1| + |y2| + L) at the file's initial state: rates x1' = 0.15, y1' = 0.25,
  // theta1' = 0.35, theta2' = 0.45 and y1 = 2, theta1 = 0.1, theta2 = 0.2, D = L/2 - b.
  const double D = kL / 2 - 0.04, I = kM * (kL * kL + kW * kW) / 12;
  const double t1 = 0.1, t2 = 0.2, w1 = 0.35, w2 = 0.45;
  const double y1 = 2, y2 = y1 + D * std::sin(t1) + D * std::sin(t2);
  const double x2_dot = 0.15 - D * std::sin(t1) * w1 - D * std::sin(t2) * w2;
  const double y2_dot = 0.25 + D * std::cos(t1) * w1 + D * std::cos(t2) * w2;
  const double T =
      kM / 2 * (0.15 * 0.15 + 0.25 * 0.25 + x2_dot * x2_dot + y2_dot * y2_dot) + I / 2 * (w1 * w1 + w2 * w2);
  const double scale = T + kM * kG * (std::fabs(y1) + std::fabs(y2) + kL);
  EXPECT_NEAR(run_all("two-blocks", 0.1, 0.1).stats.energy_scale, scale, 1e-12 * scale);
}

TEST(MechanismColumns, AGroundedMechanismHasNoMomentumErrors) {
  const sym::System system(load_mechanism("double-pendulum"));
  for (const MechanismColumn& c : mechanism_columns(system)) {
    EXPECT_NE(c.name, "momentum_y_error");
    EXPECT_NE(c.name, "com_parabola_error");
  }
}

}  // namespace
}  // namespace linkage
