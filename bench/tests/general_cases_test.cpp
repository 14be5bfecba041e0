// The general path (symbolic/system, formulations/case_*, evaluate/mechanism_dynamics,
// symbolic/energy) for the homework, built here in code, against its closed form, the
// independent second derivation written out by hand: the three cases' matrices and
// solutions, the compiled right-hand side at random states, the energies and momenta.
#include <gtest/gtest.h>

#include <random>

#include "bench/closed_form/formulation.hpp"
#include "bench/closed_form/kinematics.hpp"
#include "bench/closed_form/linkage_rhs.hpp"
#include "evaluate/mechanism_dynamics.hpp"
#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "support/mechanisms_in_code.hpp"
#include "symbolic/energy.hpp"

namespace linkage {
namespace {

using built::homework;

/// built::homework()'s initial state in the closed form's coordinates: x1, y1, theta1,
/// theta2 and their rates.
State homework_initial_state() { return {1, 2, 0.1, 0.2, 0.15, 0.25, 0.35, 0.45}; }

TEST(GeneralCases, HomeworkMatchesTheClosedForm) {
  const sym::System system(homework());
  const GiNaC::exmap values = state_values(system, system.initial_state(), 0);
  const Params p;
  const State s = homework_initial_state();
  for (CaseId id : kAllCases) {
    const CaseSystem c = derive_case(system, id);
    const CaseNumbers n = solve_numbers(c, values);
    const CaseSolution closed = solve_case(case_number(id), p, s);
    ASSERT_EQ(n.A.rows(), closed.A.rows()) << case_number(id);
    EXPECT_LT((n.A - closed.A).norm(), 1e-14) << "Case " << case_number(id) << "\n" << n.A << "\n\n" << closed.A;
    EXPECT_LT((n.B - closed.B).norm(), 1e-14) << "Case " << case_number(id) << "\n" << n.B << "\n\n" << closed.B;
    EXPECT_LT((n.solution - closed.solution).norm(), 1e-12) << case_number(id);
  }
}

// Case 3 of the general path against the homework's closed form, which is written out by
// hand (closed_form/case3_fast.hpp): same coordinates (x1, y1, theta1, theta2) and rates.
TEST(MechanismDynamics, HomeworkMatchesTheClosedFormAtRandomStates) {
  const sym::System system(built::homework());
  Params p;
  p.w = 0.1;  // the mechanism built in code: L 0.3, w 0.1, b 0.04, m 0.1, g 9.81
  const GeneralizedRhs<Case3> closed(p);
  std::mt19937 rng(3);
  for (CaseId id : kAllCases) {
    if (id == CaseId::maximal) continue;  // Case 1 integrates other coordinates; compared below
    const eval::MechanismDynamics dynamics(system, id);
    ASSERT_EQ(dynamics.coordinate_names(), (std::vector<std::string>{"1.x", "1.y", "1.theta", "2.theta"}));
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::VectorXd y = dynamics.initial_state(built::random_state(system, rng));
      Vec<8> y8;
      for (int i = 0; i < 8; ++i) y8[i] = y[i];
      Vec<8> expected;
      closed(0, y8, expected);
      Eigen::VectorXd dydt;
      ASSERT_TRUE(dynamics.derivative(0, y, dydt));
      for (int i = 0; i < 8; ++i)
        EXPECT_NEAR(dydt[i], expected[i], 1e-13 * (1 + std::abs(expected[i])))
            << "Case " << case_number(id) << " entry " << i << " trial " << trial;
    }
  }
}

// T, V, p and H against the homework's closed form (closed_form/kinematics.hpp: H about the centre
// of mass G, so H_O = H_G + M G x G').
TEST(Energy, HomeworkMatchesTheClosedForm) {
  const sym::System system(built::homework());
  const GiNaC::exmap values = state_values(system, system.initial_state(), 0);
  const State s = homework_initial_state();
  const Params params;
  const BodyState bodies = body_state(params, s);
  const Invariants expected = invariants(params, bodies);
  const Vec2 G = system_com(bodies), G_dot = system_com_velocity(bodies);
  const double H_O = expected.angular_momentum + 2 * params.m * (G.x() * G_dot.y() - G.y() * G_dot.x());

  EXPECT_NEAR(value_at(sym::kinetic_energy(system), values), expected.kinetic_energy, 1e-15);
  EXPECT_NEAR(value_at(sym::potential_energy(system), values), expected.potential_energy, 1e-14);
  EXPECT_NEAR(value_at(sym::linear_momentum(system).x, values), expected.momentum.x(), 1e-15);
  EXPECT_NEAR(value_at(sym::linear_momentum(system).y, values), expected.momentum.y(), 1e-15);
  EXPECT_NEAR(value_at(sym::angular_momentum(system), values), H_O, 1e-15);
  EXPECT_NEAR(value_at(sym::angular_momentum_about_centre(system), values), expected.angular_momentum, 1e-15);
  EXPECT_TRUE(sym::nonconservative_power_terms(system).empty());
}

}  // namespace
}  // namespace linkage
