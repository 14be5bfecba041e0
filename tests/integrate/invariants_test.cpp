// How each integrator treats the energy over long runs: the symplectic ones keep it
// bounded where RK4 drifts, on a pendulum and on the homework's two blocks (through the
// general path). The motion's exact oracles are tested on every shipped mechanism in
// mechanism_simulation_test.cpp and mechanism_columns_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "core/types.hpp"
#include "evaluate/mechanism_dynamics.hpp"
#include "integrate/explicit_rk.hpp"
#include "integrate/gauss_legendre.hpp"
#include "integrate/symplectic_euler.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

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

// The homework's blocks (two-blocks.toml, Case 3 of the general path) spinning fast
// (theta1' = 20, theta2' = -35 rad/s), without gravity so the free fall does not dominate
// the energy: a Hamiltonian that is not separable (the kinetic energy depends on the
// angles), where Gauss-Legendre is symplectic and symplectic Euler is not. Over 100 s its
// energy error stays where it was after the first few turns; RK4's grows steadily at the
// same step.
TEST(Invariants, GaussLegendreKeepsTheLinkagesEnergyBoundedWhereRk4Drifts) {
  Mechanism mechanism = load_mechanism("two-blocks");
  set_value(mechanism, "g", 0, "test");
  set_value(mechanism, "1.theta_dot", 20, "test");
  set_value(mechanism, "2.theta_dot", -35, "test");
  const sym::System system(mechanism);
  const eval::MechanismDynamics dynamics(system, CaseId::reduced);
  auto f = [&](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    EXPECT_TRUE(dynamics.derivative(t, y, dydt));
  };
  eval::MechanismSample sample;
  auto energy = [&](const Eigen::VectorXd& y) {
    dynamics.sample(0, y, sample);
    return sample.kinetic + sample.potential;
  };
  const Eigen::VectorXd y0 = dynamics.initial_state(sym::checked_initial_state(system).state);
  ASSERT_EQ(y0.size(), 8);  // x1, y1, theta1, theta2, their rates: no W, nothing does work
  const HalfErrors gl =
      energy_errors<ode::GaussLegendre2<double, Eigen::Dynamic>, Eigen::Dynamic>(f, y0, 0.01, 10000, energy);
  const HalfErrors rk4 = energy_errors<ode::Rk4<double, Eigen::Dynamic>, Eigen::Dynamic>(f, y0, 0.01, 10000, energy);
  EXPECT_LT(gl.second, 1.1 * gl.first);
  EXPECT_GT(rk4.second, 1.5 * rk4.first);
  EXPECT_LT(gl.second, 0.01 * rk4.second);
}

}  // namespace
}  // namespace linkage
