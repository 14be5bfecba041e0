// Hostile nesting in Markdown text: the readers of LaTeX math and of Markdown lists, quotes
// and spans accept kMaxNesting levels and refuse one more with one line saying where,
// instead of running out of stack.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "report/markdown.hpp"
#include "report/unicode_tex.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

using test::repeat;

std::string error_of(const std::function<void()>& action) { return test::input_error_of(action); }

const std::string kTooDeep = "nested more than " + std::to_string(kMaxNesting) + " levels deep";

// Where latex_to_unicode stopped, as an offset into its input; -1 when it did not.
long nesting_error_offset(const std::string& latex) {
  try {
    (void)latex_to_unicode(latex);
  } catch (const LatexNestingError& e) {
    EXPECT_NE(std::string(e.what()).find(kTooDeep), std::string::npos) << e.what();
    return e.at() - latex.data();
  }
  return -1;
}

TEST(LatexNesting, TheBoundIsAcceptedAndOneLevelMoreIsNot) {
  const int n = kMaxNesting;
  const std::string roots = repeat("√(", n - 1) + "√x" + repeat(")", n - 1);
  EXPECT_EQ(latex_to_unicode(repeat("\\sqrt{", n) + "x" + repeat("}", n)), roots);
  EXPECT_EQ(latex_to_unicode(repeat("{", n) + "x" + repeat("}", n)), "x");
  EXPECT_EQ(latex_to_unicode(repeat("\\sqrt", n) + " x"), roots);
  EXPECT_NO_THROW((void)latex_to_unicode(repeat("\\frac{", n) + "1" + repeat("}{2}", n)));
  EXPECT_NO_THROW((void)latex_to_unicode("a" + repeat("^", n) + "2"));
  // One more: stopped at the level too many (its brace, or the argument it starts).
  EXPECT_EQ(nesting_error_offset(repeat("\\sqrt{", n + 1) + "x" + repeat("}", n + 1)), 6 * n + 5);
  EXPECT_EQ(nesting_error_offset(repeat("{", n + 1) + "x" + repeat("}", n + 1)), n);
  EXPECT_EQ(nesting_error_offset("a" + repeat("^", n + 1) + "2"), n + 2);  // the last ^'s argument
  EXPECT_EQ(nesting_error_offset("a" + repeat("_", n + 1) + "2"), n + 2);
  EXPECT_EQ(nesting_error_offset(repeat("\\frac{", n + 1) + "1" + repeat("}{2}", n + 1)), 6 * n + 5);
}

TEST(LatexNesting, HostileMathIsRefusedInsteadOfOverflowingTheStack) {
  EXPECT_GT(nesting_error_offset(repeat("\\sqrt{", 20000)), 0);
  EXPECT_GT(nesting_error_offset("x" + repeat("^", 50000)), 0);
  EXPECT_GT(nesting_error_offset(repeat("{", 100000)), 0);
  EXPECT_GT(nesting_error_offset(repeat("\\dot", 100000) + "x"), 0);
}

TEST(MarkdownNesting, ErrorsGiveTheLineAndColumnOfTheText) {
  // Inline math in a paragraph joined from two lines, after a two-byte character: the
  // 65th brace is on line 4, after "  θ $" and 64 braces.
  const std::string inline_math = "Intro.\n\nSecond paragraph\n  θ $" + repeat("{", 70) + "$ ends.\n";
  EXPECT_EQ(error_of([&] { (void)markdown_to_text(inline_math, 80); }),
            "line 4, column " + std::to_string(5 + kMaxNesting + 1) + ": the math is " + kTooDeep +
                " (each {...} and each argument of \\sqrt, \\frac, ^ or _ is a level)");
  // A math block: the 65th \sqrt's brace, on the block's second line.
  const std::string block = "Text.\n\n$$\nx = 1\n" + repeat("\\sqrt{", 70) + "\n$$\n";
  EXPECT_EQ(error_of([&] {
              (void)markdown_to_text(block, 80);
            }).rfind("line 5, column " + std::to_string(6 * kMaxNesting + 6) + ": ", 0),
            0u);
  // In a list item, a quote and a table cell too.
  for (const std::string prefix : {"- ", "> ", "| a | "}) {
    const std::string message =
        error_of([&] { (void)markdown_to_text("\n" + prefix + "$" + repeat("\\sqrt", 99) + "$", 80); });
    // The 65th level is the argument of the 65th \sqrt: the 66th.
    EXPECT_EQ(message.rfind("line 2, column " + std::to_string(prefix.size() + 2 + 5 * (kMaxNesting + 1)) + ": ", 0),
              0u)
        << message;
  }
  // check_markdown says where the text came from.
  EXPECT_EQ(error_of([&] {
              check_markdown("$" + repeat("{", 99) + "$", "f.toml:3:8: step 2 (render): caption");
            }).rfind("f.toml:3:8: step 2 (render): caption: line 1, column 66: the math is " + kTooDeep, 0),
            0u);
  EXPECT_NO_THROW(check_markdown("$" + repeat("{", kMaxNesting) + "$ and\n\n$" + repeat("{", kMaxNesting) + "$", "f"));
}

