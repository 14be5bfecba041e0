// The static solve (evaluate/static_solve.hpp) planned from symbolic rows: which pivots it
// takes, its answer against a pivoting LU, and the pivots' verdict.
#include "evaluate/static_solve.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <random>
#include <vector>

#include "symbolic/system.hpp"

namespace linkage::eval {
namespace {

using GiNaC::ex;

// A plan compiled as MechanismDynamics compiles it: its constants evaluated once at
// `parameters` and passed after `inputs`.
struct Planned {
  Program program;
  std::vector<double> constants;
};
Planned compiled(const StaticSolve& plan, std::vector<GiNaC::symbol> inputs, GiNaC::exmap parameters) {
  Planned out;
  for (const auto& [symbol, definition] : plan.constants) {
    out.constants.push_back(sym::evaluate(definition, parameters));
    parameters[symbol] = out.constants.back();
    inputs.push_back(symbol);
  }
  out.program = compile(plan.outputs, inputs, plan.definitions);
  return out;
}

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
  const Planned solve = compiled(*plan, h.inputs(), parameters);
  const Program& p = solve.program;
  const Program rows = compile(h.entries(), h.inputs());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<double> state_in{0.1, 0.11, 1.0 / 1200, 9.81, angle(rng), angle(rng), angle(rng), angle(rng)};
    std::vector<double> in = state_in;
    in.insert(in.end(), solve.constants.begin(), solve.constants.end());
    std::vector<double> out(p.output_count()), scratch(p.scratch_size()), ab(rows.output_count()),
        scratch_rows(rows.scratch_size());
    p.run(in.data(), out.data(), scratch.data());
    rows.run(state_in.data(), ab.data(), scratch_rows.data());
    const Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> A(ab.data());
    const Eigen::Map<const Eigen::Vector4d> B(ab.data() + 16);
    const Eigen::Vector4d u = A.fullPivLu().solve(B);
    // cond(A) is about 2.4e3 here: 1e-12 of the largest is round-off of both solves.
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(out[k], u[k], 1e-12 * u.cwiseAbs().maxCoeff()) << trial << " " << k;
    // The reduced mass matrix is positive definite: the pivots vouch for the answer.
    EXPECT_GT(static_solve_spread(out.data() + 4, 2, 2), 0) << trial;
  }
}

TEST(StaticSolve, HomeworkCase3PerCallCodeDividesOnce) {
  // Eliminated symbolically, the force rows leave the reduced mass matrix [I + k, k c; k c,
  // I + k] (sin^2 + cos^2 = 1), as in the closed form (bench/closed_form/case3_fast.hpp):
  // its first pivot and that pivot's inverse are constants of the run, so each call
  // divides once, by the last pivot.
  const Homework h;
  const GiNaC::exmap parameters{{h.m, 0.1}, {h.D, 0.11}, {h.I, 1.0 / 1200}, {h.g, 9.81}};
  const std::optional<StaticSolve> plan = plan_static_solve(h.entries(), 4, {h.th1, h.th2, h.w1, h.w2}, parameters);
  ASSERT_TRUE(plan.has_value());
  const Planned solve = compiled(*plan, h.inputs(), parameters);
  std::size_t divisions = 0;
  for (const Instruction& i : solve.program.instructions()) divisions += i.op == Op::div ? 1 : 0;
  EXPECT_EQ(divisions, 1U) << solve.program.dump();
  // The remainder's first pivot, I + k, is a constant: an input, not a step.
  ASSERT_EQ(plan->fixed_pivots, 2U);
  const ex first = plan->outputs[4 + 2];
  bool constant = false;
  for (const Definition& c : plan->constants) constant = constant || ex(c.first).is_equal(first);
  EXPECT_TRUE(constant) << first;
}

TEST(StaticSolve, HoistedFactorsAreTheParametersOfEachStateTermOnceUpToSign) {
  // D = L / 2 - b expanded into the rows, as the mechanism's lengths are.
  const GiNaC::symbol m("m"), L("L"), b("b"), th("th"), w("w");
  const ex D = L / 2 - b;
  const std::vector<ex> entries{GiNaC::expand(m * D * sin(th)), GiNaC::expand(-m * D * cos(th)),
                                GiNaC::expand(D * w * w * cos(th) + 2 * m * D * sin(th)), 2, 0};
  const Hoisted h = hoist_parameters(entries, {th, w});
  ASSERT_EQ(h.factors.size(), 3U);  // m D (and -m D), 2 m D, D; the numbers stay
  GiNaC::exmap back;
  for (const auto& [symbol, factor] : h.factors) back[symbol] = factor;
  for (std::size_t k = 0; k < entries.size(); ++k)
    EXPECT_TRUE(GiNaC::expand(h.entries[k].subs(back) - entries[k]).is_zero()) << k << ": " << h.entries[k];
  // The same rows get the same names whatever GiNaC's order of terms: fresh symbols made in
  // another order (other serial numbers, so another order of terms) name them alike.
  const GiNaC::symbol w2("w"), th2("th"), b2("b"), L2("L"), m2("m");
  const ex D2 = L2 / 2 - b2;
  const std::vector<ex> again{GiNaC::expand(m2 * D2 * sin(th2)), GiNaC::expand(-m2 * D2 * cos(th2)),
                              GiNaC::expand(D2 * w2 * w2 * cos(th2) + 2 * m2 * D2 * sin(th2)), 2, 0};
  const Hoisted h2 = hoist_parameters(again, {th2, w2});
  ASSERT_EQ(h2.factors.size(), h.factors.size());
  const GiNaC::exmap rename{{m2, m}, {L2, L}, {b2, b}};
  for (const auto& [symbol, factor] : h2.factors) {
    bool found = false;
    for (const auto& [s1, f1] : h.factors)
      found = found || (s1.get_name() == symbol.get_name() && GiNaC::expand(f1 - factor.subs(rename)).is_zero());
    EXPECT_TRUE(found) << symbol << " = " << factor;
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

TEST(StaticSolve, PivotCheckWithConstantsFoldedInGivesTheSpreadsVerdict) {
  // Every pivot constant or varying, at values drawn to hit each rule: zero, NaN, mixed
  // signs, a spread below round-off, and sound ones.
  std::mt19937 rng(11);
  const double values[] = {2, 0.5, -1, -3, 0, NAN, 1e-17, 7, -7e-18, INFINITY};
  std::uniform_int_distribution<std::size_t> pick(0, std::size(values) - 1);
  std::size_t accepted = 0, rejected = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const std::size_t fixed = static_cast<std::size_t>(trial % 3), symmetric = static_cast<std::size_t>(trial / 3 % 4);
    std::vector<double> pivots(fixed + symmetric);
    std::vector<std::optional<double>> known(pivots.size());
    for (std::size_t k = 0; k < pivots.size(); ++k) {
      pivots[k] = values[trial % 5 == 0 ? pick(rng) : pick(rng) % 4];  // mostly sound values
      if (rng() % 2 == 0) known[k] = pivots[k];
    }
    const bool expected = static_solve_spread(pivots.data(), fixed, symmetric) > 0;
    EXPECT_EQ(PivotCheck(fixed, known).accepts(pivots.data()), expected) << trial;
    (expected ? accepted : rejected) += 1;
  }
  EXPECT_GT(accepted, 100U);
  EXPECT_GT(rejected, 100U);
}

}  // namespace
}  // namespace linkage::eval
