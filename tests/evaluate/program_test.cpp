// The compiled evaluator against GiNaC's own arbitrary-precision evaluation of the same
// expressions, and the properties the integrators rely on: shared subexpressions computed
// once, one sincos per argument, integer powers multiplied out, errors at compile time,
// the same bits every run, and no allocation per run (counted by replacing operator new).
#include "evaluate/program.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/allocation_counter.hpp"

namespace linkage::eval {
namespace {

using GiNaC::ex;
using GiNaC::numeric;
using GiNaC::symbol;

std::vector<double> run(const Program& p, const std::vector<double>& inputs) {
  std::vector<double> out(p.output_count()), scratch(p.scratch_size());
  p.run(inputs.data(), out.data(), scratch.data());
  return out;
}

std::size_t count(const Program& p, Op op) {
  return static_cast<std::size_t>(std::count_if(p.instructions().begin(), p.instructions().end(),
                                                [op](const Instruction& i) { return i.op == op; }));
}

double to_double(const ex& e) {
  const ex v = e.evalf();
  if (!GiNaC::is_a<numeric>(v)) throw std::logic_error("not a number");
  return GiNaC::ex_to<numeric>(v).to_double();
}

// A first-order bound, in units of the unit roundoff, of the rounding error of
// evaluating `e` in double: a sum counts its terms' magnitudes (cancellation exposes
// their rounding errors), a function passes its argument's error on times its slope.
// For an expression without cancellation this is |e| times a small factor.
ex magnitude(const ex& e) {
  if (GiNaC::is_a<symbol>(e) || GiNaC::is_a<numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return GiNaC::abs(e);
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    const bool sum = GiNaC::is_a<GiNaC::add>(e);
    ex m = sum ? 0 : 1;
    for (std::size_t k = 0; k < e.nops(); ++k) m = sum ? m + magnitude(e.op(k)) : m * magnitude(e.op(k));
    return m;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex b = e.op(0), k = e.op(1);
    const ex relative = magnitude(b) / GiNaC::abs(b);
    if (GiNaC::is_a<numeric>(k)) return GiNaC::abs(e) * (1 + GiNaC::abs(k) * relative);
    return GiNaC::abs(e) * (1 + GiNaC::abs(k) * relative + GiNaC::abs(GiNaC::log(b)) * magnitude(k));
  }
  const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
  const ex a = e.op(0);
  if (name == "sin" || name == "cos") return GiNaC::abs(e) + magnitude(a);
  if (name == "tan") return GiNaC::abs(e) + (1 + GiNaC::pow(e, 2)) * magnitude(a);
  if (name == "exp") return GiNaC::abs(e) * (1 + magnitude(a));
  if (name == "log") return GiNaC::abs(e) + magnitude(a) / GiNaC::abs(a);
  throw std::logic_error("magnitude: " + name);
}

// Random expressions over positive symbols, shaped so that every value is finite:
// negative and fractional powers and logarithms only of bases bounded away from zero.
class RandomExpressions {
 public:
  RandomExpressions(std::uint64_t seed, std::vector<symbol> symbols) : rng_(seed), symbols_(std::move(symbols)) {}

  // Any signs: sums may cancel.
  ex any(int depth) {
    if (depth == 0 || pick(5) == 0) return pick(2) == 0 ? ex(symbol_()) : rational(false) * symbol_();
    const auto sub = [&] { return any(depth - 1); };
    const auto bounded_base = [&] { return numeric(1, 2) + GiNaC::pow(sub(), 2); };
    switch (pick(11)) {
      case 0: {
        ex s = 0;
        for (int k = 1 + pick(3); k >= 0; --k) s += rational(false) * sub();
        return s;
      }
      case 1:
        return pick(2) == 0 ? sub() * sub() : sub() * sub() * sub();
      case 2:
        return GiNaC::pow(bounded_base(), -1 - pick(3));
      case 3:
        return GiNaC::sin(sub());
      case 4:
        return GiNaC::cos(sub());
      case 5:
        return GiNaC::tan(GiNaC::sin(sub()) / 2);
      case 6:
        return GiNaC::exp(GiNaC::sin(sub()));
      case 7:
        return GiNaC::log(bounded_base());
      case 8:
        return GiNaC::pow(bounded_base(), numeric(2 * pick(4) - 3, 2));
      case 9:
        return GiNaC::pow(bounded_base(), numeric(pick(5) - 2, 3 + 2 * pick(3)));
      default:
        return GiNaC::pow(sub(), 2 + pick(3));
    }
  }

