// The static solve (evaluate/static_solve.hpp) planned from symbolic rows: which pivots it
// takes, its answer against a pivoting LU, and the pivots' verdict.
#include "evaluate/static_solve.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <random>
#include <vector>

namespace linkage::eval {
namespace {

using GiNaC::ex;

// The homework's Case 3 rows (docs/problem.md): moments about the pin, then the force
// balance of both blocks, whose 2 x1'' and 2 y1'' are state-independent pivots.
struct Homework {
  GiNaC::symbol m{"m"}, D{"D"}, I{"I"}, g{"g"}, th1{"th1"}, th2{"th2"}, w1{"w1"}, w2{"w2"};
  std::vector<ex> entries() const {
    const ex s1 = sin(th1), c1 = cos(th1), s2 = sin(th2), c2 = cos(th2);
    return {m * D * s1,
            -m * D * c1,
            I,
            0,  //
            m * D * s2,
            -m * D * c2,
            0,
            I,  //
            2,
            0,
            -D * s1,
            -D * s2,  //
            0,
            2,
            D * c1,
            D * c2,  //
            m * g * D * c1,
            m * g * D * c2,
            D * (w1 * w1 * c1 + w2 * w2 * c2),
            D * (w1 * w1 * s1 + w2 * w2 * s2) - 2 * g};
  }
  std::vector<GiNaC::symbol> inputs() const { return {m, D, I, g, th1, th2, w1, w2}; }
};

TEST(StaticSolve, HomeworkCase3EliminatesTheForceRowsThenSolvesTheSymmetricRemainder) {
  const Homework h;
  const GiNaC::exmap parameters{{h.m, 0.1}, {h.D, 0.11}, {h.I, 1.0 / 1200}, {h.g, 9.81}};
  const std::optional<StaticSolve> plan = plan_static_solve(h.entries(), 4, {h.th1, h.th2, h.w1, h.w2}, parameters);
  ASSERT_TRUE(plan.has_value());
  EXPECT_EQ(plan->fixed_pivots, 2U);  // the two 2s
  EXPECT_EQ(plan->symmetric_pivots, 2U);
  const Program p = compile(plan->outputs, h.inputs(), plan->definitions);
  const Program rows = compile(h.entries(), h.inputs());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<double> in{0.1, 0.11, 1.0 / 1200, 9.81, angle(rng), angle(rng), angle(rng), angle(rng)};
    std::vector<double> out(p.output_count()), scratch(p.scratch_size()), ab(rows.output_count()),
        scratch_rows(rows.scratch_size());
    p.run(in.data(), out.data(), scratch.data());
    rows.run(in.data(), ab.data(), scratch_rows.data());
    const Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> A(ab.data());
    const Eigen::Map<const Eigen::Vector4d> B(ab.data() + 16);
    const Eigen::Vector4d u = A.fullPivLu().solve(B);
    // cond(A) is about 2.4e3 here: 1e-12 of the largest is round-off of both solves.
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(out[k], u[k], 1e-12 * u.cwiseAbs().maxCoeff()) << trial << " " << k;
    // The reduced mass matrix is positive definite: the pivots vouch for the answer.
    EXPECT_GT(static_solve_spread(out.data() + 4, 2, 2), 0) << trial;
  }
}

TEST(StaticSolve, NoPlanWhenTheRemainderIsNotSymmetric) {
  const GiNaC::symbol x("x");
  const std::vector<ex> entries{sin(x), cos(x), -cos(x), sin(x), 1, x};
  EXPECT_FALSE(plan_static_solve(entries, 2, {x}, {}).has_value());
}

TEST(StaticSolve, PivotsOfBothSignsOrZeroOrNaNAreRefused) {
  const double definite[] = {2, 1, 0.5}, indefinite[] = {2, 1, -0.5}, zero[] = {2, 0, 1}, nan[] = {2, NAN, 1};
  EXPECT_DOUBLE_EQ(static_solve_spread(definite, 1, 2), 0.25);
  EXPECT_EQ(static_solve_spread(indefinite, 1, 2), 0);
  EXPECT_EQ(static_solve_spread(zero, 1, 2), 0);
  EXPECT_EQ(static_solve_spread(nan, 1, 2), 0);
  const double negative_definite[] = {-1, -2};  // -J M^-1 J^T: as good as positive
  EXPECT_DOUBLE_EQ(static_solve_spread(negative_definite, 0, 2), 0.5);
}

}  // namespace
}  // namespace linkage::eval
