// The compiled dynamics of any mechanism: the tree's recursion equals the compiled rows,
// the three cases give the same motion of every body, and a projection lands on the
// constraints. (Against the homework's closed form: bench/tests/general_cases_test.cpp.)
#include "evaluate/mechanism_dynamics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "support/mechanisms_in_code.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

// Case 3 of a tree runs the O(n) recursion (and a Schur complement for loops); Case 2 the
// compiled rows by LU. Same accelerations at random states, for every mechanism built in
// code: pins, sliders, floating bases, springs, dampers, applied loads, closed loops.
TEST(MechanismDynamics, RecursionEqualsTheCompiledRows) {
  const std::vector<built::Named> mechanisms = built::all_mechanisms();
  std::mt19937 rng(13);
  for (const built::Named& named : mechanisms) {
    const sym::System system(named.make());
    eval::MechanismDynamics reduced(system, CaseId::reduced);
    const eval::MechanismDynamics generalized(system, CaseId::generalized);
    reduced.solve_by_structure(false);  // small systems would take the structured solve
    for (int trial = 0; trial < 5; ++trial) {
      const GiNaC::exmap state = built::random_state(system, rng);
      const Eigen::VectorXd y = reduced.initial_state(state);
      Eigen::VectorXd fast, rows;
      ASSERT_TRUE(reduced.derivative(0.3 * trial, y, fast)) << named.name;
      ASSERT_TRUE(generalized.derivative(0.3 * trial, y, rows)) << named.name;
      const double scale = 1 + rows.cwiseAbs().maxCoeff();
      for (Eigen::Index i = 0; i < y.size(); ++i)
        EXPECT_NEAR(fast[i], rows[i], 1e-12 * scale) << named.name << " entry " << i << " trial " << trial;
    }
  }
}

// Each case's sample reports the same bodies' motion and joint forces at the same state.
TEST(MechanismDynamics, CasesAgreeOnEveryBodyAndJoint) {
  const std::vector<built::Named> mechanisms = built::all_mechanisms();
  std::mt19937 rng(5);
  for (const built::Named& named : mechanisms) {
    const sym::System system(named.make());
    const GiNaC::exmap state = built::random_state(system, rng);
    std::vector<eval::MechanismSample> samples;
    for (CaseId id : kAllCases) {
      const eval::MechanismDynamics dynamics(system, id);
      const Eigen::VectorXd y = dynamics.initial_state(state);
      eval::MechanismSample s;
      dynamics.sample(0.2, y, s);
      samples.push_back(s);
    }
    for (std::size_t k = 1; k < samples.size(); ++k) {
      for (std::size_t i = 0; i < samples[0].pose.size(); ++i) {
        EXPECT_NEAR(samples[k].pose[i], samples[0].pose[i], 1e-13) << named.name << " pose " << i;
        EXPECT_NEAR(samples[k].rates[i], samples[0].rates[i], 1e-12) << named.name << " rate " << i;
      }
      for (std::size_t i = 0; i < samples[0].force.size(); ++i)
        EXPECT_NEAR(samples[k].force[i], samples[0].force[i], 1e-11 * (1 + std::abs(samples[0].force[i])))
            << named.name << " Case " << k + 1 << " force " << i;
      EXPECT_NEAR(samples[k].kinetic, samples[0].kinetic, 1e-13) << named.name;
      EXPECT_NEAR(samples[k].potential, samples[0].potential, 1e-13) << named.name;
    }
  }
}

// Case 1 integrates every body's x, y, theta; its angular accelerations equal those of
// Case 3, which integrates the angles alone.
TEST(MechanismDynamics, MaximalAccelerationsAreTheGeneralizedOnes) {
  const sym::System system(built::double_pendulum());
  std::mt19937 rng(9);
  const GiNaC::exmap state = built::random_state(system, rng);
  const eval::MechanismDynamics maximal(system, CaseId::maximal), reduced(system, CaseId::reduced);
  const Eigen::VectorXd ym = maximal.initial_state(state), yr = reduced.initial_state(state);
  Eigen::VectorXd dm, dr;
  ASSERT_TRUE(maximal.derivative(0, ym, dm));
  ASSERT_TRUE(reduced.derivative(0, yr, dr));
  auto acceleration = [](const eval::MechanismDynamics& d, const Eigen::VectorXd& dydt, const std::string& name) {
    const auto& names = d.coordinate_names();
    const auto at = std::find(names.begin(), names.end(), name) - names.begin();
    return dydt[d.coordinates() + at];
  };
  for (const std::string name : {"1.theta", "2.theta"})
    EXPECT_NEAR(acceleration(maximal, dm, name), acceleration(reduced, dr, name), 1e-12) << name;
}

// A projection moves a perturbed four-bar back onto its loop, to round-off, and its rates
// onto the loop's velocity constraint.
TEST(MechanismDynamics, ProjectionClosesTheLoop) {
  const sym::System system(built::four_bar());
  const sym::ClosedState closed = sym::checked_initial_state(system);
  for (CaseId id : kAllCases) {
    const eval::MechanismDynamics dynamics(system, id);
    ASSERT_GT(dynamics.constraint_rows(), 0);
    Eigen::VectorXd y = dynamics.initial_state(closed.state);
    EXPECT_LT(dynamics.constraint_violation(0, y), 1e-9);
    y.head(dynamics.coordinates()).array() += 1e-3;
    y.segment(dynamics.coordinates(), dynamics.coordinates()).array() += 0.1;
    EXPECT_GT(dynamics.constraint_violation(0, y), 1e-4);
    EXPECT_LT(dynamics.project(0, y), 1e-14) << "Case " << case_number(id);
    EXPECT_LT(dynamics.constraint_violation(0, y), 1e-14);
  }
}

}  // namespace
}  // namespace linkage