TEST(MarkdownNesting, ListsAndQuotesNestAsDeepAsTheBound) {
  std::string list;
  for (int i = 1; i <= kMaxNesting; ++i) list += std::string(2 * i - 2, ' ') + "- level " + std::to_string(i) + "\n";
  const std::string text = markdown_to_text(list, 300);
  EXPECT_NE(text.find("\n" + std::string(2 * kMaxNesting, ' ') + "- level " + std::to_string(kMaxNesting) + "\n"),
            std::string::npos)
      << text;
  // One level more: refused at its text ("level" after 2 * 64 spaces and "- ").
  EXPECT_EQ(error_of([&] { (void)markdown_to_text(list + std::string(2 * kMaxNesting, ' ') + "- level 65", 80); }),
            "line " + std::to_string(kMaxNesting + 1) + ", column " + std::to_string(2 * kMaxNesting + 3) +
                ": lists and quotes are " + kTooDeep);
  EXPECT_NE(error_of([&] { (void)markdown_to_text(repeat("- ", 100000) + "x", 80); }).find(kTooDeep),
            std::string::npos);
  // Quotes nest as CommonMark says (">>>" is three deep), to the same bound.
  EXPECT_EQ(markdown_to_text(">>> hi", 80), "  | | | hi\n");
  EXPECT_NO_THROW((void)markdown_to_text(repeat(">", kMaxNesting) + " hi", 80));
  EXPECT_EQ(error_of([&] { (void)markdown_to_text(repeat(">", kMaxNesting + 1) + " hi", 80); }),
            "line 1, column " + std::to_string(kMaxNesting + 3) + ": lists and quotes are " + kTooDeep);
  EXPECT_NE(error_of([&] { (void)markdown_to_text(repeat(">", 100000), 80); }).find(kTooDeep), std::string::npos);
}

// md4c parses any nesting without recursing; the renderers follow emphasis and links
// only kMaxNesting spans deep.
TEST(MarkdownNesting, SpansNestAsDeepAsTheBound) {
  const auto nested = [](int n) { return repeat("*a _", n) + "b" + repeat("_ a*", n); };
  EXPECT_NO_THROW((void)markdown_to_latex(nested(kMaxNesting / 2)));
  const std::string message = error_of([&] { (void)markdown_to_latex(nested(kMaxNesting / 2 + 1)); });
  EXPECT_EQ(message.rfind("line 1, column ", 0), 0u) << message;
  EXPECT_NE(message.find("emphasis, links and math spans are " + kTooDeep), std::string::npos) << message;
}

// Hostile inline markup is plain text to CommonMark: no deep nesting to refuse.
TEST(MarkdownNesting, InlineMarkupStaysShallowOnHostileText) {
  for (const std::string& hostile :
       {repeat("[", 20000) + "](x)", repeat("*[", 20000) + "](x)*", repeat("**[*", 20000) + "](x)**",
        repeat("**", 20000), repeat("![*a*](", 20000), repeat("`$*", 20000)}) {
    EXPECT_NO_THROW((void)markdown_to_text(hostile, 80));
    EXPECT_NO_THROW((void)markdown_to_latex(hostile));
    EXPECT_NO_THROW((void)inline_latex(hostile));
  }
}

}  // namespace
}  // namespace linkage