  // Positive terms only: no cancellation, so the relative error itself is small.
  ex positive(int depth) {
    if (depth == 0 || pick(5) == 0) return rational(true) * symbol_();
    const auto sub = [&] { return positive(depth - 1); };
    const auto unit = [&] { return sub() / (1 + sub()); };  // in (0, 1)
    switch (pick(8)) {
      case 0: {
        ex s = 0;
        for (int k = 1 + pick(3); k >= 0; --k) s += rational(true) * sub();
        return s;
      }
      case 1:
        return sub() * sub();
      case 2:
        return GiNaC::pow(sub(), pick(2) == 0 ? 2 + pick(2) : -1 - pick(3));
      case 3:
        return GiNaC::pow(sub(), numeric(2 * pick(4) - 3, 2));
      case 4:
        return GiNaC::pow(sub(), numeric(pick(2) == 0 ? 1 : -2, 3));
      case 5:
        return GiNaC::exp(GiNaC::sin(unit()));
      case 6:
        return 2 + GiNaC::cos(unit());
      default:
        return GiNaC::log(2 + sub());
    }
  }

  // An exact binary fraction in [0.5, 2], so GiNaC and the program see the same input.
  numeric input() { return numeric(std::uniform_int_distribution<long>(1L << 19, 1L << 21)(rng_), 1L << 20); }

 private:
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  symbol symbol_() { return symbols_[static_cast<std::size_t>(pick(static_cast<int>(symbols_.size())))]; }
  numeric rational(bool positive) {
    const numeric r(1 + pick(9), 1 + pick(7));
    return positive || pick(2) == 0 ? r : -r;
  }

  std::mt19937_64 rng_;
  std::vector<symbol> symbols_;
};

class AgainstGiNaC : public ::testing::Test {
 protected:
  void SetUp() override { GiNaC::Digits = 40; }
  void TearDown() override { GiNaC::Digits = 17; }

  // Compiles `expressions` into one program and compares every output, at `points`
  // random inputs, with GiNaC's 40-digit value: |error| <= tolerance * scale, where the
  // scale is |value| or, with `by_magnitude`, the magnitude bound above.
  void compare(const std::vector<ex>& expressions, RandomExpressions& random, bool by_magnitude, double tolerance) {
    const Program program = compile(expressions, symbols);
    for (int point = 0; point < 3; ++point) {
      GiNaC::exmap at;
      std::vector<double> inputs;
      for (const symbol& s : symbols) {
        const numeric v = random.input();
        at[s] = v;
        inputs.push_back(v.to_double());
      }
      const std::vector<double> got = run(program, inputs);
      for (std::size_t k = 0; k < expressions.size(); ++k) {
        const double want = to_double(expressions[k].subs(at));
        const double scale = by_magnitude ? to_double(magnitude(expressions[k]).subs(at)) : std::fabs(want);
        ASSERT_LE(std::fabs(got[k] - want), tolerance * scale)
            << "output " << k << ": " << expressions[k] << "\nwant " << want << ", got " << got[k];
      }
    }
  }

