// Issue 25, Deliver 5: a spring whose stiffness depends on a coordinate, against its
// generalized force derived by hand. cart_pendulum's rail runs along u = (2, 1)/sqrt(5)
// from Q = (0, 0), and its spring from A = (-0.5, -0.25) = -(sqrt(5)/4) u to the cart's C
// = s u, so the spring lies along u with length l = s + sqrt(5)/4 and rate l' = s'. With
// stiffness k (1 + s^2), rest length 0.2 and damping c (1 + th^2) (th the pole's angle) its
// tension is T = k (1 + s^2) (l - 0.2) + c (1 + th^2) s', its force on the cart -T u, and
// its generalized forces Q_s = -T, Q_th = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "evaluate/mechanism_dynamics.hpp"
#include "formulations/case_numbers.hpp"
#include "support/mechanisms_in_code.hpp"
#include "symbolic/energy.hpp"

namespace linkage {
namespace {

using GiNaC::ex;

constexpr double kK = 20, kC = 2;  // cart_pendulum's k and c

double hand_tension(double s, double s_dot, double th) {
  return kK * (1 + s * s) * (s + std::sqrt(5.0) / 4 - 0.2) + kC * (1 + th * th) * s_dot;
}

Mechanism stiffening_spring() {
  Mechanism m = built::cart_pendulum();
  m.springs = {built::spring("k1", "ground.A", "cart.C", "k*(1 + rail.s^2)", "0.2", "c*(1 + pole.theta^2)")};
  m.forces.clear();
  return m;
}

struct State {
  double s, s_dot, th, th_dot;
};

State draw(std::mt19937& rng) {
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  return {u(-0.3, 0.8), u(-2, 2), u(-M_PI, M_PI), u(-2, 2)};
}

// The System's load on the cart and the power term it works through, each read as the
// generalized force of s and theta, at random states: Q_s = -T, Q_th = 0 to 1e-12.
TEST(StateLoads, AStiffeningSpringsGeneralizedForceIsTheHandDerivedOne) {
  const sym::System system(stiffening_spring());
  const sym::GeneralizedCoordinate& s = system.coordinates()[0];
  const sym::GeneralizedCoordinate& th = system.coordinates()[1];
  ASSERT_EQ(s.coordinate.key, "rail.s");
  ASSERT_EQ(th.coordinate.key, "pole.theta");
  const auto in_q = [&](const ex& e) { return e.subs(system.lengths()).subs(system.to_generalized()); };
  // By virtual work, from the loads the Newton-Euler rows read: F . dr/dq at the point.
  ex Qs = 0, Qth = 0;
  int spring_loads = 0;
  for (const sym::Load& load : system.loads()) {
    if (load.source != "k1") continue;
    ++spring_loads;
    const ex fx = in_q(load.force.x), fy = in_q(load.force.y), x = in_q(load.point.x), y = in_q(load.point.y);
    Qs += fx * x.diff(s.symbols.q) + fy * y.diff(s.symbols.q);
    Qth += fx * x.diff(th.symbols.q) + fy * y.diff(th.symbols.q);
  }
  ASSERT_EQ(spring_loads, 1);  // the ground end takes none
  // From the power terms the energy balance and the work column use: dP/dq' at fixed load.
  ex Ps = 0, Pth = 0;
  for (const sym::PowerTerm& term : sym::nonconservative_power_terms(system)) {
    const ex rate = in_q(term.rate);
    Ps += in_q(term.load) * rate.diff(s.symbols.q_dot);
    Pth += in_q(term.load) * rate.diff(th.symbols.q_dot);
  }
  // Not a potential: V is gravity's alone.
  for (const sym::SymbolInfo& info : system.table().all()) {
    if (info.key == "k") {
      EXPECT_FALSE(sym::potential_energy(system).has(info.symbol));
    }
  }

  std::mt19937 rng(2511);
  for (int k = 0; k < 20; ++k) {
    const State x = draw(rng);
    GiNaC::exmap values = system.parameter_values();
    for (const auto& [symbol, e] : system.constants()) values[symbol] = e.subs(system.parameter_values());
    values[s.symbols.q] = x.s;
    values[s.symbols.q_dot] = x.s_dot;
    values[th.symbols.q] = x.th;
    values[th.symbols.q_dot] = x.th_dot;
    values[system.time()] = 0;
    const double T = hand_tension(x.s, x.s_dot, x.th);
    const std::string what = "s " + std::to_string(x.s) + " s' " + std::to_string(x.s_dot);
    EXPECT_NEAR(value_at(Qs, values), -T, 1e-12 * (1 + std::fabs(T))) << what;
    EXPECT_NEAR(value_at(Qth, values), 0, 1e-12 * (1 + std::fabs(T))) << what;
    EXPECT_NEAR(value_at(Ps, values), -T, 1e-12 * (1 + std::fabs(T))) << what;
    EXPECT_NEAR(value_at(Pth, values), 0, 1e-12 * (1 + std::fabs(T))) << what;
  }
}

// The motion the cases compute with the spring equals the one with the spring replaced by
// the hand-derived force -T u at C, written in rail.s, rail.s_dot and pole.theta: y' to
// 1e-12 at random states, in every case.
TEST(StateLoads, TheCasesMoveTheCartAsTheHandDerivedForceDoes) {
  Mechanism by_hand = built::cart_pendulum();
  by_hand.springs.clear();
  const std::string T = "(k*(1 + rail.s^2)*(rail.s + sqrt(5)/4 - 0.2) + c*(1 + pole.theta^2)*rail.s_dot)";
  by_hand.forces = {{"cart", "C", {built::q("-2*" + T + "/sqrt(5)"), built::q("-" + T + "/sqrt(5)")}, {}}};
  const sym::System spring(stiffening_spring()), force(by_hand);
  std::mt19937 rng(25);
  for (CaseId id : kAllCases) {
    const eval::MechanismDynamics a(spring, id), b(force, id);
    for (int k = 0; k < 6; ++k) {
      const State x = draw(rng);
      GiNaC::exmap values;
      for (const sym::System* system : {&spring, &force}) {
        values[system->coordinates()[0].symbols.q] = x.s;
        values[system->coordinates()[0].symbols.q_dot] = x.s_dot;
        values[system->coordinates()[1].symbols.q] = x.th;
        values[system->coordinates()[1].symbols.q_dot] = x.th_dot;
      }
      Eigen::VectorXd ya = a.initial_state(values), yb = b.initial_state(values), da, db;
      ASSERT_TRUE(a.derivative(0.3, ya, da));
      ASSERT_TRUE(b.derivative(0.3, yb, db));
      ASSERT_EQ(da.size(), db.size());
      const double scale = 1 + db.cwiseAbs().maxCoeff();
      for (Eigen::Index i = 0; i < da.size(); ++i)
        EXPECT_NEAR(da[i], db[i], 1e-12 * scale) << "Case " << case_number(id) << " entry " << i << " state " << k;
      EXPECT_GT(std::fabs(da[da.size() - 1]), 1e-3) << "the spring's power must not vanish";
    }
  }
}

}  // namespace
}  // namespace linkage
