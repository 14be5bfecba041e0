// Answer expressions and {{...}} placeholders over a mechanism's quotable values (the
// homework's: two-blocks.toml's by its [aliases]).
#include "lesson/expression.hpp"

#include <ginac/ginac.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "lesson/homework_names.hpp"
#include "lesson/text_template.hpp"
#include "support/test_support.hpp"

namespace linkage::lesson {
namespace {

double eval(const std::string& text, const QuotableValues& names = homework_names()) {
  return Expression::parse(text, "test", &names).evaluate();
}

std::string error_of(const std::string& text) {
  try {
    (void)Expression::parse(text, "f.toml:3:10: answer", &homework_names());
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    return e.what();
  }
  return "";
}

TEST(Expression, ArithmeticFollowsPrecedence) {
  EXPECT_DOUBLE_EQ(eval("1 + 2 * 3"), 7.0);
  EXPECT_DOUBLE_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_DOUBLE_EQ(eval("2 * -3 + 1"), -5.0);
  EXPECT_DOUBLE_EQ(eval("-2 ^ 2"), -4.0);    // unary minus binds looser than ^
  EXPECT_DOUBLE_EQ(eval("8 / 4 / 2"), 1.0);  // left-associative
  EXPECT_DOUBLE_EQ(eval("1.5e-3 * 2"), 3e-3);
  EXPECT_DOUBLE_EQ(eval("hypot(3, 4)"), 5.0);
  EXPECT_DOUBLE_EQ(eval("atan2(1, 1) * 4"), std::acos(-1.0));
  EXPECT_DOUBLE_EQ(eval("log10(1000) + pi"), 3 + std::acos(-1.0));
  EXPECT_DOUBLE_EQ(eval("asin(1) + acos(1) + atan(0) + abs(-1) + log(1)"), std::acos(-1.0) / 2 + 1);
}

TEST(Expression, QuantitiesMatchTheSpecExample) {
  const auto& derived = test::spec_example()["derived"];
  const auto& solution = test::spec_example()["solution"];
  const double tol = 1e-10;
  EXPECT_NEAR(eval("I_zz_C"), test::number(derived["I_zz_C"]), tol * 1e-3);
  EXPECT_NEAR(eval("I_zz_P"), test::number(derived["I_zz_P"]), tol * 1e-3);
  EXPECT_NEAR(eval("x_P"), test::number(derived["x_P"]), tol);
  EXPECT_NEAR(eval("y2"), test::number(derived["y2"]), tol);
  EXPECT_NEAR(eval("energy"), test::number(derived["energy"]), tol);
  EXPECT_NEAR(eval("theta1_ddot") / test::number(solution["theta1_ddot"]), 1.0, 1e-9);
  EXPECT_NEAR(eval("F_y") / test::number(solution["F_y"]), 1.0, 1e-9);
  // The parallel-axis theorem, written as a student would.
  EXPECT_NEAR(eval("I_zz_C + m * (L/2 - b)^2"), eval("I_zz_P"), 1e-18);
  EXPECT_NEAR(eval("x_com"), (1.0 + test::number(derived["x2"])) / 2, tol);
}

TEST(Expression, QuantitiesFollowTheSettings) {
  Mechanism m = load_mechanism("two-blocks");
  for (Parameter& p : m.parameters)
    if (p.name == "m") p.value = 0.2;
  EXPECT_NEAR(eval("I_zz_C", QuotableValues(std::make_shared<const sym::System>(m))), 0.2 * (0.01 + 0.09) / 12, 1e-15);
}

// Numbers and pi need no mechanism; a name does.
TEST(Expression, WithoutNamesReadsNumbersAndPi) {
  EXPECT_DOUBLE_EQ(Expression::parse("2 * pi", "t").evaluate(), 2 * std::acos(-1.0));
  EXPECT_THROW((void)Expression::parse("m", "t"), Error);
}

TEST(Expression, SingleName) {
  EXPECT_EQ(Expression::parse(" I_zz_P ", "t", &homework_names()).single_name(), "I_zz_P");
  EXPECT_EQ(homework_names().unit("I_zz_P"), "kg m^2");
  EXPECT_FALSE(Expression::parse("2 * I_zz_P", "t", &homework_names()).single_name());
}

TEST(Expression, ErrorsNameThePlaceAndSuggest) {
  const std::string unknown = error_of("I_zzP");
  EXPECT_EQ(unknown.rfind("f.toml:3:10: answer: unknown name 'I_zzP' at character 1 of 'I_zzP' (did you mean "
                          "'I_zz_P'?); valid: ",
                          0),
            0U)
      << unknown;
  EXPECT_NE(unknown.find("I_zz_C"), std::string::npos) << unknown;
  EXPECT_NE(error_of("sinn(1)").find("unknown function 'sinn' at character 1 of 'sinn(1)' (did you mean 'sin'?)"),
            std::string::npos);
  EXPECT_NE(error_of("1 / (m - m)").find("division by zero at character 3 of '1 / (m - m)'"), std::string::npos);
  EXPECT_NE(error_of("2 ^ 3 ^ 2").find("the power is too high or nested at character 7"), std::string::npos);
  EXPECT_NE(error_of("1 +").find("the expression ends too early at character 4 of '1 +'"), std::string::npos);
  EXPECT_NE(error_of("(1 + 2").find("expected ')' at character 7"), std::string::npos);
  EXPECT_NE(error_of("1 2").find("unexpected '2' at character 3"), std::string::npos);
  EXPECT_NE(error_of("hypot(1)").find("hypot takes 2 arguments, got 1"), std::string::npos);
  EXPECT_NE(error_of("").find("the expression is empty"), std::string::npos);
  EXPECT_NE(error_of(std::string(65, '(') + "1" + std::string(65, ')')).find("nested more than 64 levels deep"),
            std::string::npos);
}

TEST(TextTemplate, ReplacesPlaceholdersWithValues) {
  const QuotableValues* v = &homework_names();
  EXPECT_EQ(TextTemplate::parse("D = {{D}} m", "t", v).render(), "D = 0.11 m");
  EXPECT_EQ(TextTemplate::parse("I = {{ I_zz_P : 5 }} kg m^2", "t", v).render(), "I = 0.0020433 kg m^2");
  EXPECT_EQ(TextTemplate::parse("{{1000*I_zz_C:3}} and {{m}}", "t", v).render(), "0.833 and 0.1");
  EXPECT_EQ(TextTemplate::parse("no placeholders", "t", v).render(), "no placeholders");
}

TEST(TextTemplate, RejectsUnclosedAndBadDigits) {
  EXPECT_THROW((void)TextTemplate::parse("a {{D", "t", &homework_names()), Error);
  EXPECT_THROW((void)TextTemplate::parse("a {{D:0}}", "t", &homework_names()), Error);
  EXPECT_THROW((void)TextTemplate::parse("a {{D:x}}", "t", &homework_names()), Error);
  EXPECT_THROW((void)TextTemplate::parse("a {{Dx}}", "t", &homework_names()), Error);
}

// A placeholder that is inf or nan where the text is shown is an error naming it, its line
// and its column (in characters): the text never shows inf or nan.
TEST(TextTemplate, RefusesValuesThatAreNotFinite) {
  const auto error = [&](const std::string& text) {
    try {
      TextTemplate::parse(text, "f:3:8: text", &homework_names()).require_finite("f:3:8: text");
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::bad_input);
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("a {{1/(x1 - 1)}}"),
            "f:3:8: text: line 1, column 3: {{1/(x1 - 1)}} is inf at these inputs; text can show only "
            "finite numbers");
  const std::string second_line = error("ok {{D}}\n\u03b8 = {{sqrt(-1) : 3}}");
  EXPECT_EQ(second_line.substr(0, 51), "f:3:8: text: line 2, column 5: {{sqrt(-1) }} is nan") << second_line;
  EXPECT_NE(error("{{log(x1 - 1)}}").find("{{log(x1 - 1)}} is -inf"), std::string::npos);
  EXPECT_NE(error("{{1/0}}").find("division by zero"), std::string::npos);  // found when read
  EXPECT_EQ(error("{{D}} and {{1/g}} are finite"), "");
}

// Dotted names, with a numeric body too: "2.theta" is a name when known, "2.5" and
// "2.e5" stay numbers, and an unknown one names the nearest known name.
TEST(Expression, ReadsDottedMechanismNames) {
  const QuotableValues& names = homework_names();
  auto value = [&](const std::string& text) { return Expression::parse(text, "t", &names).evaluate(); };
  const double theta2_ddot = eval("theta2_ddot"), force_x = eval("F_x");
  EXPECT_DOUBLE_EQ(value("2.theta"), 0.2);
  EXPECT_DOUBLE_EQ(value("2*2.theta_ddot + P.force_x"), 2 * theta2_ddot + force_x);
  EXPECT_DOUBLE_EQ(value("2.5 + 2.theta"), 2.7);
  EXPECT_DOUBLE_EQ(value("2.e2"), 200.0);
  EXPECT_DOUBLE_EQ(value("2.5e1"), 25.0);
  std::string message;
  try {
    (void)Expression::parse("1 + 2.thet", "f.toml:3:10: answer", &names);
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("f.toml:3:10: answer: unknown name '2.thet' at character 5"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean '2.theta'?"), std::string::npos) << message;
  try {
    (void)Expression::parse("P.forcex", "f.toml:3:10: answer", &names);
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("unknown name 'P.forcex'"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'P.force_x'?"), std::string::npos) << message;
}

}  // namespace
}  // namespace linkage::lesson
