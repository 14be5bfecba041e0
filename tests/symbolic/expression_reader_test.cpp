// The one expression reader of mechanism files and lessons: precedence, exact numbers,
// functions, and one-line errors with the place, the nearest name and the bounds.
#include "symbolic/expression_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "support/test_support.hpp"
#include "symbolic/system.hpp"

namespace linkage::sym {
namespace {

const GiNaC::symbol kA("a"), kMass("mass");

const GiNaC::symtab& names() {
  static const GiNaC::symtab table{{"a", kA}, {"mass", kMass}, {"pi", GiNaC::Pi}};
  return table;
}

GiNaC::ex read(const std::string& text) { return read_expression(text, "m.toml:4:7", {names()}); }

// The value at a = 3, mass = 0.5.
double value(const std::string& text) {
  return evaluate(read(text), {{kA, GiNaC::numeric(3)}, {kMass, GiNaC::numeric(1, 2)}});
}

std::string error_of(const std::string& text) {
  try {
    (void)read_expression(text, "m.toml:4:7", {names(), "(t only in forces)"});
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.what();
  }
  return "";
}

using test::repeat;

TEST(ExpressionReader, ArithmeticFollowsPrecedence) {
  EXPECT_EQ(value("1 + 2 * 3"), 7.0);
  EXPECT_EQ(value("(1 + 2) * 3"), 9.0);
  EXPECT_EQ(value("-2 ^ 2"), -4.0);      // a sign binds looser than ^
  EXPECT_EQ(value("2 * -3 + 1"), -5.0);  // GiNaC's own parser says -4
  EXPECT_EQ(value("2 ^ -1 * 4"), 2.0);   // and 1/16 here
  EXPECT_EQ(value("8 / 4 / 2"), 1.0);    // left-associative
  EXPECT_EQ(value("1 - 2 - 3"), -4.0);
  EXPECT_EQ(value("a * -a + 1"), -8.0);
  EXPECT_EQ(value("+a"), 3.0);
  EXPECT_DOUBLE_EQ(value("1.5e-3 * 2"), 3e-3);
  EXPECT_DOUBLE_EQ(value("mass * a^2 / 12"), 0.375);
}

TEST(ExpressionReader, DecimalsAreExact) {
  EXPECT_EQ(read("0.08"), GiNaC::numeric(8, 100));
  EXPECT_EQ(read("1.5e-3"), GiNaC::numeric(15, 10000));
  EXPECT_EQ(read("2E2"), GiNaC::numeric(200));
  EXPECT_EQ(read(".5 + 0.1 + 0.2 - 0.3"), GiNaC::numeric(1, 2));  // no float residue
  EXPECT_TRUE((read("0.1 * a - a / 10")).is_zero());
}

TEST(ExpressionReader, Functions) {
  EXPECT_DOUBLE_EQ(value("sin(pi / 6)"), 0.5);
  EXPECT_DOUBLE_EQ(value("cos(a)"), std::cos(3.0));
  EXPECT_DOUBLE_EQ(value("tan(1)"), std::tan(1.0));
  EXPECT_DOUBLE_EQ(value("asin(mass)"), std::asin(0.5));
  EXPECT_DOUBLE_EQ(value("acos(mass)"), std::acos(0.5));
  EXPECT_DOUBLE_EQ(value("atan(a)"), std::atan(3.0));
  EXPECT_DOUBLE_EQ(value("atan2(1, 1) * 4"), std::acos(-1.0));
  EXPECT_DOUBLE_EQ(value("atan2(-a, mass)"), std::atan2(-3.0, 0.5));
  EXPECT_DOUBLE_EQ(value("sqrt(a)"), std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(value("exp(mass)"), std::exp(0.5));
  EXPECT_DOUBLE_EQ(value("log(a)"), std::log(3.0));
  EXPECT_DOUBLE_EQ(value("abs(mass - a)"), 2.5);
  EXPECT_DOUBLE_EQ(value("hypot(a, 4)"), 5.0);
  EXPECT_DOUBLE_EQ(value("log10(1000 * a)"), std::log10(3000.0));
  EXPECT_EQ(read("hypot(a, 4)"), GiNaC::sqrt(GiNaC::pow(kA, 2) + 16));  // differentiable like any sum
  EXPECT_TRUE(std::isnan(value("sqrt(-a)")));                           // not real
  EXPECT_TRUE(std::isnan(value("asin(a)")));
}

TEST(ExpressionReader, UnknownNamesAndFunctionsSuggestTheNearest) {
  EXPECT_EQ(error_of("2 * mas"),
            "m.toml:4:7: unknown name 'mas' at character 5 of '2 * mas' (did you mean 'mass'?); valid: a, mass "
            "(t only in forces)");
  EXPECT_EQ(
      error_of("I"),
      "m.toml:4:7: unknown name 'I' at character 1 of 'I' (did you mean 'pi'?); valid: a, mass (t only in forces)");
  EXPECT_EQ(error_of("1 + sinn(a)"),
            "m.toml:4:7: unknown function 'sinn' at character 5 of '1 + sinn(a)' (did you mean 'sin'?); valid: sin, "
            "cos, tan, asin, acos, atan, atan2, sqrt, exp, log, abs, hypot, log10");
  EXPECT_NE(error_of("min(1, 2)").find("unknown function 'min' at character 1"), std::string::npos);
  EXPECT_NE(error_of("hypot(1)").find("hypot takes 2 arguments, got 1 at character 9"), std::string::npos);
  EXPECT_NE(error_of("sin()").find("unexpected ')' at character 5"), std::string::npos);  // GiNaC's crashes
  EXPECT_NE(error_of("sin(1, 2)").find("sin takes 1 argument, got 2 at character 9"), std::string::npos);
}

TEST(ExpressionReader, SyntaxErrorsNameTheCharacter) {
  EXPECT_EQ(error_of("1 +"), "m.toml:4:7: the expression ends too early at character 4 of '1 +'");
  EXPECT_EQ(error_of("(1 + 2"), "m.toml:4:7: expected ')' at character 7 of '(1 + 2'");
  EXPECT_EQ(error_of("1 2"), "m.toml:4:7: unexpected '2' at character 3 of '1 2'");
  EXPECT_EQ(error_of("a)"), "m.toml:4:7: unexpected ')' at character 2 of 'a)'");
  EXPECT_EQ(error_of("{1, 2}"), "m.toml:4:7: unexpected '{' at character 1 of '{1, 2}'");
  EXPECT_EQ(error_of("  "), "m.toml:4:7: the expression is empty at character 3 of '  '");
  EXPECT_EQ(error_of("1e999"),
            "m.toml:4:7: the number '1e999' is out of range at character 1 of '1e999'; valid: powers of ten from "
            "-300 to 300");
}

// Issue 22 F06: a decimal of more digits than double holds was kept exactly, then rounded
// differently by solve and simulate (an energy error of 1.4e-4 where none should be).
TEST(ExpressionReader, DecimalsBeyondDoublePrecisionAreRefused) {
  EXPECT_EQ(error_of("0.300000000000000000001"),
            "m.toml:4:7: the number '0.300000000000000000001' has 21 significant digits, more than double precision "
            "holds at character 1 of '0.300000000000000000001'; valid: at most 17 significant digits");
  EXPECT_EQ(error_of("2 * 12345678901234567890e-5"),
            "m.toml:4:7: the number '12345678901234567890e-5' has 19 significant digits, more than double "
            "precision holds at character 5 of '2 * 12345678901234567890e-5'; valid: at most 17 significant digits");
  // Seventeen digits, and zeros that lead or trail, are fine.
  EXPECT_EQ(error_of("0.12345678901234567"), "");
  EXPECT_EQ(error_of("0.000000000000000000000001"), "");
  EXPECT_EQ(error_of("100000000000000000000000.0000"), "");
}

TEST(ExpressionReader, DivisionByZeroIsFoundWhereItIsWritten) {
  EXPECT_EQ(error_of("a / (a - a)"),
            "m.toml:4:7: division by zero at character 3 of 'a / (a - a)'; valid: an expression finite at the given "
            "values");
  EXPECT_NE(error_of("1 + log(0)").find("no value"), std::string::npos);
}

TEST(ExpressionReader, PowersAreBounded) {
  EXPECT_EQ(value("a^12"), std::pow(3.0, 12));
  EXPECT_EQ(value("2^-12"), std::ldexp(1.0, -12));
  EXPECT_EQ(value("a^(1 + 1)"), 9.0);
  EXPECT_EQ(value("2^a"), 8.0);
  const std::string bound = "; valid: exponents from -12 to 12, a name, or a group without ^";
  EXPECT_EQ(error_of("a*9^9^9"), "m.toml:4:7: the power is too high or nested at character 6 of 'a*9^9^9'" + bound);
  EXPECT_EQ(error_of("a^13"), "m.toml:4:7: the power is too high or nested at character 2 of 'a^13'" + bound);
  EXPECT_NE(error_of("a^-13").find("too high"), std::string::npos);
  EXPECT_NE(error_of("(a+1)^(2^9)").find("too high or nested"), std::string::npos);
  EXPECT_NE(error_of("2^(50 + 50)").find("too high or nested"), std::string::npos);
  EXPECT_NE(error_of("a^(sqrt(a^2))").find("too high or nested"), std::string::npos);
}

TEST(ExpressionReader, NestingAndLengthAreBounded) {
  const int n = kMaxNesting;
  EXPECT_EQ(value(repeat("(", n) + "a" + repeat(")", n)), 3.0);
  EXPECT_EQ(value(repeat("-", n) + "2"), 2.0);  // n is even
  EXPECT_EQ(value(repeat("sqrt(", n) + "1" + repeat(")", n)), 1.0);
  const std::string deep = "the expression is nested more than " + std::to_string(n) + " levels deep";
  EXPECT_EQ(error_of(repeat("(", n + 1) + "1" + repeat(")", n + 1)).rfind("m.toml:4:7: " + deep, 0), 0u);
  EXPECT_NE(error_of(repeat("-", n + 1) + "1")
                .find(deep + " (each parenthesis, call, sign and ^ is a level) at "
                             "character 65 of '…"),
            std::string::npos);
  EXPECT_NE(error_of(repeat("sin(", n + 1) + "1" + repeat(")", n + 1)).find(deep), std::string::npos);
  const std::string long_one = error_of(std::string(501, '1'));
  EXPECT_NE(long_one.find("is 501 characters long; valid: at most 500"), std::string::npos);
  EXPECT_LT(long_one.size(), 200u);
  EXPECT_EQ(value(std::string(500, '0')), 0.0);
}

// Dotted names, the body a number too, when the table holds them; numbers stay numbers,
// and a dotted name no table holds is one unknown name (not "2." and a stray word).
TEST(ExpressionReader, ReadsDottedNamesWithNumericBodies) {
  const GiNaC::symbol theta("2.theta"), force("B.force_x");
  const GiNaC::symtab table{{"2.theta", theta}, {"B.force_x", force}, {"a", kA}};
  const GiNaC::ex sum = read_expression("2.theta * 2 + B.force_x - 2.5 + 1.e1", "t", {table});
  EXPECT_DOUBLE_EQ(evaluate(sum, {{theta, GiNaC::numeric(1)}, {force, GiNaC::numeric(3)}}), 2 + 3 - 2.5 + 10);
  std::string message;
  try {
    (void)read_expression("a + 2.thta", "m.toml:4:7", {table});
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("m.toml:4:7: unknown name '2.thta' at character 5"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean '2.theta'?"), std::string::npos) << message;
  // Without such names in the table, 2.x is an unknown name and 2.5 a number as ever.
  EXPECT_NE(error_of("2.x").find("unknown name '2.x'"), std::string::npos) << error_of("2.x");
  EXPECT_DOUBLE_EQ(value("2.5 * a"), 7.5);
}

}  // namespace
}  // namespace linkage::sym
