// Observed orders of the fixed-step methods: the error at a fixed time against the exact
// Kepler orbit, for step sizes halving; the log-log slope is the order.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "integrate/explicit_rk.hpp"
#include "integrate/gauss_legendre.hpp"
#include "integrate/kepler.hpp"
#include "integrate/symplectic_euler.hpp"

namespace linkage {
namespace {

/// Integrates the Kepler orbit (e = 0.5) from perihelion to t_end in n equal steps;
/// returns the largest error in position and velocity against the exact orbit.
template <class Stepper>
double error_at(double t_end, long n) {
  const test::Kepler f{0.5};
  Vec<4> y = f.initial();
  Stepper stepper;
  const double h = t_end / static_cast<double>(n);
  for (long k = 0; k < n; ++k) EXPECT_EQ(stepper.step(f, static_cast<double>(k) * h, h, y), ode::StepStatus::ok);
  return (y - f.exact(t_end)).cwiseAbs().maxCoeff();
}

/// Least-squares slope of log(error) against log(h).
template <class Stepper>
double observed_order(double t_end, const std::vector<long>& steps) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (long n : steps) {
    const double x = std::log(t_end / static_cast<double>(n)), y = std::log(error_at<Stepper>(t_end, n));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double k = static_cast<double>(steps.size());
  return (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

// Step sizes are chosen so the errors stay well above round-off (1e-12) and in the
// asymptotic range: 0.002 .. 0.00025 s for first order (errors 3e-2 .. 5e-4), 0.05 ..
// 0.00625 s over 1.6 orbits for fourth (errors 4e-4 .. 1e-8).
TEST(FixedStep, ExplicitEulerIsFirstOrder) {
  EXPECT_NEAR((observed_order<ode::ExplicitEuler<double, 4>>(2.0, {1000, 2000, 4000, 8000})), 1.0, 0.3);
}

TEST(FixedStep, SymplecticEulerIsFirstOrder) {
  EXPECT_NEAR((observed_order<ode::SymplecticEuler<double, 4>>(2.0, {1000, 2000, 4000, 8000})), 1.0, 0.3);
}

TEST(FixedStep, Rk4IsFourthOrder) {
  EXPECT_NEAR((observed_order<ode::Rk4<double, 4>>(10.0, {200, 400, 800, 1600})), 4.0, 0.3);
}

TEST(FixedStep, GaussLegendreIsFourthOrder) {
  EXPECT_NEAR((observed_order<ode::GaussLegendre2<double, 4>>(10.0, {200, 400, 800, 1600})), 4.0, 0.3);
}

// At h = 0.002 s fourth order puts the error near 3e-8 (1600 steps) * (1600 / 5000)^4.
TEST(FixedStep, Rk4ReachesTheExactOrbitAtSmallSteps) { EXPECT_LT((error_at<ode::Rk4<double, 4>>(10.0, 5000)), 1e-9); }

TEST(FixedStep, CountsEvaluationsAndSteps) {
  const test::Kepler f{0.5};
  Vec<4> y = f.initial();
  ode::Rk4<double, 4> rk4;
  ode::SymplecticEuler<double, 4> euler;
  Vec<4> z = y;
  for (int k = 0; k < 10; ++k) {
    ASSERT_EQ(rk4.step(f, 0.01 * k, 0.01, y), ode::StepStatus::ok);
    ASSERT_EQ(euler.step(f, 0.01 * k, 0.01, z), ode::StepStatus::ok);
  }
  EXPECT_EQ(rk4.counters().steps_accepted, 10);
  EXPECT_EQ(rk4.counters().rhs_evaluations, 40);
  EXPECT_EQ(euler.counters().rhs_evaluations, 10);
}

TEST(FixedStep, NonFiniteStateIsReported) {
  auto blow_up = [](double /*t*/, const Vec<2>& y, Vec<2>& dydt) { dydt << y[1], 1e300 * y[1] * y[1]; };
  Vec<2> y(0.0, 1e10);
  ode::Rk4<double, 2> rk4;
  EXPECT_EQ(rk4.step(blow_up, 0.0, 1.0, y), ode::StepStatus::non_finite);
  EXPECT_EQ(y, Vec<2>(0.0, 1e10)) << "a failed step leaves the state unchanged";
}

// Gauss-Legendre is implicit: when h is too large for the problem its Newton iteration
// cannot converge, and it says so instead of returning a wrong state.
TEST(FixedStep, GaussLegendreReportsNewtonFailure) {
  auto riccati = [](double /*t*/, const Vec<1>& y, Vec<1>& dydt) { dydt[0] = y[0] * y[0]; };  // y = 1/(1 - t)
  ode::GaussLegendre2<double, 1> gl;
  Vec<1> y(1.0);
  EXPECT_EQ(gl.step(riccati, 0.0, 0.1, y), ode::StepStatus::ok);
  EXPECT_NEAR(y[0], 1.0 / 0.9, 1e-5);
  y[0] = 1.0;
  EXPECT_EQ(gl.step(riccati, 0.0, 3.0, y), ode::StepStatus::newton_failed);  // past the blow-up at t = 1
  EXPECT_EQ(y[0], 1.0);
  EXPECT_GT(gl.counters().newton_iterations, 0);
}

// GL2 is exact for polynomial solutions of degree <= 4 (collocation at Gauss points):
// the centre of mass's free fall, y'' = -g, comes out to round-off at any step.
TEST(FixedStep, GaussLegendreIsExactForFreeFall) {
  auto fall = [](double /*t*/, const Vec<2>& y, Vec<2>& dydt) { dydt << y[1], -9.81; };
  ode::GaussLegendre2<double, 2> gl;
  Vec<2> y(2.0, 0.25);
  for (int k = 0; k < 10; ++k) ASSERT_EQ(gl.step(fall, 0.5 * k, 0.5, y), ode::StepStatus::ok);
  EXPECT_NEAR(y[0], 2.0 + 0.25 * 5.0 - 0.5 * 9.81 * 25.0, 1e-12);
  EXPECT_NEAR(y[1], 0.25 - 9.81 * 5.0, 1e-12);
}

}  // namespace
}  // namespace linkage
