// Lesson Markdown for a terminal (wrapped) and for LaTeX (compilable by pdflatex).
#include "report/markdown.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "core/error.hpp"
#include "report/text_layout.hpp"
#include "support/commonmark_sample.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

using test::lines_of;

TEST(MarkdownText, ParagraphsWrapToTheWidth) {
  const std::string text =
      "The two blocks are identical, so their moments of inertia about their own centres of mass are equal: "
      "**I = m (w² + L²) / 12**, with `m` the mass and θ₁ the angle.";
  for (std::size_t width : {40u, 60u, 80u}) {
    const std::string out = markdown_to_text(text, width);
    for (const std::string& line : lines_of(out)) EXPECT_LE(display_width(line), width) << line;
    EXPECT_EQ(out.find("**"), std::string::npos);
    EXPECT_EQ(out.find('`'), std::string::npos);
    std::string joined = out;
    std::replace(joined.begin(), joined.end(), '\n', ' ');
    EXPECT_NE(joined.find("I = m (w² + L²) / 12"), std::string::npos);
  }
}

TEST(MarkdownText, ListsQuotesHeadingsAndBlocks) {
  const std::string out = markdown_to_text(
      "# Spot the mistake\n\nIntro line\ncontinues here.\n\n- first item that is long enough to wrap around the "
      "narrow terminal width\n- second\n\n> the text says 2.0433 x 10^-4\n\n```\ncode  stays\n```\n\n$$\nA q = "
      "B\n$$\n\n"
      "See [the spec](spec.txt), *holonomic* and m * D.",
      40);
  const std::vector<std::string> lines = lines_of(out);
  ASSERT_GE(lines.size(), 10u);
  EXPECT_EQ(lines[0], "Spot the mistake");
  EXPECT_EQ(lines[1], "================");
  EXPECT_EQ(lines[3], "Intro line continues here.");
  EXPECT_EQ(lines[5].rfind("  - first item", 0), 0u);
  EXPECT_EQ(lines[6].rfind("    ", 0), 0u);  // hanging indent
  EXPECT_NE(out.find("  - second\n"), std::string::npos);
  EXPECT_NE(out.find("  | the text says 2.0433 x 10^-4\n"), std::string::npos);
  EXPECT_NE(out.find("    code  stays\n"), std::string::npos);
  EXPECT_NE(out.find("    A q = B\n"), std::string::npos);
  std::string joined = out;
  std::replace(joined.begin(), joined.end(), '\n', ' ');
  EXPECT_NE(joined.find("See the spec (spec.txt), holonomic and m * D."), std::string::npos) << out;
}

TEST(MarkdownText, ANumberStartingALineIsNotAList) {
  EXPECT_EQ(markdown_to_text("The value is\n240000. Then more.", 80), "The value is 240000. Then more.\n");
  EXPECT_EQ(markdown_to_text("Steps:\n1. one\n2. two", 80), "Steps:\n\n  1. one\n  2. two\n");
}

TEST(MarkdownText, TablesLineUp) {
  EXPECT_EQ(markdown_to_text("| a | value |\n| --- | --- |\n| $\\theta_1$ | 0.1 |\n| long name | 2 |\n", 80),
            "  a          value\n  ----------------\n  θ₁         0.1\n  long name  2\n");
}

TEST(MarkdownLatex, ConvertsMarkupAndSymbols) {
  EXPECT_EQ(inline_latex("**bold** and *em* and `a_b`"), "\\textbf{bold} and \\emph{em} and \\texttt{a\\_b}");
  EXPECT_EQ(inline_latex("θ₁ = 0.1 rad"), "$\\theta_{1}$ = 0.1 rad");
  EXPECT_EQ(inline_latex("θ̈₂ and ẍ₁"), "$\\ddot{\\theta}_{2}$ and $\\ddot{x}_{1}$");
  EXPECT_EQ(inline_latex("m² × 2 − 1 ≈ 0"), "$m^{2}$ $\\times$ 2 $-$ 1 $\\approx$ 0");
  EXPECT_EQ(inline_latex("50% of $x_1$ & #3"), "50\\% of $x_1$ \\& \\#3");
  EXPECT_EQ(inline_latex("[spec](a_b.txt)"), "\\href{a_b.txt}{spec}");
  EXPECT_EQ(inline_latex("m * D^2"), "m * D\\textasciicircum{}2");
}

TEST(MarkdownLatex, Blocks) {
  const std::string out = markdown_to_latex(
      "# Title\n\n- a\n- b\n\n1. one\n2. two\n\n> quote\n\n$$\nx = 1\n$$\n\n"
      "| a | b |\n|---|---|\n| 1 | 2 |\n");
  EXPECT_NE(out.find("\\subsection*{Title}"), std::string::npos);
  EXPECT_NE(out.find("\\begin{itemize}\n  \\item a\n  \\item b\n\\end{itemize}"), std::string::npos);
  EXPECT_NE(out.find("\\begin{enumerate}\n  \\item one\n  \\item two\n\\end{enumerate}"), std::string::npos);
  EXPECT_NE(out.find("\\begin{quote}\nquote\n"), std::string::npos);
  EXPECT_NE(out.find("\\[\nx = 1\n\\]"), std::string::npos);
  EXPECT_NE(out.find("\\begin{tabular}{ll}\n  a & b \\\\\n  \\hline\n  1 & 2 \\\\\n\\end{tabular}"), std::string::npos);
}