  std::vector<symbol> symbols{symbol("x"), symbol("y"), symbol("z"), symbol("w")};
};

TEST_F(AgainstGiNaC, RandomExpressionsWithCancellationWithinTheirRoundingBound) {
  RandomExpressions random(12, symbols);
  for (int batch = 0; batch < 40; ++batch) {
    std::vector<ex> expressions;
    for (int k = 0; k < 8; ++k) expressions.push_back(random.any(3));
    compare(expressions, random, true, 1e-13);
  }
}

TEST_F(AgainstGiNaC, RandomPositiveExpressionsToRelative1e13) {
  RandomExpressions random(34, symbols);
  for (int batch = 0; batch < 40; ++batch) {
    std::vector<ex> expressions;
    for (int k = 0; k < 8; ++k) expressions.push_back(random.positive(3));
    compare(expressions, random, false, 1e-13);
  }
}

// The homework's Case 3 A and B, one program over parameters and state.
TEST_F(AgainstGiNaC, HomeworkCase3Matrices) {
  const symbol L("L"), w("w"), b("b"), m("m"), g("g"), th1("th1"), th2("th2"), om1("om1"), om2("om2");
  const ex D = L / 2 - b, I = m * (L * L + w * w) / 12;
  const GiNaC::matrix A = {{m * D * sin(th1), -m * D * cos(th1), I, 0},
                           {m * D * sin(th2), -m * D * cos(th2), 0, I},
                           {2, 0, -D * sin(th1), -D * sin(th2)},
                           {0, 2, D * cos(th1), D * cos(th2)}};
  const GiNaC::matrix B = {{m * g * D * cos(th1)},
                           {m * g * D * cos(th2)},
                           {D * (om1 * om1 * cos(th1) + om2 * om2 * cos(th2))},
                           {D * (om1 * om1 * sin(th1) + om2 * om2 * sin(th2)) - 2 * g}};
  symbols = {L, w, b, m, g, th1, th2, om1, om2};
  std::vector<ex> entries = flatten(A);
  for (const ex& e : flatten(B)) entries.push_back(e);
  const Program program = compile(entries, symbols);
  EXPECT_EQ(count(program, Op::sincos), 2u);  // one per angle
  EXPECT_EQ(count(program, Op::sin) + count(program, Op::cos), 0u);
  RandomExpressions random(56, symbols);
  compare(entries, random, true, 1e-13);
}

// Braced lists of expressions, as the vector overload.
Program compile_in(const std::vector<ex>& outputs, const std::vector<symbol>& inputs) {
  return compile(outputs, inputs);
}

TEST(Program, SharedSubexpressionIsComputedOnce) {
  const symbol x("x"), g("g");
  const ex f = GiNaC::exp(GiNaC::sin(x) * g + GiNaC::pow(x, 2) / 3);
  const std::size_t alone = compile_in({f}, {x, g}).instruction_count();
  EXPECT_EQ(compile_in({f + f * g}, {x, g}).instruction_count(), alone + 2);  // one *, one +
  EXPECT_EQ(compile_in({f, f * g, f + f * g}, {x, g}).instruction_count(), alone + 2);
}

TEST(Program, CommonFactorsAndSignsShareTheirProduct) {
  const symbol x("x"), y("y");
  // x y once; 2 x y scales it, -x y is subtracted, not negated.
  const Program p = compile_in({x * y, 2 * x * y, 1 - x * y}, {x, y});
  EXPECT_EQ(p.instruction_count(), 3u) << p.dump();
  EXPECT_EQ(count(p, Op::neg), 0u);
  EXPECT_EQ(run(p, {3.0, 5.0}), (std::vector<double>{15.0, 30.0, -14.0}));
  // A negative coefficient is a negative constant.
  const Program scaled = compile_in({x * y, -2 * x * y}, {x, y});
  EXPECT_EQ(scaled.instruction_count(), 2u) << scaled.dump();
  EXPECT_EQ(count(scaled, Op::neg), 0u);
  EXPECT_EQ(run(scaled, {3.0, 5.0}), (std::vector<double>{15.0, -30.0}));
}

TEST(Program, NegationsAreTakenIntoSumsAndProductsWithTheSameBits) {
  const symbol x("x"), y("y"), z("z"), w("w"), s("s"), r("r");
  // s and r are each other's negation, so one of them is a negated sum (as a static
  // solve's steps are): the products and sums reading it take its sign in.
  const std::vector<Definition> definitions{{s, x - y}, {r, y - x}};
  // Sums of positive terms only: their orientation is their own (compile's canonical one).
  const std::vector<ex> outputs{s * z + w, r * z + w, s * s, 3 * r, -3 * s, w / r + z, w + r, w + s, s / x + z};
  const Program p = compile(outputs, {x, y, z, w}, definitions);
  EXPECT_EQ(count(p, Op::neg), 0u) << p.dump();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 50; ++trial) {
    const double a = u(rng), b = u(rng), c = u(rng), d = u(rng);
    const double sv = a - b, rv = b - a;
    // What the expressions say, operation by operation: the same bits.
    const std::vector<double> expected{sv * c + d, rv * c + d, sv * sv, 3 * rv,    -3 * sv,
                                       d / rv + c, d + rv,     d + sv,  sv / a + c};
    EXPECT_EQ(run(p, {a, b, c, d}), expected) << trial;
  }
}

TEST(Program, ProductsOverTheSameEarlyFactorsShareThem) {
  const symbol m("m"), d("d"), g("g"), t("t");
  // m d once, whatever order GiNaC keeps the factors in.
  const Program p =
      compile_in({m * d * GiNaC::sin(t), -m * d * GiNaC::cos(t), m * d * g * GiNaC::cos(t)}, {m, d, g, t});
  // sincos, m d, (m d) sin, (m d) cos, its negation, (m d) g, (m d g) cos
  EXPECT_EQ(p.instruction_count(), 7u) << p.dump();
  const std::vector<double> v = run(p, {2.0, 3.0, 5.0, 0.5});
  EXPECT_DOUBLE_EQ(v[0], 6.0 * std::sin(0.5));
  EXPECT_DOUBLE_EQ(v[1], -6.0 * std::cos(0.5));
  EXPECT_DOUBLE_EQ(v[2], 30.0 * std::cos(0.5));
}

TEST(Program, SinAndCosOfOneArgumentShareOneSincos) {
  const symbol x("x"), y("y");
  const Program both = compile_in({GiNaC::sin(x + y), 2 * GiNaC::cos(x + y)}, {x, y});
  EXPECT_EQ(count(both, Op::sincos), 1u) << both.dump();
  EXPECT_EQ(count(both, Op::sin) + count(both, Op::cos), 0u);
  EXPECT_EQ(both.instruction_count(), 3u);  // x + y, sincos, 2 cos
  const std::vector<double> v = run(both, {0.3, 0.4});
  EXPECT_DOUBLE_EQ(v[0], std::sin(0.7));
  EXPECT_DOUBLE_EQ(v[1], 2 * std::cos(0.7));
  EXPECT_NE(both.dump().find("sincos"), std::string::npos);

  // Different arguments: no pairing.
  const Program apart = compile_in({GiNaC::sin(x) * GiNaC::cos(y)}, {x, y});
  EXPECT_EQ(count(apart, Op::sincos), 0u);
  EXPECT_EQ(count(apart, Op::sin), 1u);
  EXPECT_EQ(count(apart, Op::cos), 1u);
}

TEST(Program, IntegerPowersAreMultipliedOut) {
  const symbol x("x");
  EXPECT_EQ(compile_in({GiNaC::pow(x, 2)}, {x}).instruction_count(), 1u);
  EXPECT_EQ(compile_in({GiNaC::pow(x, 3)}, {x}).instruction_count(), 2u);
  EXPECT_EQ(compile_in({GiNaC::pow(x, 4)}, {x}).instruction_count(), 2u);
  // x^2, x^3 = x^2 x, x^4 = x^2 x^2: the square computed once.
  const Program p = compile_in({GiNaC::pow(x, 2), GiNaC::pow(x, 3), GiNaC::pow(x, 4)}, {x});
  EXPECT_EQ(p.instruction_count(), 3u) << p.dump();
  EXPECT_EQ(count(p, Op::pow), 0u);
  const double v = 1.1;
  const double v2 = v * v;
  EXPECT_EQ(run(p, {v}), (std::vector<double>{v2, v2 * v, v2 * v2}));

  const Program inverse = compile_in({1 / x}, {x});
  EXPECT_EQ(inverse.instruction_count(), 1u);
  EXPECT_EQ(count(inverse, Op::div), 1u);
  const Program half = compile_in({GiNaC::pow(x, numeric(3, 2)), GiNaC::pow(x, numeric(-1, 2))}, {x});
  EXPECT_EQ(count(half, Op::sqrt), 1u) << half.dump();
  EXPECT_EQ(count(half, Op::pow), 0u);
  EXPECT_EQ(run(half, {2.0}), (std::vector<double>{2.0 * std::sqrt(2.0), 1.0 / std::sqrt(2.0)}));
  const Program third = compile_in({GiNaC::pow(x, numeric(1, 3))}, {x});
  EXPECT_EQ(count(third, Op::pow), 1u);
}

TEST(Program, ConstantsAreFoldedAndShared) {
  const symbol x("x");
  const Program p = compile_in({GiNaC::sqrt(ex(2)) * x, GiNaC::Pi * x, numeric(1, 4) * x, ex(7)}, {x});
  EXPECT_EQ(p.instruction_count(), 3u) << p.dump();
  const std::vector<double> v = run(p, {3.0});
  EXPECT_EQ(v[0], std::sqrt(2.0) * 3.0);
  EXPECT_DOUBLE_EQ(v[1], M_PI * 3.0);
  EXPECT_EQ(v[2], 0.75);
  EXPECT_EQ(v[3], 7.0);
}

TEST(Program, MatrixOutputsAreRowMajor) {
  const symbol x("x"), y("y");
  const GiNaC::matrix m = {{x, 2 * y}, {x * y, 1}};
  EXPECT_EQ(run(compile(m, {x, y}), {3.0, 5.0}), (std::vector<double>{3.0, 10.0, 15.0, 1.0}));
}

TEST(Program, TemporariesAreReusedOnceDead) {
  const symbol x("x");
  ex s = 0;
  for (int k = 1; k <= 40; ++k) s += GiNaC::sin(k * x) / k;
  const Program p = compile_in({s}, {x});
  EXPECT_GT(p.instruction_count(), 100u);
  // The input, the constants (k and 1/k) and a few temporaries, not one per instruction.
  EXPECT_LE(p.scratch_size(), 1 + p.constant_count() + 4) << p.dump();
  double want = 0;
  for (int k = 1; k <= 40; ++k) want += std::sin(k * 0.3) / k;
  EXPECT_NEAR(run(p, {0.3})[0], want, 1e-14);
}

TEST(Program, UnknownSymbolIsNamedAtCompileTime) {
  const symbol x("x"), stray("stray");
  try {
    (void)compile_in({x + 1, x * GiNaC::sin(stray)}, {x});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'stray' in output 1"), std::string::npos) << e.what();
  }
}

TEST(Program, BadInputsAndFunctionsAreRefused) {
  const symbol x("x");
  EXPECT_THROW((void)compile_in({x}, {x, x}), std::invalid_argument);
  EXPECT_THROW((void)compile_in({GiNaC::I * x}, {x}), std::invalid_argument);
  try {
    (void)compile_in({GiNaC::atan(x)}, {x});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("atan"), std::string::npos) << e.what();
  }
}

