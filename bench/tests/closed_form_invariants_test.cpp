// The exact oracles of the homework's motion (docs/errata.md), run by its closed form
// (Simulation): the centre of mass falls on a parabola, the horizontal momentum and the
// angular momentum about the centre of mass stay constant, and the energy is conserved.
#include <gtest/gtest.h>

#include <cmath>

#include "bench/closed_form/kinematics.hpp"
#include "bench/closed_form/simulation.hpp"
#include "bench/tests/spec_reference.hpp"

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

}  // namespace
}  // namespace linkage
