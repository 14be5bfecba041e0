#include "report/text_report.hpp"

#include <gtest/gtest.h>

#include <clocale>
#include <cstdlib>
#include <sstream>

#include "report/formula.hpp"
#include "report/latex_report.hpp"
#include "report/text_layout.hpp"

namespace linkage {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

Inputs inputs_with(std::initializer_list<std::pair<const char*, double>> values) {
  Inputs inputs;
  for (const auto& [key, value] : values) inputs.set(*find_input_key(key), value, "test");
  return inputs;
}

TEST(TextReport, EveryLineFitsEightyColumnsInBothStyles) {
  const Inputs cases[] = {
      Inputs{},
      inputs_with({{"m", 1234.5678}, {"L", 0.0123}, {"b", 0.0001}, {"theta1", -123.456}, {"theta2_dot", -98765.4}}),
      inputs_with({{"m", 1e-3}, {"x1", -1.23456789e-7}, {"y1", 9.87654321e12}, {"g", 0}, {"b", 0.3}}),
  };
  for (const Inputs& inputs : cases) {
    const WorkedSolution w = work_out(inputs, {1, 2, 3});
    for (expr::Style style : {expr::Style::unicode, expr::Style::ascii}) {
      ReportOptions options;
      options.text_style = style;
      const std::string text = text_report(w, options);
      for (const std::string& line : lines_of(text)) EXPECT_LE(display_width(line), 80u) << line;
      EXPECT_EQ(text.find(kBreakMark), std::string::npos);
      if (style == expr::Style::ascii) {
        for (unsigned char c : text) ASSERT_LT(c, 128) << "non-ASCII byte in ASCII mode";
      }
    }
  }
}

TEST(TextReport, ShowsEveryStepOfTheWorkedSolution) {
  ReportOptions options;
  options.text_style = expr::Style::ascii;
  const std::string text = text_report(work_out(Inputs{}, {1, 2, 3}), options);
  for (const char* expected :
       {"I_zz^C = m (w^2 + L^2) / 12 = 0.1 * (0.1^2 + 0.3^2) / 12 = 0.000833333 kg m^2", "D      = L / 2 - b",
        "x2  = xP + D cos(th2) = 1.10945 + 0.11 * cos(0.2) = 1.21726 m", "(8.1)  y1'' + D cos(th1) th1''",
        "(6.2)  y1'' + D cos(th1) th1'' + D cos(th2) th2'' + Fy/m",
        "Residual ||A q - B||_2 = ", "Condition number cond_2(A) = ", "The cases agree", "-0.017575*"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
}

TEST(TextReport, StyleFollowsTheLocale) {
  const char* saved = std::getenv("LC_ALL");
  const std::string previous = saved != nullptr ? saved : "";
  ::setenv("LC_ALL", "C", 1);
  EXPECT_EQ(text_style_from_locale(), expr::Style::ascii);
  ::setenv("LC_ALL", "C.UTF-8", 1);
  const bool have_utf8 = std::setlocale(LC_CTYPE, "C.UTF-8") != nullptr;
  std::setlocale(LC_CTYPE, "C");
  if (have_utf8) {
    EXPECT_EQ(text_style_from_locale(), expr::Style::unicode);
  }
  if (saved != nullptr)
    ::setenv("LC_ALL", previous.c_str(), 1);
  else
    ::unsetenv("LC_ALL");
  EXPECT_STREQ(std::setlocale(LC_CTYPE, nullptr), "C");  // restored
}

TEST(LatexReport, BalancedEnvironmentsAndNoMarks) {
  const WorkedSolution w = work_out(Inputs{}, {1, 2, 3});
  for (const std::string& text : {latex_report(w, ReportOptions{}), markdown_report(w, ReportOptions{})}) {
    EXPECT_EQ(text.find(kBreakMark), std::string::npos);
    for (const char* env : {"bmatrix", "align*", "multline*", "aligned", "tabular", "equation*"}) {
      std::size_t begins = 0, ends = 0;
      for (auto at = text.find("\\begin{" + std::string(env) + "}"); at != std::string::npos;
           at = text.find("\\begin{" + std::string(env) + "}", at + 1))
        ++begins;
      for (auto at = text.find("\\end{" + std::string(env) + "}"); at != std::string::npos;
           at = text.find("\\end{" + std::string(env) + "}", at + 1))
        ++ends;
      EXPECT_EQ(begins, ends) << env;
    }
    int depth = 0;
    for (char c : text) {
      depth += c == '{' ? 1 : c == '}' ? -1 : 0;
      ASSERT_GE(depth, 0);
    }
    EXPECT_EQ(depth, 0);
  }
  const std::string markdown = markdown_report(w, ReportOptions{});
  // Markdown math must not hold LaTeX comments (a forge may join the lines).
  EXPECT_EQ(markdown.find("% ("), std::string::npos);
  EXPECT_NE(latex_report(w, ReportOptions{}).find("\\tag{8.1}"), std::string::npos);
}

}  // namespace
}  // namespace linkage
