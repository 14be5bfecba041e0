// A second, independent route to the accelerations of every tree mechanism (no loop
// joint): Lagrange's equations by GiNaC differentiation of L = T - V in the generalized
// coordinates q,
//   d/dt (dL/dq_i') - dL/dq_i = Q_i,   Q_i = sum_k Q_k dv_k/dq_i'
// (the non-conservative power P = sum_k Q_k v_k with its loads held fixed), linear in q'':
// M q'' = f, solved here numerically. It shares only T, V and P (symbolic/energy) and the
// kinematics to_generalized() with the cases, never their Newton-Euler rows or forces;
// Case 3 (and Cases 1 and 2) must give the same accelerations to 1e-12 relative.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "model/mechanism_toml.hpp"
#include "support/mechanisms_in_code.hpp"
#include "symbolic/energy.hpp"

namespace linkage {
namespace {

using GiNaC::ex;

constexpr int kStates = 4;

struct LagrangeEquations {
  std::vector<GiNaC::symbol> accelerations;  // q_i''
  std::vector<std::vector<ex>> M;            // d E_i / d q_j''
  std::vector<ex> f;                         // -E_i at q'' = 0
};

LagrangeEquations lagrange_equations(const sym::System& system) {
  const GiNaC::exmap& to_q = system.to_generalized();
  const ex L = (sym::kinetic_energy(system) - sym::potential_energy(system)).subs(to_q);
  std::vector<sym::PowerTerm> terms = sym::nonconservative_power_terms(system);
  for (sym::PowerTerm& term : terms) term = {term.load.subs(to_q), term.rate.subs(to_q)};

  LagrangeEquations out;
  GiNaC::exmap at_rest;
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    out.accelerations.push_back(g.symbols.q_ddot);
    at_rest[g.symbols.q_ddot] = 0;
  }
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    ex Q = 0;
    for (const sym::PowerTerm& term : terms) Q += term.load * term.rate.diff(g.symbols.q_dot);
    const ex E = system.time_derivative(L.diff(g.symbols.q_dot)) - L.diff(g.symbols.q) - Q;
    std::vector<ex> row;
    for (const GiNaC::symbol& a : out.accelerations) row.push_back(E.diff(a));
    out.M.push_back(std::move(row));
    out.f.push_back(-E.subs(at_rest));
  }
  return out;
}

Eigen::VectorXd solve_lagrange(const LagrangeEquations& e, const GiNaC::exmap& values) {
  const auto n = static_cast<Eigen::Index>(e.accelerations.size());
  Eigen::MatrixXd M(n, n);
  Eigen::VectorXd f(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j)
      M(i, j) = value_at(e.M[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], values);
    f(i) = value_at(e.f[static_cast<std::size_t>(i)], values);
  }
  return M.fullPivLu().solve(f);
}

// Every tree mechanism: the ones built in code here; when the mechanism reader lands,
// append each shipped mechanisms/*.toml whose spanning tree has no loop joint.
std::vector<built::Named> tree_mechanisms() {
  return {{"homework", built::homework},
          {"double_pendulum", built::double_pendulum},
          {"triple_pendulum", built::triple_pendulum},
          {"spring_pendulum", [] { return built::spring_pendulum(false); }},
          {"driven_spring_pendulum", [] { return built::spring_pendulum(true); }},
          {"double_pendulum_loaded", built::double_pendulum_loaded},
          {"cart_pendulum", built::cart_pendulum},
          {"arm_collar", built::arm_collar},
          {"reversed_joints", built::reversed_joints},
          {"floating_pair", built::floating_pair},
          {"floating_collar", built::floating_collar},
          // The shipped tree mechanisms, as the program reads them.
          {"shipped_two_blocks", [] { return load_mechanism("two-blocks"); }},
          {"shipped_unequal_blocks", [] { return load_mechanism("unequal-blocks"); }},
          {"shipped_double_pendulum", [] { return load_mechanism("double-pendulum"); }},
          {"shipped_triple_pendulum", [] { return load_mechanism("triple-pendulum"); }},
          {"shipped_spring_pendulum", [] { return load_mechanism("spring-pendulum"); }}};
}

