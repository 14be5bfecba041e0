// Energy, power and momentum (symbolic/energy.hpp) against the derived cases: along the
// motion each case predicts, d(T + V)/dt equals the power P of dampers and applied loads,
// and a mechanism with nothing external keeps p and H_O. The values themselves are held
// to a spring pendulum by hand (and to the homework's closed form in
// bench/tests/general_cases_test.cpp).
#include "symbolic/energy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "model/mechanism_toml.hpp"
#include "support/mechanisms_in_code.hpp"

namespace linkage {
namespace {

using GiNaC::ex;

constexpr int kStates = 4;

/// `values` (a state) with every body's x'', y'', theta'' as case `c` gives them.
GiNaC::exmap with_accelerations(const sym::System& system, const CaseSystem& c, const GiNaC::exmap& values) {
  const CaseNumbers numbers = solve_numbers(c, values);
  GiNaC::exmap out = values;
  for (const sym::BodySystem& b : system.bodies()) {
    std::vector<GiNaC::symbol> accelerations{b.x.q_ddot, b.y.q_ddot};
    if (b.rotates) accelerations.push_back(b.theta.q_ddot);
    for (const GiNaC::symbol& a : accelerations) {
      const auto value = case_value(c, numbers, values, a);
      if (!value) throw std::logic_error("no acceleration in the case");
      out[a] = GiNaC::numeric(*value);
    }
  }
  return out;
}

std::string param_name(const testing::TestParamInfo<built::Named>& param) { return param.param.name; }

class EnergyRate : public testing::TestWithParam<built::Named> {};

// dT/dt + dV/dt = P at random states, in every case: dT/dt uses the case's accelerations,
// so a wrong mass, inertia, load or sign in the equations (or here) breaks the balance.
TEST_P(EnergyRate, EqualsThePowerOfDampersAndAppliedLoads) {
  const sym::System system(GetParam().make());
  const ex T_rate = system.time_derivative(sym::kinetic_energy(system));
  const ex V_rate = system.time_derivative(sym::potential_energy(system));
  const std::vector<sym::PowerTerm> terms = sym::nonconservative_power_terms(system);
  const ex P = sym::nonconservative_power(system);
  std::vector<CaseSystem> cases;
  for (CaseId id : kAllCases) cases.push_back(derive_case(system, id));

  std::mt19937 rng(20261123);
  double largest_power_share = 0;
  for (int k = 0; k < kStates; ++k) {
    const double t = std::uniform_real_distribution<double>(0, 5)(rng);
    const GiNaC::exmap values = state_values(system, built::random_state(system, rng), t);
    for (const CaseSystem& c : cases) {
      const GiNaC::exmap solved = with_accelerations(system, c, values);
      const double dT = value_at(T_rate, solved), dV = value_at(V_rate, solved), power = value_at(P, solved);
      double scale = std::abs(dT) + std::abs(dV);
      for (const sym::PowerTerm& term : terms) scale += std::abs(value_at(term.load * term.rate, solved));
      ASSERT_GT(scale, 1e-3) << "a state where nothing moves checks nothing";
      EXPECT_NEAR(dT + dV, power, 1e-10 * scale) << GetParam().name << ", Case " << case_number(c.id) << ", state " << k
                                                 << ": dT/dt " << dT << ", dV/dt " << dV;
      largest_power_share = std::max(largest_power_share, std::abs(power) / scale);
    }
  }
  // Where there are dampers or applied loads, their power is a real share of the balance.
  if (!terms.empty()) {
    EXPECT_GT(largest_power_share, 0.02) << GetParam().name;
  }
}

std::vector<built::Named> energy_mechanisms() {
  return {{"homework", built::homework},
          {"double_pendulum", built::double_pendulum},
          {"triple_pendulum", built::triple_pendulum},
          {"spring_pendulum", [] { return built::spring_pendulum(false); }},
          {"driven_spring_pendulum", [] { return built::spring_pendulum(true); }},
          {"double_pendulum_loaded", built::double_pendulum_loaded},
          {"cart_pendulum", built::cart_pendulum},
          {"cart_pendulum_state_loads", built::cart_pendulum_state_loads},
          {"double_pendulum_state_loads", built::double_pendulum_state_loads},
          {"arm_collar", built::arm_collar},
          {"reversed_joints", built::reversed_joints},
          {"floating_pair", built::floating_pair},
          {"floating_collar", built::floating_collar},
          {"four_bar_loaded", built::four_bar_loaded},
          {"four_bar", built::four_bar},
          {"slider_crank", built::slider_crank},
          {"shipped_slider_crank", [] { return load_mechanism("slider-crank"); }},
          {"shipped_four_bar", [] { return load_mechanism("four-bar"); }},
          {"shipped_triple_pendulum", [] { return load_mechanism("triple-pendulum"); }}};
}

INSTANTIATE_TEST_SUITE_P(Mechanisms, EnergyRate, testing::ValuesIn(energy_mechanisms()), param_name);

// Nothing external: dp/dt = 0 and dH_O/dt = 0 in every case, though the joints' springs
// and dampers and the spring between the bodies push them about.
class FreeMomentum : public testing::TestWithParam<built::Named> {};

TEST_P(FreeMomentum, StaysConstant) {
  const sym::System system(GetParam().make());
  const sym::Vec2 p = sym::linear_momentum(system);
  const ex H = sym::angular_momentum(system);
  const ex px_rate = system.time_derivative(p.x), py_rate = system.time_derivative(p.y);
  const ex H_rate = system.time_derivative(H);
  std::vector<CaseSystem> cases;
  for (CaseId id : kAllCases) cases.push_back(derive_case(system, id));
  std::mt19937 rng(7);
  for (int k = 0; k < kStates; ++k) {
    const GiNaC::exmap values = state_values(system, built::random_state(system, rng), 0);
    for (const CaseSystem& c : cases) {
      const GiNaC::exmap solved = with_accelerations(system, c, values);
      // The size of each sum's terms: m |a| per body, and m |r x a| + I |theta''|.
      double force_scale = 0, moment_scale = 0;
      for (const sym::BodySystem& b : system.bodies()) {
        const double m = value_at(b.mass, solved);
        const double x = value_at(b.x.q, solved), y = value_at(b.y.q, solved);
        const double ax = value_at(b.x.q_ddot, solved), ay = value_at(b.y.q_ddot, solved);
        force_scale += m * (std::abs(ax) + std::abs(ay));
        moment_scale += m * std::abs(x * ay - y * ax);
        if (b.rotates) moment_scale += std::abs(value_at(b.inertia * b.theta.q_ddot, solved));
      }
      ASSERT_GT(force_scale, 1e-2) << "the internal loads must accelerate the bodies";
      EXPECT_NEAR(value_at(px_rate, solved), 0, 1e-12 * force_scale) << "Case " << case_number(c.id);
      EXPECT_NEAR(value_at(py_rate, solved), 0, 1e-12 * force_scale) << "Case " << case_number(c.id);
      EXPECT_NEAR(value_at(H_rate, solved), 0, 1e-12 * moment_scale) << "Case " << case_number(c.id);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Mechanisms, FreeMomentum,
                         testing::Values(built::Named{"floating_pair", built::floating_pair},
                                         built::Named{"floating_collar", built::floating_collar}),
                         param_name);

// Under gravity the same sums change as the external loads say: dp/dt = (0, -2 m g) and
// dH_O/dt = -m g (x1 + x2), the moment of gravity about O; H_c does not change.
TEST(Momentum, HomeworkChangesByGravityAlone) {
  const sym::System system(built::homework());
  const sym::Vec2 p = sym::linear_momentum(system);
  const ex H_rate = system.time_derivative(sym::angular_momentum(system));
  const ex Hc_rate = system.time_derivative(sym::angular_momentum_about_centre(system));
  const double m = 0.1, g = 9.81;
  std::vector<CaseSystem> cases;
  for (CaseId id : kAllCases) cases.push_back(derive_case(system, id));
  std::mt19937 rng(11);
  for (int k = 0; k < kStates; ++k) {
    const GiNaC::exmap values = state_values(system, built::random_state(system, rng), 0);
    for (const CaseSystem& c : cases) {
      const GiNaC::exmap solved = with_accelerations(system, c, values);
      EXPECT_NEAR(value_at(system.time_derivative(p.x), solved), 0, 1e-12) << "Case " << case_number(c.id);
      EXPECT_NEAR(value_at(system.time_derivative(p.y), solved), -2 * m * g, 1e-12) << "Case " << case_number(c.id);
      const double x1 = value_at(system.bodies()[0].x.q, solved), x2 = value_at(system.bodies()[1].x.q, solved);
      EXPECT_NEAR(value_at(H_rate, solved), -m * g * (x1 + x2), 1e-12) << "Case " << case_number(c.id);
      // About the centre of mass gravity has no moment: H_c stays constant.
      EXPECT_NEAR(value_at(Hc_rate, solved), 0, 1e-12) << "Case " << case_number(c.id);
    }
  }
}

// A point mass at (x, y) on a spring-damper from O, driven by F0 sin(Omega t) along x:
//   T = m v^2 / 2,  V = m g y + k (l - l0)^2 / 2,  P = -c l'^2 + F0 sin(Omega t) x'.
TEST(Energy, DrivenSpringPendulumByHand) {
  const sym::System system(built::spring_pendulum(true));
  const double m = 0.5, k = 40, l0 = 0.3, c = 0.7, g = 9.81, F0 = 1.5, Omega = 2.3;
  const double x = 0.4, y = -0.5, vx = 0.3, vy = -0.7, t = 1.2;
  const sym::BodySystem& b = system.bodies()[0];
  const GiNaC::exmap state{{b.x.q, x}, {b.y.q, y}, {b.x.q_dot, vx}, {b.y.q_dot, vy}};
  const GiNaC::exmap values = state_values(system, state, t);
  const double l = std::hypot(x, y), l_dot = (x * vx + y * vy) / l;

  EXPECT_NEAR(value_at(sym::kinetic_energy(system), values), m * (vx * vx + vy * vy) / 2, 1e-15);
  EXPECT_NEAR(value_at(sym::potential_energy(system), values), m * g * y + k * (l - l0) * (l - l0) / 2, 1e-14);
  EXPECT_NEAR(value_at(sym::nonconservative_power(system), values), -c * l_dot * l_dot + F0 * std::sin(Omega * t) * vx,
              1e-14);
  EXPECT_EQ(sym::nonconservative_power_terms(system).size(), 3u);  // the damper, F_x, F_y
}

// The loaded double pendulum's torsional spring and damper, and its torque, by hand:
//   V += kt (th2 - th1 - 0.3)^2 / 2,   P = -ct (th2' - th1')^2 + tau0 cos(Omega t) th2' + F . v_T.
TEST(Energy, TorsionalSpringDamperAndTorqueByHand) {
  const sym::System system(built::double_pendulum_loaded());
  const double L1 = 0.3, L2 = 0.25, m1 = 0.2, m2 = 0.15, g = 9.81, kt = 2.5, ct = 0.4, tau0 = 0.8, Omega = 1.7;
  const double th1 = -1.1, th2 = 0.4, w1 = 0.7, w2 = -1.3, t = 0.9;
  const auto& coordinates = system.coordinates();
  ASSERT_EQ(coordinates.size(), 2u);
  const GiNaC::exmap state{{coordinates[0].symbols.q, th1},
                           {coordinates[1].symbols.q, th2},
                           {coordinates[0].symbols.q_dot, w1},
                           {coordinates[1].symbols.q_dot, w2}};
  const GiNaC::exmap values = state_values(system, state, t);
  const double y1 = L1 / 2 * std::sin(th1), y2 = L1 * std::sin(th1) + L2 / 2 * std::sin(th2);
  const double spring = kt * std::pow(th2 - th1 - 0.3, 2) / 2;
  EXPECT_NEAR(value_at(sym::potential_energy(system), values), (m1 * y1 + m2 * y2) * g + spring, 1e-14);
  // The tip T of rod 2: v = L1 w1 (-sin th1, cos th1) + L2 w2 (-sin th2, cos th2); F = (0.5 t, -0.2).
  const double vx = -L1 * w1 * std::sin(th1) - L2 * w2 * std::sin(th2);
  const double vy = L1 * w1 * std::cos(th1) + L2 * w2 * std::cos(th2);
  const double power = -ct * (w2 - w1) * (w2 - w1) + tau0 * std::cos(Omega * t) * w2 + 0.5 * t * vx - 0.2 * vy;
  EXPECT_NEAR(value_at(sym::nonconservative_power(system), values), power, 1e-14);
}

}  // namespace
}  // namespace linkage
