// The Simulation seam: the spec's reference motion for every case, the cases agreeing
// with each other, sampling rules, Case 1 stabilization, failures and option checks.
#include "integrate/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "integrate/explicit_rk.hpp"
#include "integrate/linkage_rhs.hpp"
#include "integrate/projection.hpp"
#include "integrate/reference.hpp"
#include "model/kinematics.hpp"

namespace linkage {
namespace {

SimulationOptions options(int case_id, IntegratorKind integrator, double tol = 1e-12) {
  SimulationOptions o;
  o.case_id = case_id;
  o.integrator = integrator;
  o.rtol = o.atol = tol;
  o.duration = 10.0;
  if (case_id == 1) o.stabilization = Stabilization::projection;
  return o;
}

Simulation reference_run(const SimulationOptions& o) {
  return Simulation(test::reference_params(), test::reference_initial_state(), o);
}

// The "done when" of the simulate issue, at the library level: DOP853 at 1e-12
// reproduces the 25-digit reference at 1, 2, 5 and 10 s to 1e-9 in every case.
TEST(Simulation, ReproducesTheReferenceInEveryCase) {
  for (int case_id : {1, 2, 3}) {
    Simulation sim = reference_run(options(case_id, IntegratorKind::dop853));
    for (const test::ReferenceSample& ref : test::reference_samples()) {
      const BodyState s = sim.state_at(ref.t);
      EXPECT_LT(test::state_error(s.generalized(), ref.state), 1e-9) << "Case " << case_id << ", t = " << ref.t;
      const Dynamics d = sim.dynamics(s);
      EXPECT_NEAR(d.x1_ddot, test::number(ref.values["x1_ddot"]), 1e-9);
      EXPECT_NEAR(d.y1_ddot, test::number(ref.values["y1_ddot"]), 1e-9);
      EXPECT_NEAR(d.theta1_ddot, test::number(ref.values["theta1_ddot"]), 1e-9);
      EXPECT_NEAR(d.theta2_ddot, test::number(ref.values["theta2_ddot"]), 1e-9);
      EXPECT_NEAR(d.F_x, test::number(ref.values["F_x"]), 1e-9);
      EXPECT_NEAR(d.F_y, test::number(ref.values["F_y"]), 1e-9);
      const Invariants inv = invariants(sim.params(), s);
      EXPECT_NEAR(inv.energy, test::number(ref.values["energy"]), 1e-9);
      EXPECT_NEAR(inv.angular_momentum, test::number(ref.values["angular_momentum"]), 1e-12);
    }
    EXPECT_EQ(sim.stats().force_evaluations, 4);
  }
}

TEST(Simulation, TheThreeCasesGiveTheSameTrajectory) {
  for (IntegratorKind kind : {IntegratorKind::dopri5, IntegratorKind::rk4}) {
    SimulationOptions o3 = options(3, kind, 1e-10);
    o3.dt = 0.01;
    SimulationOptions o2 = o3, o1 = o3;
    o2.case_id = 2;
    o1.case_id = 1;
    o1.stabilization = Stabilization::none;
    Simulation s3 = reference_run(o3), s2 = reference_run(o2), s1 = reference_run(o1);
    for (double t = 0; t <= 10.0; t += 0.5) {
      const BodyState a = s3.state_at(t), b = s2.state_at(t), c = s1.state_at(t);
      EXPECT_LT((a.vector() - b.vector()).cwiseAbs().maxCoeff(), 1e-8) << info(kind).name << " t = " << t;
      EXPECT_LT((a.vector() - c.vector()).cwiseAbs().maxCoeff(), 1e-8) << info(kind).name << " t = " << t;
    }
  }
}

// A fixed-step sample between grid points is a shorter step from the grid point
// before it: the same as stepping there by hand, and the grid run goes on unchanged.
TEST(Simulation, FixedStepSamplesBetweenGridPointsByAShortStep) {
  SimulationOptions o = options(3, IntegratorKind::rk4);
  o.dt = 0.1;
  Simulation sampled = reference_run(o), plain = reference_run(o);
  const BodyState mid = sampled.state_at(0.25);
  const BodyState after = sampled.state_at(0.5);
  EXPECT_EQ(after.vector(), plain.state_at(0.5).vector()) << "bit-identical grid run";

  const GeneralizedRhs<Case3> f(test::reference_params());
  ode::Rk4<double, 8> rk4;
  Vec<8> y = test::reference_initial_state().vector();
  for (double t : {0.0, 0.1}) ASSERT_EQ(rk4.step(f, t, 0.1, y), ode::StepStatus::ok);
  ASSERT_EQ(rk4.step(f, 0.2, 0.25 - 0.2, y), ode::StepStatus::ok);
  EXPECT_EQ(mid.generalized().vector(), y);
}

TEST(Simulation, SamplesAtTheStartAndTheEnd) {
  SimulationOptions o = options(3, IntegratorKind::dop853, 1e-10);
  o.duration = 2.0;
  Simulation sim = reference_run(o);
  EXPECT_EQ(sim.state_at(0.0).generalized().vector(), test::reference_initial_state().vector());
  EXPECT_LT(test::state_error(sim.state_at(2.0).generalized(), test::reference_at(2.0).state), 1e-8);
  EXPECT_THROW((void)sim.state_at(1.0), Error) << "times must not go back";
  EXPECT_THROW((void)sim.state_at(2.5), Error) << "nor past the duration";
}

TEST(Simulation, AdaptiveStepsDoNotDependOnTheSampling) {
  SimulationOptions o = options(3, IntegratorKind::dop853, 1e-10);
  Simulation sparse = reference_run(o), dense = reference_run(o);
  (void)sparse.state_at(10.0);
  for (int k = 0; k <= 1000; ++k) (void)dense.state_at(0.01 * k);
  EXPECT_EQ(sparse.stats().steps_accepted, dense.stats().steps_accepted);
  EXPECT_EQ(sparse.stats().steps_rejected, dense.stats().steps_rejected);
}

// --- Case 1 and the pin constraint --------------------------------------------------

/// The largest |C| over samples of a Case 1 run in [from, to].
double max_constraint_error(Simulation& sim, double from, double to, double every) {
  double worst = 0;
  for (double t = from; t <= to + 1e-12; t += every)
    worst = std::max(worst, constraint_error(sim.params(), sim.state_at(std::min(t, to))).position.norm());
  return worst;
}

// The linkage spinning fast (theta1' = 20, theta2' = -35 rad/s), where RK4 at
// dt = 0.01 s makes truncation errors large enough to watch the constraint drift.
Simulation fast_case1(Stabilization s) {
  SimulationOptions o;
  o.case_id = 1;
  o.integrator = IntegratorKind::rk4;
  o.dt = 0.01;
  o.duration = 40.0;
  o.stabilization = s;
  State fast = test::reference_initial_state();
  fast.theta1_dot = 20;
  fast.theta2_dot = -35;
  return Simulation(test::reference_params(), fast, o);
}

TEST(Simulation, Case1DriftsWithoutStabilization) {
  Simulation sim = fast_case1(Stabilization::none);
  const double early = max_constraint_error(sim, 0, 10, 1), late = max_constraint_error(sim, 30, 40, 1);
  EXPECT_GT(early, 1e-4);
  EXPECT_GT(late, 3 * early) << "the error in C grows with time";
}

TEST(Simulation, Case1StaysOnTheConstraintWithProjection) {
  Simulation sim = fast_case1(Stabilization::projection);
  // Positions reach ~8000 m at t = 40 s, where one unit of round-off is 1e-12 m.
  EXPECT_LT(max_constraint_error(sim, 0, 40, 0.5), 1e-11);
  EXPECT_LT(sim.stats().max_constraint_error, 1e-11);
}

// Baumgarte does not reach round-off: the stages of an explicit method leave the
// constraint by O(h^2), and the feedback turns that into an O(h^4) steady error with
// RK4. But it stays there instead of growing.
TEST(Simulation, Case1StaysBoundedWithBaumgarte) {
  Simulation none = fast_case1(Stabilization::none);
  Simulation baumgarte = fast_case1(Stabilization::baumgarte);
  const double early = max_constraint_error(baumgarte, 0, 20, 1), late = max_constraint_error(baumgarte, 20, 40, 1);
  EXPECT_LT(late, 1.5 * early) << "no growth";
  EXPECT_LT(late, 0.01 * max_constraint_error(none, 0, 40, 1)) << "far below the unstabilized drift";
}

// Baumgarte pulls a violated constraint back like a critically damped oscillator
// (alpha = beta = 10/s): an error C0 decays as (1 + 10 t) e^(-10 t) C0. This also pins
// down the sign of the added terms: the wrong sign makes the error grow instead.
TEST(Simulation, BaumgarteDampsAConstraintViolation) {
  const Params p = test::reference_params();
  const MaximalRhs f(p, 10.0, 10.0);
  Vec<12> y = body_state(p, test::reference_initial_state()).vector();
  y[3] += 1e-3;  // block 2 a millimetre off the pin
  ode::Rk4<double, 12> rk4;
  for (int k = 0; k < 1000; ++k) ASSERT_EQ(rk4.step(f, 0.001 * k, 0.001, y), ode::StepStatus::ok);
  const double expected = 1e-3 * 11.0 * std::exp(-10.0);
  const double C = constraint_error(p, BodyState::from_vector(y)).position.norm();
  EXPECT_NEAR(C, expected, 0.05 * expected);
}

TEST(Projection, ReachesRoundOffAndKeepsTheCentreOfMassAndMomentum) {
  const Params p = test::reference_params();
  BodyState s = body_state(p, test::reference_initial_state());
  s.x2 += 2e-3;
  s.y2 -= 1e-3;
  s.theta1 += 1e-3;
  s.x2_dot += 0.01;
  Vec<12> y = s.vector();
  const Invariants before = invariants(p, s);
  const ProjectionResult r = project_onto_constraint(p, y);
  const BodyState after = BodyState::from_vector(y);
  ASSERT_TRUE(r.converged);
  EXPECT_GE(r.iterations, 2);
  const ConstraintError e = constraint_error(p, after);
  EXPECT_LT(e.position.norm(), 1e-15);
  EXPECT_LT(e.velocity.norm(), 1e-15);
  EXPECT_NEAR(s.x1 + s.x2, after.x1 + after.x2, 1e-15);
  EXPECT_NEAR(s.y1 + s.y2, after.y1 + after.y2, 1e-15);
  EXPECT_NEAR(before.momentum.x(), invariants(p, after).momentum.x(), 1e-16);
  EXPECT_NEAR(before.momentum.y(), invariants(p, after).momentum.y(), 1e-16);
}

// --- failures -------------------------------------------------------------------------

/// Runs Case 1 with stiff Baumgarte gains (1e6/s) to 50 s and returns the one-line
/// message it must stop with (exit code 3).
std::string stiff_failure(IntegratorKind integrator, double dt) {
  SimulationOptions o = options(1, integrator);
  o.stabilization = Stabilization::baumgarte;
  o.baumgarte_alpha = o.baumgarte_beta = 1e6;
  o.dt = dt;
  o.duration = 50.0;
  Simulation sim = reference_run(o);
  try {
    for (int k = 0; k <= 100; ++k) (void)sim.state_at(0.5 * k);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::diverged);
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "one line";
    EXPECT_NE(m.find("t = "), std::string::npos) << m;
    return m;
  }
  ADD_FAILURE() << "expected the run to fail";
  return "";
}

// RK4 at dt = 0.01 s explodes at once.
TEST(Simulation, DivergenceStopsWithAClearMessage) {
  const std::string m = stiff_failure(IntegratorKind::rk4, 0.01);
  EXPECT_NE(m.find("step 0.01 s"), std::string::npos) << m;
  EXPECT_NE(m.find("finite"), std::string::npos) << m;
  EXPECT_NE(m.find("try a smaller step dt"), std::string::npos) << m;
}

// Gauss-Legendre's Newton iteration cannot converge at dt = 0.5 s.
TEST(Simulation, NewtonFailureStopsWithAClearMessage) {
  const std::string m = stiff_failure(IntegratorKind::gauss2, 0.5);
  EXPECT_NE(m.find("step 0.5 s"), std::string::npos) << m;
  EXPECT_NE(m.find("Newton"), std::string::npos) << m;
  EXPECT_NE(m.find("explicit integrator"), std::string::npos) << m;
}

// --- options -------------------------------------------------------------------------

// Errors are data: the setting at fault, never a flag (the CLI and lessons phrase it).
void expect_bad(SimulationOptions o, const std::string& setting) {
  try {
    o.validate();
    ADD_FAILURE() << "accepted a bad " << setting;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_EQ(e.setting(), setting) << e.what();
    EXPECT_EQ(e.detail().find("--"), std::string::npos) << e.what();
  }
}

TEST(SimulationOptions, RejectsValuesOutOfRange) {
  SimulationOptions o;
  EXPECT_NO_THROW(o.validate());
  auto with = [&](auto change) {
    SimulationOptions c;
    change(c);
    return c;
  };
  expect_bad(with([](auto& c) { c.case_id = 4; }), "case");
  expect_bad(with([](auto& c) { c.dt = 0; }), "dt");
  expect_bad(with([](auto& c) { c.dt = -1e-3; }), "dt");
  expect_bad(with([](auto& c) { c.dt = 20; }), "dt");
  expect_bad(with([](auto& c) { c.duration = 0; }), "duration");
  expect_bad(with([](auto& c) { c.duration = 2e6; }), "duration");
  expect_bad(with([](auto& c) { c.rtol = 0; }), "rtol");
  expect_bad(with([](auto& c) { c.rtol = 1e-16; }), "rtol");
  expect_bad(with([](auto& c) { c.atol = -1; }), "atol");
  expect_bad(with([](auto& c) { c.baumgarte_alpha = -1; }), "baumgarte_alpha");
  expect_bad(with([](auto& c) { c.baumgarte_beta = std::nan(""); }), "baumgarte_beta");
  expect_bad(with([](auto& c) {
               c.integrator = IntegratorKind::rk4;
               c.dt = 1e-9;
             }),
             "dt");
  EXPECT_NO_THROW(with([](auto& c) {
                    c.integrator = IntegratorKind::dop853;
                    c.dt = 1e-9;
                  }).validate())
      << "an adaptive method's first step may be tiny";
}

TEST(SimulationOptions, ParsesNamesAndListsTheValidOnes) {
  for (const IntegratorInfo& i : integrators()) EXPECT_EQ(parse_integrator(i.name, "--integrator"), i.kind);
  EXPECT_EQ(parse_stabilization("projection", "--stabilize"), Stabilization::projection);
  EXPECT_EQ(name(Stabilization::baumgarte), "baumgarte");
  try {
    (void)parse_integrator("rk45", "--integrator");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "--integrator: 'rk45' is not an integrator; valid: euler, symplectic-euler, rk4, "
              "dopri5, dop853, gauss-legendre");
  }
  EXPECT_THROW((void)parse_stabilization("baumgärte", "--stabilize"), Error);
}

}  // namespace
}  // namespace linkage
