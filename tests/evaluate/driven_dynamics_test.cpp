// Drivers in the compiled dynamics (issue 25): each driver's row C(q, t) = driven(q) -
// motion(t) is kept after the joints' in every case, C' = J q' + C_t in Baumgarte's terms
// and the projection, the drivers' power lambda (dC/dq) q' in W', and the structured solve
// gives the general path's accelerations with driver rows.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "evaluate/mechanism_dynamics.hpp"
#include "structured_agreement.hpp"
#include "support/mechanisms_in_code.hpp"

namespace linkage {
namespace {

using built::q;

Driver driver(const std::string& name, const std::string& joint, const std::string& motion) {
  return {name, joint, q(motion), {}};
}

// A rod of mass 0.2 and length 0.3 on the ground pin O2 at its end, turned by M at
// th = 0.3 + 2 t: no damper, no load but gravity.
Mechanism driven_rod() {
  Mechanism m;
  m.gravity = q("g");
  m.parameters = {{"l", 0.3, {}}, {"m", 0.2, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {built::rod("crank", "m", "l", {{"O", {"-l/2", "0"}}})};
  m.joints = {built::pin("O2", "ground", "O", "crank", "O")};
  m.drivers = {driver("M", "O2", "0.3 + 2*t")};
  m.initial = {{"crank.theta", 0.3, {}}, {"crank.theta_dot", 2.0, {}}};
  return m;
}

// The rod's state at t on its motion (th = 0.3 + 2 t, th' = 2), or off it by `off`.
GiNaC::exmap rod_state(const sym::System& system, double t, double off = 0) {
  GiNaC::exmap state = system.initial_state();
  const sym::GeneralizedCoordinate& g = system.coordinates().front();
  state[g.symbols.q] = GiNaC::numeric(0.3 + 2 * t + off);
  state[g.symbols.q_dot] = GiNaC::numeric(2 - 10 * off);
  return state;
}

std::vector<built::Named> driven_mechanisms() {
  return {{"four_bar",
           [] {
             Mechanism m = built::four_bar();
             m.joints[1].damping = q("0.05");
             m.drivers = {driver("M", "O2", "1 + 2*t + 0.3*t^2")};
             return m;
           }},
          {"slider_crank_crank",
           [] {
             Mechanism m = built::slider_crank();
             m.drivers = {driver("M", "O", "0.8 + 3*t")};
             return m;
           }},
          {"slider_crank_piston",
           [] {
             Mechanism m = built::slider_crank();
             m.drivers = {driver("P", "s", "0.4 + 0.05*sin(3*t)")};
             return m;
           }},
          {"cart_pendulum", [] {
             Mechanism m = built::cart_pendulum();
             m.drivers = {driver("D", "rail", "0.3 + 0.1*sin(5*t)")};
             return m;
           }}};
}

// Driver rows are the last constraint rows and their multipliers the last unknowns:
// [M G; J 0] is found (or not) on the whole A, and the structured solve gives the
// general LU's y' to 1e-12, with and without Baumgarte's terms, in every case.
TEST(DrivenDynamics, StructuredSolveAgreesWithTheGeneralPath) {
  std::mt19937 rng(25);
  for (const built::Named& named : driven_mechanisms()) {
    const sym::System system(named.make());
    for (CaseId id : kAllCases) {
      const std::string what = named.name + " Case " + std::to_string(case_number(id));
      eval::MechanismDynamics structured(system, id);
      test::expect_structured_agrees(system, structured, rng, what);
      EXPECT_EQ(structured.constraint_joints().back(), system.drivers().back().joint) << what;
    }
  }
}

// On the motion (C = 0 and C' = J q' + C_t = 0, C_t = -2) Baumgarte's terms vanish: y' is
// the plain equations' y'. With J q' alone for C' they would add -2 alpha * 2 to the
// driver's row. And the crank at constant speed has th'' = 0 in every case.
TEST(DrivenDynamics, BaumgarteUsesTheMotionsRate) {
  const sym::System system(driven_rod());
  for (CaseId id : kAllCases) {
    const std::string what = "Case " + std::to_string(case_number(id));
    eval::MechanismDynamics plain(system, id), corrected(system, id);
    corrected.set_baumgarte(5.0, 7.0);
    const Eigen::VectorXd y = plain.initial_state(rod_state(system, 0.4));
    EXPECT_NEAR(plain.constraint_violation(0.4, y), 0, 1e-15) << what;
    Eigen::VectorXd dp, dc;
    ASSERT_TRUE(plain.derivative(0.4, y, dp)) << what;
    ASSERT_TRUE(corrected.derivative(0.4, y, dc)) << what;
    for (Eigen::Index k = 0; k < dp.size(); ++k) EXPECT_NEAR(dc[k], dp[k], 1e-12) << what << " value " << k;
    const auto theta = static_cast<Eigen::Index>(plain.coordinates() - 1);  // the rod's angle is last
    EXPECT_NEAR(dp[plain.coordinates() + theta], 0, 1e-12) << what;
  }
}

// The projection moves a state off the motion back onto th = 0.3 + 2 t, th' = 2 (the
// velocity step solves J q' = -C_t, not J q' = 0).
TEST(DrivenDynamics, ProjectionLandsOnTheMotion) {
  const sym::System system(driven_rod());
  for (CaseId id : kAllCases) {
    const std::string what = "Case " + std::to_string(case_number(id));
    const eval::MechanismDynamics dynamics(system, id);
    Eigen::VectorXd y = dynamics.initial_state(rod_state(system, 0.4, 0.01));
    EXPECT_LT(dynamics.project(0.4, y), 1e-12) << what;
    const Eigen::VectorXd on = dynamics.initial_state(rod_state(system, 0.4));
    for (Eigen::Index k = 0; k + 1 < y.size(); ++k) EXPECT_NEAR(y[k], on[k], 1e-12) << what << " value " << k;
  }
}

// The motor turning the rod at constant speed holds gravity's moment: M.torque =
// m g (l/2) cos th, and W' (no damper, no load) is its power M.torque * th'.
TEST(DrivenDynamics, DriversTorqueAndPowerAtConstantSpeed) {
  const sym::System system(driven_rod());
  for (CaseId id : kAllCases) {
    const std::string what = "Case " + std::to_string(case_number(id));
    const eval::MechanismDynamics dynamics(system, id);
    for (const double t : {0.0, 0.4, 1.3}) {
      const Eigen::VectorXd y = dynamics.initial_state(rod_state(system, t));
      const double torque = 0.2 * 9.81 * 0.15 * std::cos(0.3 + 2 * t);
      eval::MechanismSample sample;
      dynamics.sample(t, y, sample);
      ASSERT_EQ(sample.drivers.size(), 1U) << what;
      EXPECT_NEAR(sample.drivers[0], torque, 1e-12) << what << " t " << t;
      Eigen::VectorXd dydt;
      ASSERT_TRUE(dynamics.derivative(t, y, dydt)) << what;
      EXPECT_NEAR(dydt[dydt.size() - 1], 2 * torque, 1e-12) << what << " t " << t;
    }
  }
}

}  // namespace
}  // namespace linkage
