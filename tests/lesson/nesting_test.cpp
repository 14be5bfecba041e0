// Hostile nesting in lesson text: the expression and template readers accept kMaxNesting
// levels and refuse one more with one line saying where, instead of running out of stack
// (tests/report/nesting_test.cpp does the same for Markdown and LaTeX math).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "lesson/expression.hpp"
#include "lesson/homework_names.hpp"
#include "lesson/text_template.hpp"
#include "support/test_support.hpp"

namespace linkage::lesson {
namespace {

using test::repeat;

std::string error_of(const std::function<void()>& action) { return test::input_error_of(action); }

const std::string kTooDeep = "nested more than " + std::to_string(kMaxNesting) + " levels deep";

double eval(const std::string& text) { return Expression::parse(text, "t").evaluate(); }

std::string expression_error(const std::string& text) {
  return error_of([&] { (void)Expression::parse(text, "f.toml:5:10: step 1 (exercise): answer"); });
}

TEST(ExpressionNesting, TheBoundIsAcceptedAndOneLevelMoreIsNot) {
  const int n = kMaxNesting;
  EXPECT_EQ(eval(repeat("(", n) + "1" + repeat(")", n)), 1.0);
  EXPECT_EQ(eval(repeat("-", n) + "2"), 2.0);  // n is even
  EXPECT_EQ(eval(repeat("+", n) + "2"), 2.0);
  EXPECT_EQ(eval(repeat("sqrt(", n) + "1" + repeat(")", n)), 1.0);
  EXPECT_EQ(eval(repeat("1 + (", n) + "1" + repeat(")", n)), n + 1.0);
  EXPECT_EQ(eval(repeat("-(", n / 2) + "1" + repeat(")", n / 2)), 1.0);  // a sign and ( a level each
  for (const std::string& deeper :
       {repeat("(", n + 1) + "1" + repeat(")", n + 1), repeat("-", n + 1) + "1",
        repeat("sqrt(", n + 1) + "1" + repeat(")", n + 1), repeat("-(", n / 2) + "-1" + repeat(")", n / 2)}) {
    const std::string message = expression_error(deeper);
    EXPECT_EQ(message.rfind("f.toml:5:10: step 1 (exercise): answer: the expression is " + kTooDeep, 0), 0u) << message;
  }
}

TEST(ExpressionNesting, HostileExpressionsGetAShortOneLineError) {
  for (const std::string& hostile :
       {repeat("(", 100000) + "1", repeat("-", 100000) + "1", repeat("sqrt(", 20000) + "1"}) {
    const std::string message = expression_error(hostile);
    EXPECT_NE(message.find(kTooDeep), std::string::npos) << message.substr(0, 300);
    EXPECT_LT(message.size(), 300u) << message.substr(0, 300);
  }
  // A tower of powers is refused at its second ^, long text where reading passes 500 characters.
  EXPECT_NE(
      expression_error(repeat("1", 1) + repeat("^1", 100000)).find("the power is too high or nested at character 4"),
      std::string::npos);
  for (const std::string& hostile :
       {repeat("1 + ", 100000) + "1", "1" + std::string(100000, ' '), repeat("(1)*", 200)}) {
    const std::string message = expression_error(hostile);
    EXPECT_NE(message.find(" characters long; valid: at most 500"), std::string::npos) << message.substr(0, 300);
    EXPECT_LT(message.size(), 300u) << message.substr(0, 300);
  }
  // The excerpt ends at the level too many.
  EXPECT_NE(expression_error(repeat("(", 100000) + "1").find("at character 65 of '…" + repeat("(", 40) + "…'"),
            std::string::npos);
  // Arguments are counted as they come.
  const std::string many = expression_error("hypot(" + repeat("1, ", 150) + "1)");
  EXPECT_NE(many.find("hypot takes 2 arguments, got 3 at character 14 of 'hypot(1, 1, 1"), std::string::npos)
      << many.substr(0, 300);
  EXPECT_LT(many.size(), 300u);
  EXPECT_EQ(expression_error("1 +\n(").find('\n'), std::string::npos);  // one line
}

TEST(TemplateNesting, TextIsCheckedWhenParsedAndPlaceholdersKeepColumns) {
  const std::string origin = "f.toml:3:8: step 1 (say): text";
  // "{{m}} kg and $" is 14 characters: the 65th "{ " starts at column 15 + 2 * 64.
  const std::string text = "{{m}} kg and $" + repeat("{ ", 70) + "$";
  EXPECT_EQ(
      error_of([&] {
        (void)TextTemplate::parse(text, origin, &homework_names());
      }).rfind(origin + ": line 1, column " + std::to_string(15 + 2 * kMaxNesting) + ": the math is " + kTooDeep, 0),
      0u);
  EXPECT_EQ(TextTemplate::parse("{{m}} kg and $" + repeat("{ ", kMaxNesting) + "$", origin, &homework_names())
                .render()
                .substr(0, 12),
            "0.1 kg and $");
  const std::string deep_placeholder = "v = {{" + repeat("(", 100000) + "1}}";
  const std::string message = error_of([&] { (void)TextTemplate::parse(deep_placeholder, origin); });
  EXPECT_NE(message.find(kTooDeep), std::string::npos) << message.substr(0, 300);
  EXPECT_LT(message.size(), 400u);
}

}  // namespace
}  // namespace linkage::lesson
