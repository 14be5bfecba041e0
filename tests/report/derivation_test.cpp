// The worked steps before the equations of motion: every printed formula evaluates to
// the model's value (so the text cannot drift from src/model), in its symbolic and its
// substituted spelling, and reads as a worked solution should.
#include "report/derivation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "report/ascii_math.hpp"
#include "report/notation.hpp"
#include "report/random_inputs.hpp"
#include "report/text_layout.hpp"

namespace linkage {
namespace {

WorkedSolution worked_at(const Params& p, const State& s) {
  Inputs inputs;
  for (const InputKey& key : kInputKeys) inputs.set(key, key.param != nullptr ? p.*key.param : s.*key.state, "test");
  return work_out(inputs, {});
}

std::vector<WorkedSolution> random_worked(int count) {
  std::vector<WorkedSolution> out;
  for (const test::Sample& x : test::random_samples(count, 99)) out.push_back(worked_at(x.p, x.s));
  return out;
}

// Every symbol a formula may use, by its ASCII spelling: inputs and derived quantities.
std::map<std::string, double> symbols(const std::vector<DerivationGroup>& groups, const Inputs& inputs) {
  std::map<std::string, double> table;
  for (const InputKey& key : kInputKeys) table[std::string(input_symbol(key, inputs).ascii)] = inputs.value(key);
  for (const auto& group : groups)
    for (const auto& step : group.steps) table[std::string(step.quantity.ascii)] = step.quantity.value;
  return table;
}

constexpr double kTight = 1e-12;

TEST(Derivation, EveryFormulaEvaluatesToTheModelsValue) {
  int steps = 0;
  for (const WorkedSolution& w : random_worked(100)) {
    for (const DerivationGroup& group : derivation(w)) {
      for (const DerivationStep& step : group.steps) {
        const double v = step.quantity.value;
        EXPECT_NEAR(step.formula.eval(), v, kTight * (1 + std::fabs(v))) << step.quantity.ascii;
        ++steps;
      }
    }
  }
  EXPECT_EQ(steps, 100 * 15);
}

TEST(Derivation, PrintedAsciiFormulasEvaluateToTheModelsValue) {
  for (const WorkedSolution& w : random_worked(100)) {
    const std::vector<DerivationGroup> groups = derivation(w);
    test::AsciiMath math(symbols(groups, w.inputs));
    for (const DerivationGroup& group : groups) {
      for (const DerivationStep& step : group.steps) {
        const double v = step.quantity.value;
        const std::string symbolic = strip_marks(step.formula.print(expr::Style::ascii, Spelling::symbolic, 6));
        EXPECT_NEAR(math.eval(symbolic), v, kTight * (1 + std::fabs(v))) << step.quantity.ascii << " = " << symbolic;
        // 17 significant digits substitute every value exactly.
        const std::string exact = strip_marks(step.formula.print(expr::Style::ascii, Spelling::substituted, 17));
        EXPECT_NEAR(math.eval(exact), v, kTight * (1 + std::fabs(v))) << step.quantity.ascii << " = " << exact;
      }
    }
  }
}

TEST(Derivation, SubstitutedAtSixDigitsAgreesToSixDigits) {
  const WorkedSolution w = worked_at(Params{}, State{});
  test::AsciiMath math({});
  for (const DerivationGroup& group : derivation(w)) {
    for (const DerivationStep& step : group.steps) {
      const std::string text = strip_marks(step.formula.print(expr::Style::ascii, Spelling::substituted, 6));
      const double v = step.quantity.value;
      EXPECT_NEAR(math.eval(text), v, 2e-5 * std::fabs(v)) << step.quantity.ascii << " = " << text;
    }
  }
}

TEST(Derivation, ReadsLikeTheSpecInEveryStyle) {
  const std::vector<DerivationGroup> groups = derivation(worked_at(Params{}, State{}));
  ASSERT_EQ(groups.size(), 3u);
  const DerivationStep& inertia = groups[0].steps[0];
  auto print = [](const DerivationStep& step, expr::Style style, Spelling spelling) {
    return strip_marks(step.formula.print(style, spelling, 6));
  };
  EXPECT_EQ(inertia.quantity.unicode, "I_zz^C");
  EXPECT_EQ(print(inertia, expr::Style::unicode, Spelling::symbolic), "m (w² + L²) / 12");
  EXPECT_EQ(print(inertia, expr::Style::unicode, Spelling::substituted), "0.1 × (0.1² + 0.3²) / 12");
  EXPECT_EQ(print(inertia, expr::Style::ascii, Spelling::substituted), "0.1 * (0.1^2 + 0.3^2) / 12");
  EXPECT_EQ(print(inertia, expr::Style::latex, Spelling::symbolic), "\\frac{m \\left(w^2 + L^2\\right)}{12}");
  EXPECT_EQ(print(groups[0].steps[1], expr::Style::ascii, Spelling::symbolic), "L / 2 - b");
  EXPECT_EQ(print(groups[0].steps[2], expr::Style::unicode, Spelling::symbolic), "I_zz^C + m D²");
  const DerivationStep& x2_dot = groups[1].steps[4];
  EXPECT_EQ(print(x2_dot, expr::Style::unicode, Spelling::symbolic), "ẋ₁ - D (θ̇₁ sin θ₁ + θ̇₂ sin θ₂)");
  EXPECT_EQ(print(x2_dot, expr::Style::ascii, Spelling::substituted),
            "0.15 - 0.11 * (0.35 * sin(0.1) + 0.45 * sin(0.2))");
  EXPECT_EQ(print(groups[2].steps[1], expr::Style::latex, Spelling::symbolic), "m g \\left(y_1 + y_2\\right)");
}

TEST(Derivation, NegativeValuesAreParenthesizedWhenSubstituted) {
  Params p;
  p.b = 0.25;  // D = 0.15 - 0.25 = -0.1
  State s;
  s.x1 = -1;
  const std::vector<DerivationGroup> groups = derivation(worked_at(p, s));
  const DerivationStep& pin_x = groups[1].steps[0];
  EXPECT_EQ(strip_marks(pin_x.formula.print(expr::Style::unicode, Spelling::substituted, 6)),
            "(-1) + (-0.1) × cos 0.1");
  EXPECT_EQ(strip_marks(groups[0].steps[2].formula.print(expr::Style::ascii, Spelling::substituted, 6)),
            "0.000833333 + 0.1 * (-0.1)^2");
}

}  // namespace
}  // namespace linkage
