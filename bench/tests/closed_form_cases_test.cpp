// The three formulations: the spec's example, agreement with each other and with a
// generic solve, and the invariants the equations of motion imply.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <random>

#include "bench/closed_form/case1.hpp"
#include "bench/closed_form/case2.hpp"
#include "bench/closed_form/case3.hpp"
#include "bench/closed_form/formulation.hpp"
#include "bench/closed_form/kinematics.hpp"
#include "bench/closed_form/linear_solve.hpp"
#include "core/error.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

Params example_params() {
  const auto& p = test::spec_example()["parameters"];
  return {p["L"].get<double>(), p["w"].get<double>(), p["b"].get<double>(), p["m"].get<double>(), p["g"].get<double>()};
}

State example_state() {
  const auto& s = test::spec_example()["state"];
  return {s["x1"].get<double>(),         s["y1"].get<double>(),        s["theta1"].get<double>(),
          s["theta2"].get<double>(),     s["x1_dot"].get<double>(),    s["y1_dot"].get<double>(),
          s["theta1_dot"].get<double>(), s["theta2_dot"].get<double>()};
}

double relative_error(double got, double want) { return std::fabs(got - want) / std::fabs(want); }

TEST(Cases, ReproduceTheSpecExampleTo1e10Relative) {
  const auto& expected = test::spec_example()["solution"];
  for (int id : kCaseIds) {
    const CaseSolution solution = solve_case(id, example_params(), example_state());
    for (const auto& u : kUnknowns) {
      const Unknown unknown = static_cast<Unknown>(&u - kUnknowns.data());
      const double want = expected[std::string(u.key)].get<double>();
      const double got = solution_value(solution, unknown, example_params());
      EXPECT_LT(relative_error(got, want), 1e-10) << "case " << id << " " << u.key << " got " << got;
    }
    EXPECT_LT(solution.residual, 1e-14) << "case " << id;
  }
}

struct Sample {
  Params params;
  State state;
};

// Random states with ordinary, fast and extreme values: spins to 1e3 rad/s, masses
// from 1e-6 to 1e6 kg, the pin anywhere on the block.
std::vector<Sample> random_samples(int count) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> angle(-10.0, 10.0);
  std::vector<Sample> samples;
  for (int i = 0; i < count; ++i) {
    Params p;
    p.L = std::pow(10.0, -2.0 + 3.0 * unit(rng));
    p.w = p.L * std::pow(10.0, -2.0 + 2.0 * unit(rng));
    p.b = p.L * unit(rng);
    p.m = std::pow(10.0, -6.0 + 12.0 * unit(rng));
    p.g = 20.0 * unit(rng);
    const double spin = std::pow(10.0, -1.0 + 4.0 * unit(rng));
    State s{angle(rng),
            angle(rng),
            angle(rng),
            angle(rng),
            angle(rng),
            angle(rng),
            spin * (2 * unit(rng) - 1),
            spin * (2 * unit(rng) - 1)};
    samples.push_back({p, s});
  }
  return samples;
}

// Sizes of the terms in the accelerations, for round-off tolerances: the gravity
// scale g and the centripetal scale D (th1'^2 + th2'^2) for linear accelerations,
// divided by the length D for angular ones. Forces scale with m.
double acceleration_scale(const Params& p, const State& s) {
  return p.g + std::fabs(p.pin_offset()) * (s.theta1_dot * s.theta1_dot + s.theta2_dot * s.theta2_dot) + 1e-300;
}

double unknown_scale(Unknown u, const Params& p, const State& s) {
  const double a = acceleration_scale(p, s);
  switch (u) {
    case Unknown::theta1_ddot:
    case Unknown::theta2_ddot:
      return a / std::max(std::fabs(p.pin_offset()), p.L * 1e-3) + a / p.L;
    case Unknown::F_x:
    case Unknown::F_y:
      return p.m * a;
    case Unknown::x1_ddot:
    case Unknown::y1_ddot:
    case Unknown::x2_ddot:
    case Unknown::y2_ddot:
      return a;
  }
  return a;
}

TEST(Cases, AgreeToRoundOffAtRandomStatesIncludingFastSpinsAndExtremeMasses) {
  for (const Sample& sample : random_samples(2000)) {
    const CaseSolution c1 = solve_case(1, sample.params, sample.state);
    const CaseSolution c2 = solve_case(2, sample.params, sample.state);
    const CaseSolution c3 = solve_case(3, sample.params, sample.state);
    for (std::size_t k = 0; k < kUnknowns.size(); ++k) {
      const Unknown u = static_cast<Unknown>(k);
      const double v1 = solution_value(c1, u, sample.params);
      const double tolerance = 1e-11 * unknown_scale(u, sample.params, sample.state);
      EXPECT_NEAR(solution_value(c2, u, sample.params), v1, tolerance) << kUnknowns[k].key;
      EXPECT_NEAR(solution_value(c3, u, sample.params), v1, tolerance) << kUnknowns[k].key;
    }
  }
}