TEST(Program, SameInputsGiveTheSameBits) {
  const symbol x("x"), y("y");
  RandomExpressions random(78, {x, y});
  std::vector<ex> expressions;
  for (int k = 0; k < 20; ++k) expressions.push_back(random.any(4));
  const Program p = compile_in(expressions, {x, y});
  const Program again = compile_in(expressions, {x, y});
  const std::vector<double> in{0.7, 1.3};
  const std::vector<double> first = run(p, in), second = run(p, in), other = run(again, in);
  EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(first.data(), other.data(), first.size() * sizeof(double)), 0);
}

TEST(Program, StateInputsComeFromTheStateWhenGivenApart) {
  const symbol p("p"), q("q"), v("v"), t("t");
  Program program = compile_in({p * GiNaC::sin(q) + v * t, q - v}, {p, q, v, t});
  const std::uint64_t before = program.fingerprint();
  program.read_state_from(1, 2);
  EXPECT_NE(program.fingerprint(), before);  // native code made for the one is not the other's
  const std::vector<double> inputs{2.0, 0.5, -1.5, 3.0};
  const std::vector<double> apart{2.0, std::nan(""), std::nan(""), 3.0}, state{0.5, -1.5};
  std::vector<double> out(program.output_count()), scratch(program.scratch_size());
  program.run(apart.data(), state.data(), out.data(), scratch.data());
  EXPECT_EQ(out, run(program, inputs));
  EXPECT_DOUBLE_EQ(out[0], 2.0 * std::sin(0.5) - 4.5);
  EXPECT_DOUBLE_EQ(out[1], 2.0);
  EXPECT_THROW(program.read_state_from(3, 2), std::invalid_argument);
  EXPECT_THROW(program.read_state_from(5, 0), std::invalid_argument);
}

TEST(Program, RunAllocatesNothing) {
  const symbol x("x"), y("y");
  RandomExpressions random(90, {x, y});
  std::vector<ex> expressions;
  for (int k = 0; k < 20; ++k) expressions.push_back(random.any(4));
  const Program p = compile_in(expressions, {x, y});
  std::vector<double> in{0.7, 1.3}, out(p.output_count()), scratch(p.scratch_size());
  const long before = test::allocations();
  for (int k = 0; k < 100; ++k) {
    in[0] += 0.01;
    p.run(in.data(), out.data(), scratch.data());
  }
  EXPECT_EQ(test::allocations() - before, 0);
  EXPECT_GT(test::allocations(), 0);  // the counter is live: compiling allocated
}

TEST(Program, DumpNamesInputsAndOutputs) {
  const symbol x("x");
  const std::string d = compile_in({2 * x}, {x}).dump();
  EXPECT_NE(d.find("r0 = input x"), std::string::npos) << d;
  EXPECT_NE(d.find("out0 = r"), std::string::npos) << d;
}

}  // namespace
}  // namespace linkage::eval