class Lagrange : public testing::TestWithParam<built::Named> {};

TEST_P(Lagrange, GivesTheAccelerationsOfEveryCase) {
  const sym::System system(GetParam().make());
  ASSERT_TRUE(system.tree().loop_joints.empty()) << GetParam().name << " has a loop: Lagrange here is for trees";
  const LagrangeEquations lagrange = lagrange_equations(system);
  std::vector<CaseSystem> cases;
  for (CaseId id : kAllCases) cases.push_back(derive_case(system, id));
  // Every body's x'', y'', theta'' in generalized accelerations, to compare with Case 1.
  std::vector<std::pair<GiNaC::symbol, ex>> maximal;
  for (const sym::BodySystem& b : system.bodies()) {
    std::vector<GiNaC::symbol> symbols{b.x.q_ddot, b.y.q_ddot};
    if (b.rotates) symbols.push_back(b.theta.q_ddot);
    for (const GiNaC::symbol& s : symbols) {
      const auto it = system.to_generalized().find(s);
      maximal.emplace_back(s, it == system.to_generalized().end() ? ex(s) : it->second);
    }
  }

  std::mt19937 rng(31);
  for (int k = 0; k < kStates; ++k) {
    const double t = std::uniform_real_distribution<double>(0, 5)(rng);
    const GiNaC::exmap values = state_values(system, built::random_state(system, rng), t);
    const Eigen::VectorXd q_ddot = solve_lagrange(lagrange, values);
    GiNaC::exmap with_q_ddot = values;
    for (std::size_t i = 0; i < lagrange.accelerations.size(); ++i)
      with_q_ddot[lagrange.accelerations[i]] = GiNaC::numeric(q_ddot(static_cast<Eigen::Index>(i)));
    std::vector<double> expected;
    for (const auto& [symbol, value] : maximal) expected.push_back(value_at(value, with_q_ddot));
    double scale = std::max(1.0, q_ddot.cwiseAbs().maxCoeff());
    for (double a : expected) scale = std::max(scale, std::abs(a));

    for (const CaseSystem& c : cases) {
      const CaseNumbers numbers = solve_numbers(c, values);
      const std::string where =
          GetParam().name + ", Case " + std::to_string(case_number(c.id)) + ", state " + std::to_string(k) + ": ";
      // The generalized accelerations: Case 3's and Case 2's unknowns.
      for (std::size_t i = 0; i < lagrange.accelerations.size(); ++i) {
        const auto value = case_value(c, numbers, values, lagrange.accelerations[i]);
        if (c.id == CaseId::maximal && !value) continue;  // a slider's s'' is not a Case 1 unknown
        ASSERT_TRUE(value.has_value()) << where << lagrange.accelerations[i];
        EXPECT_NEAR(*value, q_ddot(static_cast<Eigen::Index>(i)), 1e-12 * scale) << where << lagrange.accelerations[i];
      }
      // Every body's accelerations: Case 1's unknowns, recovered in Cases 2 and 3.
      for (std::size_t i = 0; i < maximal.size(); ++i) {
        const auto value = case_value(c, numbers, values, maximal[i].first);
        ASSERT_TRUE(value.has_value()) << where << maximal[i].first;
        EXPECT_NEAR(*value, expected[i], 1e-12 * scale) << where << maximal[i].first;
      }
    }
  }
}

std::string param_name(const testing::TestParamInfo<built::Named>& param) { return param.param.name; }

INSTANTIATE_TEST_SUITE_P(Trees, Lagrange, testing::ValuesIn(tree_mechanisms()), param_name);

}  // namespace
}  // namespace linkage