template <class Case>
void expect_block_solve_matches_generic_lu(const Sample& sample) {
  const expr::Env env = make_env(sample.params, sample.state.theta1, sample.state.theta2, sample.state.theta1_dot,
                                 sample.state.theta2_dot);
  const LinearSystem<Case> system = assemble<Case>(env);
  Vec<Case::size> q;
  ASSERT_TRUE(solve_blocks<Case>(system.A, system.B, q));
  const Vec<Case::size> reference = system.A.fullPivLu().solve(system.B);
  // Backward error of the block solve is at the level of round-off in A and B.
  const double scale = system.A.cwiseAbs().maxCoeff() * q.cwiseAbs().maxCoeff() + system.B.cwiseAbs().maxCoeff();
  EXPECT_LT((system.A * q - system.B).cwiseAbs().maxCoeff(), 1e-13 * scale);
  EXPECT_LT((system.A * reference - system.B).cwiseAbs().maxCoeff(), 1e-13 * scale);
}

TEST(Cases, BlockSolveHasRoundOffBackwardErrorLikeFullPivotLu) {
  for (const Sample& sample : random_samples(500)) {
    expect_block_solve_matches_generic_lu<Case1>(sample);
    expect_block_solve_matches_generic_lu<Case2>(sample);
    expect_block_solve_matches_generic_lu<Case3>(sample);
  }
}

// d/dt of each invariant, from the accelerations of Case 1 (maximal coordinates).
TEST(Cases, EquationsOfMotionConserveEnergyMomentumAndAngularMomentum) {
  for (const Sample& sample : random_samples(1000)) {
    const Params& p = sample.params;
    const BodyState b = body_state(p, sample.state);
    for (int id : kCaseIds) {
      const CaseSolution c = solve_case(id, p, sample.state);
      auto a = [&](Unknown u) { return solution_value(c, u, p); };
      const double I = p.inertia_centroidal();
      const double power_terms =
          p.m * (std::fabs(b.x1_dot * a(Unknown::x1_ddot)) + std::fabs(b.y1_dot * a(Unknown::y1_ddot)) +
                 std::fabs(b.x2_dot * a(Unknown::x2_ddot)) + std::fabs(b.y2_dot * a(Unknown::y2_ddot))) +
          I * (std::fabs(b.theta1_dot * a(Unknown::theta1_ddot)) + std::fabs(b.theta2_dot * a(Unknown::theta2_ddot))) +
          p.m * p.g * (std::fabs(b.y1_dot) + std::fabs(b.y2_dot));
      const double dE = p.m * (b.x1_dot * a(Unknown::x1_ddot) + b.y1_dot * a(Unknown::y1_ddot) +
                               b.x2_dot * a(Unknown::x2_ddot) + b.y2_dot * a(Unknown::y2_ddot)) +
                        I * (b.theta1_dot * a(Unknown::theta1_ddot) + b.theta2_dot * a(Unknown::theta2_ddot)) +
                        p.m * p.g * (b.y1_dot + b.y2_dot);
      EXPECT_LE(std::fabs(dE), 1e-10 * power_terms + 1e-300) << "case " << id;

      const double as = acceleration_scale(p, sample.state);
      EXPECT_NEAR(a(Unknown::x1_ddot) + a(Unknown::x2_ddot), 0.0, 1e-11 * as) << "case " << id;
      EXPECT_NEAR(a(Unknown::y1_ddot) + a(Unknown::y2_ddot), -2 * p.g, 1e-11 * as) << "case " << id;

      // H_c = m/2 d x d' + I (th1' + th2'), d = C2 - C1:  H_c' = m/2 d x d'' + I (th1'' + th2'')
      const double dx = b.x2 - b.x1, dy = b.y2 - b.y1;
      const double ddx = a(Unknown::x2_ddot) - a(Unknown::x1_ddot), ddy = a(Unknown::y2_ddot) - a(Unknown::y1_ddot);
      const double dH = 0.5 * p.m * (dx * ddy - dy * ddx) + I * (a(Unknown::theta1_ddot) + a(Unknown::theta2_ddot));
      // d'' is a difference of accelerations of size g: its round-off is relative to those.
      const double H_scale = 0.5 * p.m * std::hypot(dx, dy) *
                                 (std::fabs(a(Unknown::x1_ddot)) + std::fabs(a(Unknown::x2_ddot)) +
                                  std::fabs(a(Unknown::y1_ddot)) + std::fabs(a(Unknown::y2_ddot))) +
                             I * unknown_scale(Unknown::theta1_ddot, p, sample.state);
      EXPECT_LE(std::fabs(dH), 1e-10 * H_scale + 1e-300) << "case " << id;
    }
  }
}

TEST(Cases, SingularMatrixIsAClearError) {
  Params p;
  p.m = 0.0;  // no inertia at all: every case is singular
  try {
    (void)solve_case(1, p, State{});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::diverged);
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
}

TEST(Cases, ConditionNumberIsReportedAndGrowsWithExtremeMass) {
  Params p;
  const double ordinary = solve_case(2, p, State{}).condition_number;
  p.m = 1e6;
  const double heavy = solve_case(2, p, State{}).condition_number;
  EXPECT_GT(ordinary, 1.0);
  EXPECT_GT(heavy, 1e3 * ordinary);  // the 1/m rows of Case 2 against the m rows
}

}  // namespace
}  // namespace linkage
