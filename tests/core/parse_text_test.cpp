// Numbers and comma lists as people type them, with the errors every command shares.
#include "core/parse_text.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace linkage {
namespace {

Error error_of(const std::string& text) {
  try {
    (void)parse_number(text, "dt", "s");
  } catch (const Error& e) {
    return e;
  }
  return Error::input("no error");
}

TEST(ParseNumber, ReadsWholeFiniteNumbers) {
  EXPECT_EQ(parse_number("0.001", "dt", "s"), 0.001);
  EXPECT_EQ(parse_number("+1.5", "dt", "s"), 1.5);
  EXPECT_EQ(parse_number("-2e-3", "dt", "s"), -2e-3);
}

TEST(ParseNumber, RefusesWithTheSettingAndTheReason) {
  const Error word = error_of("ten");
  EXPECT_EQ(word.code(), ExitCode::bad_input);
  EXPECT_EQ(word.setting(), "dt");
  EXPECT_STREQ(word.what(), "dt: 'ten' is not a number (s)");
  EXPECT_EQ(error_of("0.1s").detail(), "'0.1s' is not a number (s)");
  EXPECT_EQ(error_of("").detail(), "'' is not a number (s)");
  EXPECT_EQ(error_of("1e999").detail(), "'1e999' is outside the range of double precision (about 1e-308 to 1e308)");
  EXPECT_EQ(error_of("inf").detail(), "'inf' is not a finite number; give a finite value in s");
  EXPECT_EQ(error_of("nan").detail(), "'nan' is not a finite number; give a finite value in s");
}

TEST(SplitCommas, KeepsEmptyItemsForTheReaderToRefuse) {
  EXPECT_EQ(split_commas(""), std::vector<std::string>{});
  EXPECT_EQ(split_commas("a"), std::vector<std::string>{"a"});
  EXPECT_EQ(split_commas("a,b,,c"), (std::vector<std::string>{"a", "b", "", "c"}));
  EXPECT_EQ(split_commas("a,"), (std::vector<std::string>{"a", ""}));
}

TEST(SplitCommas, ACommaInsideParenthesesIsAnExpressions) {
  EXPECT_EQ(split_commas("t,a=atan2(y, x),b"), (std::vector<std::string>{"t", "a=atan2(y, x)", "b"}));
  EXPECT_EQ(split_commas("f(g(1,2),3),h"), (std::vector<std::string>{"f(g(1,2),3)", "h"}));
  EXPECT_EQ(split_commas("a),b"), (std::vector<std::string>{"a)", "b"}));  // an unmatched ')' is the reader's
}

}  // namespace
}  // namespace linkage
