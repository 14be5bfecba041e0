// The exact oracles of the motion (docs/errata.md): the centre of mass falls on a parabola,
// the horizontal momentum and the angular momentum about the centre of mass stay
// constant, and the energy is conserved; and how each integrator treats the energy
// over long runs.
#include <gtest/gtest.h>

#include <cmath>

#include "integrate/explicit_rk.hpp"
#include "integrate/gauss_legendre.hpp"
#include "integrate/linkage_rhs.hpp"
#include "integrate/reference.hpp"
#include "integrate/simulation.hpp"
#include "integrate/symplectic_euler.hpp"
#include "model/kinematics.hpp"

namespace linkage {
namespace {

SimulationOptions accurate(int case_id) {
  SimulationOptions o;
  o.case_id = case_id;
  o.integrator = IntegratorKind::dop853;
  o.rtol = o.atol = 1e-12;
  o.duration = 10.0;
  if (case_id == 1) o.stabilization = Stabilization::projection;
  return o;
}

TEST(Invariants, CentreOfMassFallsOnAParabolaAndMomentaStayConstant) {
  const Params p = test::reference_params();
  const BodyState s0 = body_state(p, test::reference_initial_state());
  const Invariants i0 = invariants(p, s0);
  const double xc0 = 0.5 * (s0.x1 + s0.x2), yc0 = 0.5 * (s0.y1 + s0.y2);
  const double vx = 0.5 * (s0.x1_dot + s0.x2_dot), vy = 0.5 * (s0.y1_dot + s0.y2_dot);
  for (int case_id : {1, 2, 3}) {
    Simulation sim(p, test::reference_initial_state(), accurate(case_id));
    for (double t = 0; t <= 10.0; t += 0.25) {
      const BodyState s = sim.state_at(t);
      const Invariants i = invariants(p, s);
      EXPECT_NEAR(0.5 * (s.x1 + s.x2), xc0 + vx * t, 1e-10) << "Case " << case_id << ", t = " << t;
      EXPECT_NEAR(0.5 * (s.y1 + s.y2), yc0 + vy * t - 0.5 * p.g * t * t, 1e-9) << "Case " << case_id << ", t = " << t;
      EXPECT_NEAR(i.momentum.x(), i0.momentum.x(), 1e-12);
      EXPECT_NEAR(i.momentum.y(), i0.momentum.y() - 2 * p.m * p.g * t, 1e-11);
      EXPECT_NEAR(i.angular_momentum, i0.angular_momentum, 1e-13);
      EXPECT_NEAR(i.energy, i0.energy, 1e-10);
    }
  }
}

TEST(Invariants, EnergyErrorShrinksWithTheTolerance) {
  for (IntegratorKind kind : {IntegratorKind::dopri5, IntegratorKind::dop853}) {
    double previous = 1.0;
    for (double tol : {1e-5, 1e-7, 1e-9, 1e-11}) {
      SimulationOptions o = accurate(3);
      o.integrator = kind;
      o.rtol = o.atol = tol;
      Simulation sim(test::reference_params(), test::reference_initial_state(), o);
      for (int k = 0; k <= 100; ++k) (void)sim.state_at(0.1 * k);
      const double error = sim.stats().max_energy_error;
      EXPECT_LT(error, previous) << info(kind).name << " rtol " << tol;
      EXPECT_LT(error, 10 * tol) << info(kind).name << " rtol " << tol;
      previous = error;
    }
  }
}

/// The largest |H - H0| over the first and over the second half of n steps of size h.
struct HalfErrors {
  double first = 0, second = 0;
};

template <class Stepper, int N, class F, class Energy>
HalfErrors energy_errors(F& f, Vec<N> y, double h, long n, Energy energy) {
  Stepper stepper;
  const double e0 = energy(y);
  HalfErrors r;
  for (long k = 0; k < n; ++k) {
    EXPECT_EQ(stepper.step(f, static_cast<double>(k) * h, h, y), ode::StepStatus::ok);
    const double e = std::fabs(energy(y) - e0);
    double& worst = k < n / 2 ? r.first : r.second;
    worst = std::max(worst, e);
  }
  return r;
}

// A pendulum, q'' = -sin q, has a separable Hamiltonian, where semi-implicit Euler is
// symplectic: its energy error oscillates at O(h) forever. RK4's is far smaller at first
// but drifts: it doubles from the first half of the run to the second.
TEST(Invariants, SymplecticMethodsKeepThePendulumsEnergyBoundedWhereRk4Drifts) {
  auto f = [](double /*t*/, const Vec<2>& y, Vec<2>& dydt) { dydt << y[1], -std::sin(y[0]); };
  auto energy = [](const Vec<2>& y) { return 0.5 * y[1] * y[1] - std::cos(y[0]); };
  const Vec<2> y0(1.0, 0.0);
  const HalfErrors euler = energy_errors<ode::SymplecticEuler<double, 2>, 2>(f, y0, 0.25, 8000, energy);
  const HalfErrors gl = energy_errors<ode::GaussLegendre2<double, 2>, 2>(f, y0, 0.25, 8000, energy);
  const HalfErrors rk4 = energy_errors<ode::Rk4<double, 2>, 2>(f, y0, 0.25, 8000, energy);
  EXPECT_LT(euler.second, 1.05 * euler.first);
  EXPECT_LT(euler.first, 0.25);  // O(h)
  EXPECT_LT(gl.second, 1.05 * gl.first);
  EXPECT_GT(rk4.second, 1.8 * rk4.first);
}

// The linkage spinning fast (theta1' = 20, theta2' = -35 rad/s), without gravity so
// the free fall does not dominate the energy: over 100 s Gauss-Legendre's energy error
// stays where it was after the first few turns, RK4's grows steadily at the same step.
TEST(Invariants, GaussLegendreKeepsTheLinkagesEnergyBoundedWhereRk4Drifts) {
  Params p = test::reference_params();
  p.g = 0;
  State s = test::reference_initial_state();
  s.theta1_dot = 20;
  s.theta2_dot = -35;
  const GeneralizedRhs<Case3> f(p);
  auto energy = [&](const Vec<8>& y) { return invariants(p, body_state(p, State::from_vector(y))).energy; };
  const HalfErrors gl = energy_errors<ode::GaussLegendre2<double, 8>, 8>(f, s.vector(), 0.01, 10000, energy);
  const HalfErrors rk4 = energy_errors<ode::Rk4<double, 8>, 8>(f, s.vector(), 0.01, 10000, energy);
  EXPECT_LT(gl.second, 1.1 * gl.first);
  EXPECT_GT(rk4.second, 1.5 * rk4.first);
  EXPECT_LT(gl.second, 0.01 * rk4.second);
}

}  // namespace
}  // namespace linkage
