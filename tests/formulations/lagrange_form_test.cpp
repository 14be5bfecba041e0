// Case 3 in Lagrange's form (formulations/case_lagrange.cpp), for every shipped mechanism
// and every mechanism built in code: one row per generalized coordinate with M symmetric
// exactly (M_ij - M_ji is zero as an expression), the solution Case 3's to round-off at the
// initial state and at random states, and the double pendulum's M_12 the board's
// m2 l1 l2 cos(θ₁ - θ₂) / 2, with no product of sines or cosines left in it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "model/mechanism_toml.hpp"
#include "support/mechanisms_in_code.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

std::vector<built::Named> mechanisms() {
  std::vector<built::Named> out = built::all_mechanisms();
  for (const std::string& name : shipped_mechanism_names())
    out.push_back({"shipped_" + name, [name] { return load_mechanism(name); }});
  for (built::Named& named : out) named.name = test::test_name(named.name);
  return out;
}

class LagrangeForm : public testing::TestWithParam<built::Named> {};

TEST_P(LagrangeForm, IsOneRowPerCoordinateWithMSymmetric) {
  const sym::System system(GetParam().make());
  const CaseSystem lagrange = lagrange_case(system);
  const CaseSystem reduced = reduced_case(system);
  const std::size_t n = system.coordinates().size();
  ASSERT_EQ(lagrange.unknowns, reduced.unknowns);
  ASSERT_EQ(lagrange.A.size(), reduced.A.size());
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(lagrange.unknowns[i], system.coordinates()[i].symbols.q_ddot);
    EXPECT_FALSE(lagrange.A[i][i].is_zero()) << "M_" << i << i;
    for (std::size_t j = 0; j < n; ++j)
      EXPECT_TRUE(GiNaC::expand(lagrange.A[i][j] - lagrange.A[j][i]).is_zero())
          << "M_" << i << j << " = " << lagrange.A[i][j] << ", M_" << j << i << " = " << lagrange.A[j][i];
  }
}

// |u - u_3| within a few hundred round-offs of the worse conditioned of the two solves.
void expect_agreement(const CaseNumbers& lagrange, const CaseNumbers& reduced, const std::string& where) {
  ASSERT_EQ(lagrange.solution.size(), reduced.solution.size());
  const double scale = std::max(1.0, reduced.solution.cwiseAbs().maxCoeff());
  const double tolerance =
      256 * std::numeric_limits<double>::epsilon() * std::max(lagrange.condition, reduced.condition) * scale;
  for (Eigen::Index i = 0; i < reduced.solution.size(); ++i)
    EXPECT_NEAR(lagrange.solution(i), reduced.solution(i), tolerance) << where << ", unknown " << i;
}

TEST_P(LagrangeForm, SolvesAsCase3) {
  const sym::System system(GetParam().make());
  const CaseSystem lagrange = lagrange_case(system);
  const CaseSystem reduced = reduced_case(system);
  if (!system.mechanism().initial.empty()) {  // those built in code start at zero: random states only
    const GiNaC::exmap initial = state_values(system, sym::checked_initial_state(system).state, 0);
    expect_agreement(solve_numbers(lagrange, initial), solve_numbers(reduced, initial), "the initial state");
  }
  std::mt19937 rng(23);
  for (int k = 0; k < 3; ++k) {
    const GiNaC::exmap values = state_values(system, built::random_state(system, rng), 0.7 * k);
    expect_agreement(solve_numbers(lagrange, values), solve_numbers(reduced, values), "state " + std::to_string(k));
  }
}

INSTANTIATE_TEST_SUITE_P(Mechanisms, LagrangeForm, testing::ValuesIn(mechanisms()),
                         [](const testing::TestParamInfo<built::Named>& p) { return p.param.name; });

TEST(LagrangeFormOf, TheDoublePendulumCouplesByTheCosineOfTheDifference) {
  const sym::System system(load_mechanism("double-pendulum"));
  const CaseSystem lagrange = lagrange_case(system);
  auto symbol = [&](const char* key) { return GiNaC::ex(system.table().find(std::string(key))->symbol); };
  const GiNaC::ex th1 = system.bodies()[0].theta.q, th2 = system.bodies()[1].theta.q;
  const GiNaC::ex m12 = symbol("m2") * symbol("l1") * symbol("l2") * GiNaC::cos(th1 - th2) / 2;
  EXPECT_TRUE(GiNaC::expand(lagrange.A[0][1] - m12).is_zero()) << lagrange.A[0][1];
  EXPECT_FALSE(lagrange.A[0][1].has(GiNaC::sin(th1)) || lagrange.A[0][1].has(GiNaC::cos(th1))) << lagrange.A[0][1];
  // The velocity terms contract too: m2 l1 l2 sin(θ₁ - θ₂) θ̇₂² / 2 in row 1, no sin θ₁ cos θ₂.
  EXPECT_TRUE(lagrange.B[0].has(GiNaC::sin(th1 - th2))) << lagrange.B[0];
  EXPECT_FALSE(lagrange.B[0].has(GiNaC::sin(th1) * GiNaC::cos(th2))) << lagrange.B[0];
}

}  // namespace
}  // namespace linkage
