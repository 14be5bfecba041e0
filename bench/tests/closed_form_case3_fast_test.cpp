// The closed-form Case 3 accelerations against the one definition (case3.hpp solved by
// the block solver), the spec's example, and its own long double evaluation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "bench/closed_form/case3.hpp"
#include "bench/closed_form/case3_fast.hpp"
#include "bench/closed_form/linear_solve.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

// Random parameters and states: lengths 1e-2..10 m, widths down to 1e-4 L, the pin
// anywhere (D from -L/2 to L/2, including near 0), masses 1e-6..1e6 kg, spins to 1e4 rad/s.
struct Sample {
  Params p;
  double th1, th2, w1, w2;
};
std::vector<Sample> random_samples(int count) {
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Sample> out;
  for (int i = 0; i < count; ++i) {
    Params p;
    p.L = std::pow(10.0, -2.0 + 3.0 * unit(rng));
    p.w = p.L * std::pow(10.0, -4.0 + 4.0 * unit(rng));
    p.b = i % 10 == 0 ? p.L / 2 - p.L * std::pow(10.0, -6.0 * unit(rng)) * 1e-2 : p.L * unit(rng);
    p.m = std::pow(10.0, -6.0 + 12.0 * unit(rng));
    p.g = 20.0 * unit(rng);
    const double spin = std::pow(10.0, -1.0 + 5.0 * unit(rng));
    out.push_back(
        {p, 20 * unit(rng) - 10, 20 * unit(rng) - 10, spin * (2 * unit(rng) - 1), spin * (2 * unit(rng) - 1)});
  }
  return out;
}

TEST(Case3Fast, MatchesTheDefinitionsBlockSolveToRoundOff) {
  for (const Sample& x : random_samples(5000)) {
    const LinearSystem<Case3> system = assemble<Case3>(make_env(x.p, x.th1, x.th2, x.w1, x.w2));
    Vec<4> want;
    ASSERT_TRUE(solve_blocks<Case3>(system.A, system.B, want));
    double got[4];
    Case3Fast<double>(x.p).accelerations(x.th1, x.th2, x.w1, x.w2, got);
    // Scales of the round-off: linear accelerations g + D w^2; angular ones k w^2 / I from
    // the spins, plus m g D / I from gravity, which cancels exactly in the closed form
    // but only to round-off in the block solve of the definition.
    const double D = std::fabs(x.p.pin_offset());
    const double I = x.p.inertia_centroidal();
    const double linear = x.p.g + D * (x.w1 * x.w1 + x.w2 * x.w2);
    const double angular = (x.w1 * x.w1 + x.w2 * x.w2) * std::min(1.0, D * D * x.p.m / I) + x.p.m * x.p.g * D / I;
    const double scales[4] = {linear, linear, angular, angular};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[i], want[i], 1e-12 * scales[i] + 1e-300) << "unknown " << i;
    // And it satisfies the definition's equations with a round-off residual.
    const Vec<4> q = Eigen::Map<const Vec<4>>(got);
    const double residual_scale =
        system.A.cwiseAbs().maxCoeff() * q.cwiseAbs().maxCoeff() + system.B.cwiseAbs().maxCoeff();
    EXPECT_LT((system.A * q - system.B).cwiseAbs().maxCoeff(), 1e-13 * residual_scale);
  }
}

TEST(Case3Fast, ReproducesTheSpecExample) {
  const auto& ex = test::spec_example();
  const auto& pj = ex["parameters"];
  const auto& sj = ex["state"];
  const auto& want = ex["solution"];
  const Params p{pj["L"].get<double>(), pj["w"].get<double>(), pj["b"].get<double>(), pj["m"].get<double>(),
                 pj["g"].get<double>()};
  double q[4];
  Case3Fast<double>(p).accelerations(sj["theta1"].get<double>(), sj["theta2"].get<double>(),
                                     sj["theta1_dot"].get<double>(), sj["theta2_dot"].get<double>(), q);
  const char* keys[4] = {"x1_ddot", "y1_ddot", "theta1_ddot", "theta2_ddot"};
  for (int i = 0; i < 4; ++i) {
    const double w = want[keys[i]].get<double>();
    EXPECT_LT(std::fabs(q[i] - w), 1e-12 * std::fabs(w)) << keys[i];
  }
}

TEST(Case3Fast, LongDoubleAgreesWithDoubleToDoubleRoundOff) {
  for (const Sample& x : random_samples(500)) {
    double qd[4];
    long double ql[4];
    Case3Fast<double>(x.p).accelerations(x.th1, x.th2, x.w1, x.w2, qd);
    Case3Fast<long double>(x.p).accelerations(x.th1, x.th2, x.w1, x.w2, ql);
    const double size = std::fabs(qd[0]) + std::fabs(qd[1]) + x.p.g;
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(qd[i], static_cast<double>(ql[i]), 1e-13 * size);
    for (int i = 2; i < 4; ++i)
      EXPECT_NEAR(qd[i], static_cast<double>(ql[i]), 1e-13 * (std::fabs(qd[2]) + std::fabs(qd[3])) + 1e-300);
  }
}

}  // namespace
}  // namespace linkage
