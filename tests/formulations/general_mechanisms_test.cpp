// The three cases of mechanisms beyond the homework, built in code: every case gives the
// same accelerations and joint forces (directly or recovered) to 1e-12 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "model/mechanism_toml.hpp"
#include "support/mechanisms_in_code.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

using built::double_pendulum;
using built::four_bar;
using built::slider_crank;

void expect_cases_agree(const Mechanism& mechanism) {
  const sym::System system(mechanism);
  const sym::ClosedState closed = sym::close_loops(system, system.initial_state());
  const GiNaC::exmap values = state_values(system, closed.state, 0);
  std::vector<CaseSystem> cases;
  std::vector<CaseNumbers> numbers;
  for (CaseId id : kAllCases) {
    cases.push_back(derive_case(system, id));
    numbers.push_back(solve_numbers(cases.back(), values));
    EXPECT_LT(numbers.back().residual, 1e-10 * (1 + numbers.back().B.norm())) << case_number(id);
  }
  // Every Case 1 unknown, from every case.
  for (std::size_t j = 0; j < cases[0].unknowns.size(); ++j) {
    const GiNaC::symbol& u = cases[0].unknowns[j];
    const double reference = numbers[0].solution(static_cast<Eigen::Index>(j));
    for (std::size_t k = 1; k < cases.size(); ++k) {
      const auto value = case_value(cases[k], numbers[k], values, u);
      ASSERT_TRUE(value.has_value()) << u << " missing from Case " << k + 1;
      EXPECT_NEAR(*value, reference, 1e-12 * (1 + std::abs(reference))) << u << " in Case " << k + 1;
    }
  }
}

TEST(GeneralMechanisms, DoublePendulumCasesAgree) { expect_cases_agree(double_pendulum()); }
TEST(GeneralMechanisms, FourBarCasesAgree) { expect_cases_agree(four_bar()); }
TEST(GeneralMechanisms, SliderCrankCasesAgree) { expect_cases_agree(slider_crank()); }

TEST(GeneralMechanisms, FourBarLoopCloses) {
  const Mechanism m = four_bar();
  const sym::System system(m);
  const sym::ClosedState closed = sym::close_loops(system, system.initial_state());
  EXPECT_TRUE(closed.changed);
  const GiNaC::exmap values = state_values(system, closed.state, 0);
  for (int j : system.tree().loop_joints)
    for (const GiNaC::ex& phi : system.joints()[static_cast<std::size_t>(j)].constraints) {
      EXPECT_NEAR(value_at(phi.subs(system.to_generalized()), values), 0, 1e-13);
      const GiNaC::ex rate = system.time_derivative(phi.subs(system.to_generalized()));
      EXPECT_NEAR(value_at(rate, values), 0, 1e-12);
    }
  // The crank keeps its angle.
  EXPECT_DOUBLE_EQ(value_at(system.coordinates()[0].symbols.q, values), 1.0);
}

// Issue 22 F16: Newton reached the loop whole turns away (the shipped four-bar from
// 3.theta = 2, 4.theta = 0 moved 32.0 and -36.1 rad); each angle must end within pi of where
// it was put, over a grid of starting angles.
TEST(GeneralMechanisms, LoopClosureKeepsAnglesWithinPiOfTheGivenOnes) {
  int closed_count = 0;
  for (double theta3 = -3; theta3 <= 3; theta3 += 0.5)
    for (double theta4 = -3; theta4 <= 3; theta4 += 0.5) {
      Mechanism m = four_bar();
      set_value(m, "3.theta", theta3, "test");
      set_value(m, "4.theta", theta4, "test");
      const sym::System system(m);
      sym::ClosedState closed;
      try {
        closed = sym::close_loops(system, system.initial_state());
      } catch (const Error&) {
        continue;  // Newton did not converge from here: refused, not wrong
      }
      ++closed_count;
      const GiNaC::exmap values = state_values(system, closed.state, 0);
      for (int j : system.tree().loop_joints)
        for (const GiNaC::ex& phi : system.joints()[static_cast<std::size_t>(j)].constraints)
          EXPECT_NEAR(value_at(phi.subs(system.to_generalized()), values), 0, 1e-13);
      for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
        const double given = g.coordinate.key == "3.theta" ? theta3 : g.coordinate.key == "4.theta" ? theta4 : 1.0;
        EXPECT_NEAR(value_at(g.symbols.q, values), given, std::numbers::pi)
            << g.coordinate.key << " from " << theta3 << ", " << theta4;
      }
    }
  EXPECT_GT(closed_count, 100);
}

TEST(GeneralMechanisms, FourBarKeepsOnlyTheLoopForce) {
  const sym::System system(four_bar());
  const CaseSystem c3 = reduced_case(system);
  EXPECT_EQ(c3.unknowns.size(), 3u + 2u);  // three angles, the loop pin's two components
  EXPECT_EQ(c3.A.size(), 5u);
}

}  // namespace
}  // namespace linkage