// CommonMark as GitHub renders it: nested lists, emphasis inside a link, a table with a
// right-aligned column, fenced code and a quote holding a quote.
TEST(CommonMark, TheTerminalShowsEachStructure) {
  EXPECT_EQ(markdown_to_text(test::kCommonMarkSample, 40),
            "Bodies and joints\n"
            "=================\n\n"
            "Read the whole spec (spec.txt) before\n"
            "θ₁.\n\n"
            "  - bodies\n"
            "    - block 1\n"
            "    - block 2\n"
            "  - joints\n"
            "    1. pin at O\n"
            "    2. slider\n\n"
            "  name  value\n"
            "  -----------\n"
            "  θ\u0307₁      0.1\n"
            "  mass      2\n\n"
            "    linkage solve --case 1\n\n"
            "  | A quote, with emphasis, over two\n"
            "  | lines.\n"
            "  |\n"
            "  | | and a quote inside it\n");
}

TEST(CommonMark, TheHandoutShowsEachStructure) {
  EXPECT_EQ(markdown_to_latex(test::kCommonMarkSample),
            "\\subsection*{Bodies and joints}\n\n"
            "Read \\href{spec.txt}{the \\emph{whole} spec} before $\\theta_1$.\n\n"
            "\\begin{itemize}\n"
            "  \\item bodies\n"
            "\\begin{itemize}\n"
            "  \\item block 1\n"
            "  \\item block 2\n"
            "\\end{itemize}\n"
            "  \\item joints\n"
            "\\begin{enumerate}\n"
            "  \\item pin at $O$\n"
            "  \\item slider\n"
            "\\end{enumerate}\n"
            "\\end{itemize}\n\n"
            "\\begin{tabular}{lr}\n"
            "  name & value \\\\\n"
            "  \\hline\n"
            "  $\\dot\\theta_1$ & 0.1 \\\\\n"
            "  \\textbf{mass} & 2 \\\\\n"
            "\\end{tabular}\n\n"
            "\\begin{verbatim}\n"
            "linkage solve --case 1\n"
            "\\end{verbatim}\n\n"
            "\\begin{quote}\n"
            "A quote, with \\emph{emphasis}, over two lines.\n\n"
            "\\begin{quote}\n"
            "and a quote inside it\n\n"
            "\\end{quote}\n\n"
            "\\end{quote}\n\n");
}

// Where CommonMark reads differently from the line-by-line reader it replaced.
TEST(CommonMark, NumbersLinksAndLooseLists) {
  EXPECT_EQ(markdown_to_text("3. three\n3. four", 80), "  3. three\n  4. four\n");  // numbered from the start
  EXPECT_EQ(markdown_to_text("<https://x.org/a>", 80), "https://x.org/a\n");        // an autolink once
  EXPECT_EQ(markdown_to_text("- a\n\n- b", 80), "  - a\n\n  - b\n");                // a loose list
  EXPECT_EQ(markdown_to_text("a  \nb &amp; c", 80), "a\nb & c\n");                  // hard break, entity
  EXPECT_EQ(inline_latex("1. Introduction"), "1. Introduction");                    // a title, not a list
  EXPECT_EQ(inline_latex("# 3"), "\\# 3");
}

TEST(LatexToUnicode, MathInTerminalText) {
  EXPECT_EQ(markdown_to_text("The angle $\\theta_1$ grows.\n\n$$\n\\ddot{y}_1 = -g\n$$\n", 80),
            "The angle θ₁ grows.\n\n    y\u0308₁ = -g\n");
}

TEST(MarkdownHtml, BlocksSpansAndMath) {
  EXPECT_EQ(markdown_to_html("# Worked *solution*\n\nA $\\theta_2$ and `code`.\n\n$$\nx = 1\n$$\n\n"
                             "| symbol | value |\n| :-- | --: |\n| $a$ | 0.1 |\n\n- one\n- two\n"),
            "<h1>Worked <em>solution</em></h1>\n"
            "<p>A <math><msub><mi>θ</mi><mn>2</mn></msub></math> and <code>code</code>.</p>\n"
            "<p><math display=\"block\"><mi>x</mi><mo>=</mo><mn>1</mn></math></p>\n"
            "<table>\n<thead>\n<tr><th>symbol</th><th align=\"right\">value</th></tr>\n</thead>\n"
            "<tbody>\n<tr><td><math><mi>a</mi></math></td><td align=\"right\">0.1</td></tr>\n</tbody>\n</table>\n"
            "<ul>\n<li>one</li>\n<li>two</li>\n</ul>\n");
}

TEST(MarkdownHtml, NothingInTheTextBecomesMarkupOrRuns) {
  // Raw HTML is text (md4c's NOHTML), entities stay characters, a script link loses its target.
  EXPECT_EQ(markdown_to_html("<script>alert(1)</script> &amp; &lt;b&gt; \"q\"\n\n[x](javascript:alert(1)) "
                             "[y](https://example.org/?a=1&b=2) [z](notes.md)"),
            "<p>&lt;script&gt;alert(1)&lt;/script&gt; &amp; &lt;b&gt; &quot;q&quot;</p>\n"
            "<p><span>x</span> <a href=\"https://example.org/?a=1&amp;b=2\">y</a> <a href=\"notes.md\">z</a></p>\n");
  std::vector<std::string> unknown;
  EXPECT_NE(markdown_to_html("$\\nope x$", &unknown).find("<merror>"), std::string::npos);
  EXPECT_EQ(unknown, std::vector<std::string>{"\\nope"});
  // Math nested too deep is refused naming where (its 65th brace), as for the other renderers.
  try {
    (void)markdown_to_html("text\n\n$" + std::string(100, '{') + "$");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("line 3, column 66"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace linkage
