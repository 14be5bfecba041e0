// The adaptive methods (Dopri5, DOP853, Vern7): tolerances met against the exact Kepler orbit, dense output of
// the right order and consistent with stepping, long double, and failure reports.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrate/dop853.hpp"
#include "integrate/dopri5.hpp"
#include "integrate/kepler.hpp"
#include "integrate/vern7.hpp"

namespace linkage {
namespace {

template <class Integrator>
typename Integrator::Settings settings(double tol) {
  typename Integrator::Settings s;
  s.tolerances = {tol, tol};
  return s;
}

/// The Kepler orbit (e = 0.5) over half a period, from perihelion (the fastest, most
/// curved part) to aphelion, by dense output at t = pi: the largest error in position and
/// velocity against the exact orbit.
template <class Integrator>
void expect_tolerances_met() {
  const test::Kepler f{0.5};
  double previous = 1.0;
  for (double tol : {1e-6, 1e-8, 1e-10, 1e-12}) {
    Integrator integrator(settings<Integrator>(tol));
    integrator.start(f, 0.0, f.initial());
    while (integrator.t() < std::numbers::pi) ASSERT_EQ(integrator.step(f), ode::StepStatus::ok);
    Vec<4> y;
    integrator.dense(f, std::numbers::pi, y);
    const double error = (y - f.exact(std::numbers::pi)).cwiseAbs().maxCoeff();
    // Each accepted step's local error is within tol (|y| <= 1.7 here); half an orbit
    // amplifies them little, so their sum bounds the global error.
    const auto steps = static_cast<double>(integrator.counters().steps_accepted);
    EXPECT_LT(error, steps * tol) << "rtol = atol = " << tol << ", " << steps << " steps";
    EXPECT_LT(error, previous) << "the error shrinks with the tolerance";
    previous = error;
  }
}

TEST(Adaptive, Dopri5MeetsItsTolerance) { expect_tolerances_met<ode::Dopri5<double, 4>>(); }
TEST(Adaptive, Dop853MeetsItsTolerance) { expect_tolerances_met<ode::Dop853<double, 4>>(); }
TEST(Adaptive, Vern7MeetsItsTolerance) { expect_tolerances_met<ode::Vern7<double, 4>>(); }

/// One step of size h from (0, y0) of y' = A y (a rotation with decay, exact solution
/// known), then dense output at the middle of the step: its error against exp(A t).
template <class Integrator>
double dense_error_mid_step(double h) {
  auto f = [](double /*t*/, const Vec<2>& y, Vec<2>& dydt) { dydt << -0.1 * y[0] - y[1], y[0] - 0.1 * y[1]; };
  auto exact = [](double t) { return Vec<2>(std::exp(-0.1 * t) * std::cos(t), std::exp(-0.1 * t) * std::sin(t)); };
  typename Integrator::Settings s = settings<Integrator>(1.0);  // accept the step whatever its error
  s.first_step = h;
  Integrator integrator(s);
  integrator.start(f, 0.0, Vec<2>(1.0, 0.0));
  EXPECT_EQ(integrator.step(f), ode::StepStatus::ok);
  EXPECT_EQ(integrator.t(), h);
  Vec<2> y;
  integrator.dense(f, 0.5 * h, y);
  return (y - exact(0.5 * h)).norm();
}

/// The local error of dense output is O(h^(q+1)) for a continuous extension of order q.
template <class Integrator>
double dense_order() {
  return std::log2(dense_error_mid_step<Integrator>(0.4) / dense_error_mid_step<Integrator>(0.2));
}

TEST(Adaptive, Dopri5DenseOutputIsFourthOrder) { EXPECT_NEAR((dense_order<ode::Dopri5<double, 2>>()), 5.0, 0.3); }
TEST(Adaptive, Dop853DenseOutputIsSeventhOrder) { EXPECT_NEAR((dense_order<ode::Dop853<double, 2>>()), 8.0, 0.3); }
// Order 6 with a seventh-order defect of 2e-7 (tableau_order_test.cpp): at these steps the
// local error still falls as h^7 or faster.
TEST(Adaptive, Vern7DenseOutputIsSixthOrder) { EXPECT_GT((dense_order<ode::Vern7<double, 2>>()), 6.7); }

/// Dense output at a sample time against the same method stepping exactly to it (the
/// last step shortened with t_stop): both are accurate to the tolerance.
template <class Integrator>
void expect_dense_matches_stepping(double tol) {
  const test::Kepler f{0.5};
  const Vec<4> y0 = f.initial();
  for (double sample : {0.123, 1.0, 3.7, 7.777}) {
    Integrator dense(settings<Integrator>(tol));
    dense.start(f, 0.0, y0);
    while (dense.t() < sample) ASSERT_EQ(dense.step(f), ode::StepStatus::ok);
    Vec<4> by_dense;
    dense.dense(f, sample, by_dense);

    typename Integrator::Settings s = settings<Integrator>(tol);
    s.t_stop = sample;
    Integrator stepping(s);
    stepping.start(f, 0.0, y0);
    while (stepping.t() < sample) ASSERT_EQ(stepping.step(f), ode::StepStatus::ok);
    ASSERT_EQ(stepping.t(), sample);
    const double scale = y0.cwiseAbs().maxCoeff() + stepping.y().cwiseAbs().maxCoeff();
    EXPECT_LT((by_dense - stepping.y()).cwiseAbs().maxCoeff(), 10 * tol * scale) << "t = " << sample;
  }
}

TEST(Adaptive, Dopri5DenseOutputMatchesSteppingToTheSample) {
  expect_dense_matches_stepping<ode::Dopri5<double, 4>>(1e-8);
}
TEST(Adaptive, Dop853DenseOutputMatchesSteppingToTheSample) {
  expect_dense_matches_stepping<ode::Dop853<double, 4>>(1e-10);
}
TEST(Adaptive, Vern7DenseOutputMatchesSteppingToTheSample) {
  expect_dense_matches_stepping<ode::Vern7<double, 4>>(1e-10);
}

// The benchmark's reference runs DOP853 in long double: it must reach accuracies a
// double cannot hold. y'' = -y over 2 pi from (1, 0) comes back to (1, 0).
TEST(Adaptive, Dop853RunsInLongDouble) {
  using State2 = ode::State<long double, 2>;
  auto f = [](long double /*t*/, const State2& y, State2& dydt) { dydt << y[1], -y[0]; };
  ode::Dop853<long double, 2>::Settings s;
  s.tolerances = {1e-18L, 1e-18L};
  ode::Dop853<long double, 2> integrator(s);
  integrator.start(f, 0.0L, State2(1.0L, 0.0L));
  const long double period = 2 * std::numbers::pi_v<long double>;
  while (integrator.t() < period) ASSERT_EQ(integrator.step(f), ode::StepStatus::ok);
  State2 y;
  integrator.dense(f, period, y);
  EXPECT_LT(std::fabs(y[0] - 1.0L), 1e-16L);
  EXPECT_LT(std::fabs(y[1]), 1e-16L);
  EXPECT_GT(integrator.counters().steps_accepted, 10);
}

TEST(Adaptive, CountsStepsRejectionsAndEvaluations) {
  const test::Kepler f{0.5};
  typename ode::Dop853<double, 4>::Settings s = settings<ode::Dop853<double, 4>>(1e-10);
  s.first_step = 5.0;  // far too large: the first attempts are rejected
  ode::Dop853<double, 4> integrator(s);
  integrator.start(f, 0.0, f.initial());
  while (integrator.t() < 1.0) ASSERT_EQ(integrator.step(f), ode::StepStatus::ok);
  const ode::Counters c = integrator.counters();  // a copy: the integrator's own goes on counting
  EXPECT_GT(c.steps_rejected, 0);
  // One evaluation at the start, then 12 per attempt (the 13th is the next step's first).
  EXPECT_EQ(c.rhs_evaluations, 1 + 12 * (c.steps_accepted + c.steps_rejected));
  Vec<4> y;
  integrator.dense(f, 0.5 * (integrator.t_previous() + integrator.t()), y);
  EXPECT_EQ(integrator.counters().rhs_evaluations, c.rhs_evaluations + 3) << "dense output's three extra stages";
  integrator.dense(f, integrator.t_previous(), y);
  EXPECT_EQ(integrator.counters().rhs_evaluations, c.rhs_evaluations + 3) << "computed once per step";
}

TEST(Adaptive, Vern7CountsTenEvaluationsAStepAndFiveForDenseOutput) {
  const test::Kepler f{0.5};
  typename ode::Vern7<double, 4>::Settings s = settings<ode::Vern7<double, 4>>(1e-10);
  s.first_step = 5.0;
  ode::Vern7<double, 4> integrator(s);
  integrator.start(f, 0.0, f.initial());
  while (integrator.t() < 1.0) ASSERT_EQ(integrator.step(f), ode::StepStatus::ok);
  const ode::Counters c = integrator.counters();
  EXPECT_GT(c.steps_rejected, 0);
  // 10 stages an attempt: the eleventh, f(t + h, y1), is the next step's first.
  EXPECT_EQ(c.rhs_evaluations, 1 + 10 * (c.steps_accepted + c.steps_rejected));
  Vec<4> y;
  integrator.dense(f, 0.5 * (integrator.t_previous() + integrator.t()), y);
  EXPECT_EQ(integrator.counters().rhs_evaluations, c.rhs_evaluations + 5) << "dense output's five extra stages";
}

TEST(Adaptive, FindsItsOwnFirstStep) {
  const test::Kepler f{0.5};
  ode::Dopri5<double, 4> integrator(settings<ode::Dopri5<double, 4>>(1e-8));  // first_step = 0: automatic
  integrator.start(f, 0.0, f.initial());
  EXPECT_GT(integrator.next_step(), 0.0);
  while (integrator.t() < 2.0) ASSERT_EQ(integrator.step(f), ode::StepStatus::ok);
  Vec<4> y;
  integrator.dense(f, 2.0, y);
  EXPECT_LT((y - f.exact(2.0)).cwiseAbs().maxCoeff(), 1e-7);
}

// y' = y^2, y(0) = 1 has y = 1/(1 - t): it leaves every number at t = 1. The step
// must shrink to nothing there and be reported, not loop forever or return infinity.
TEST(Adaptive, StepUnderflowAtASingularityIsReported) {
  auto f = [](double /*t*/, const Vec<1>& y, Vec<1>& dydt) { dydt[0] = y[0] * y[0]; };
  ode::Dop853<double, 1> integrator(settings<ode::Dop853<double, 1>>(1e-8));
  integrator.start(f, 0.0, Vec<1>(1.0));
  ode::StepStatus status = ode::StepStatus::ok;
  for (int i = 0; i < 100000 && status == ode::StepStatus::ok; ++i) status = integrator.step(f);
  EXPECT_TRUE(status == ode::StepStatus::step_underflow || status == ode::StepStatus::non_finite)
      << ode::describe(status);
  EXPECT_NEAR(integrator.t(), 1.0, 1e-3);
  EXPECT_TRUE(std::isfinite(integrator.y()[0]));
}

}  // namespace
}  // namespace linkage
