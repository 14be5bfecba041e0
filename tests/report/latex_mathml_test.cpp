// LaTeX math as MathML (a clip page's equations): real pieces of the reports compared with
// their exact MathML; every shipped mechanism's worked solution, as Markdown turned into
// HTML, has no command the converter does not know and is well-formed.
#include "report/latex_mathml.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "core/markup_escape.hpp"
#include "model/mechanism_toml.hpp"
#include "report/markdown.hpp"
#include "report/mechanism_latex.hpp"
#include "report/mechanism_solution.hpp"
#include "report/unicode_tex.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

std::string inline_math(const std::string& latex) {
  std::vector<std::string> unknown;
  std::string out = latex_to_mathml(latex, false, &unknown);
  EXPECT_TRUE(unknown.empty()) << latex << ": " << (unknown.empty() ? "" : unknown.front());
  return out;
}

TEST(LatexMathml, AFractionOfAProductAndANumber) {
  EXPECT_EQ(inline_math("\\frac{a^2 \\mathrm{ma}}{12}"),
            "<math><mfrac><mrow><msup><mi>a</mi><mn>2</mn></msup><mi>ma</mi></mrow><mn>12</mn></mfrac></math>");
}

TEST(LatexMathml, DotsScriptsAndUprightNames) {
  // A dotted angle with two scripts, a subscript word, a function with its thin space after
  // and before (a cos), and a unit in upright letters.
  EXPECT_EQ(inline_math("\\ddot{\\theta}_{1}"),
            "<math><msub><mover accent=\"true\"><mi>θ</mi><mo>¨</mo></mover><mn>1</mn></msub></math>");
  EXPECT_EQ(inline_math("\\dot{\\theta}_2^2"),
            "<math><msubsup><mover accent=\"true\"><mi>θ</mi><mo>˙</mo></mover><mn>2</mn><mn>2</mn></msubsup></math>");
  EXPECT_EQ(inline_math("x_{\\mathrm{crank}}"), "<math><msub><mi>x</mi><mi>crank</mi></msub></math>");
  EXPECT_EQ(inline_math("a \\cos\\theta_2"),
            "<math><mi>a</mi><mspace width=\"0.1667em\"/><mi>cos</mi><mspace width=\"0.1667em\"/>"
            "<msub><mi>θ</mi><mn>2</mn></msub></math>");
  EXPECT_EQ(inline_math("0.006\\ \\mathrm{kg\\,m^2}"),
            "<math><mn>0.006</mn><mspace width=\"0.3333em\"/><mrow><mi>kg</mi><mspace width=\"0.1667em\"/>"
            "<msup><mi mathvariant=\"normal\">m</mi><mn>2</mn></msup></mrow></math>");
  EXPECT_EQ(inline_math("\\mathrm{m/s}"),
            "<math><mrow><mi mathvariant=\"normal\">m</mi><mo lspace=\"0\" rspace=\"0\">/</mo>"
            "<mi mathvariant=\"normal\">s</mi></mrow></math>");
  EXPECT_EQ(inline_math("-\\Delta"), "<math><mo>−</mo><mi mathvariant=\"normal\">Δ</mi></math>");
}

TEST(LatexMathml, ABmatrixIsAMatrixInBrackets) {
  EXPECT_EQ(latex_to_mathml("A = \\begin{bmatrix}\n  1 & -a \\\\\n  0 & \\pi\n\\end{bmatrix}", true),
            "<math display=\"block\"><mi>A</mi><mo>=</mo><mrow><mo>[</mo><mtable class=\"matrix\">"
            "<mtr><mtd><mn>1</mn></mtd><mtd><mo>−</mo><mi>a</mi></mtd></mtr>"
            "<mtr><mtd><mn>0</mn></mtd><mtd><mi>π</mi></mtd></mtr></mtable><mo>]</mo></mrow></math>");
}

TEST(LatexMathml, AnAlignedEquationKeepsItsColumnsAndRowGaps) {
  // Two rows, the second under the first's "=", then a gap (\\[1ex]) before a third with a
  // note in its own column pair (&&), as the reports write the joints' constraints.
  EXPECT_EQ(latex_to_mathml("\\begin{aligned}\nI_2 &= \\frac{m}{12} \\\\\n  &= 0.5 \\\\[1ex]\n"
                            "y &= 0 && \\text{position}\n\\end{aligned}",
                            true),
            "<math display=\"block\"><mtable class=\"aligned\" displaystyle=\"true\">"
            "<mtr><mtd><msub><mi>I</mi><mn>2</mn></msub></mtd><mtd><mo>=</mo><mfrac><mi>m</mi><mn>12</mn></mfrac>"
            "</mtd></mtr>"
            "<mtr><mtd></mtd><mtd><mo>=</mo><mn>0.5</mn></mtd></mtr>"
            "<mtr class=\"gap\"><mtd><mi>y</mi></mtd><mtd><mo>=</mo><mn>0</mn></mtd><mtd></mtd>"
            "<mtd><mtext>position</mtext></mtd></mtr></mtable></math>");
}

TEST(LatexMathml, DelimitersStretchOnlyWhenAskedTo) {
  EXPECT_EQ(inline_math("\\left(\\frac{a}{b}\\right)^2 (x)"),
            "<math><msup><mrow><mo>(</mo><mfrac><mi>a</mi><mi>b</mi></mfrac><mo>)</mo></mrow><mn>2</mn></msup>"
            "<mo stretchy=\"false\">(</mo><mi>x</mi><mo stretchy=\"false\">)</mo></math>");
  // Around one line \left ( is a plain parenthesis (TeX's size there; Chromium would space
  // a stretchy one apart).
  EXPECT_EQ(inline_math("\\left(\\dot{x}^2\\right)"),
            "<math><mrow><mo stretchy=\"false\">(</mo><msup><mover accent=\"true\"><mi>x</mi><mo>˙</mo></mover>"
            "<mn>2</mn></msup><mo stretchy=\"false\">)</mo></mrow></math>");
  EXPECT_EQ(inline_math("\\lVert r \\rVert_2 \\Big|_{t = 0}"),
            "<math><mo stretchy=\"false\">‖</mo><mi>r</mi><msub><mo stretchy=\"false\">‖</mo><mn>2</mn></msub>"
            "<msub><mo minsize=\"1.623em\" maxsize=\"1.623em\" symmetric=\"true\">|</mo>"
            "<mrow><mi>t</mi><mo>=</mo><mn>0</mn></mrow></msub></math>");
}

TEST(LatexMathml, MarkupCharactersAreEscaped) {
  EXPECT_EQ(inline_math("s + l < p \\text{ & } q > 0"),
            "<math><mi>s</mi><mo>+</mo><mi>l</mi><mo>&lt;</mo><mi>p</mi><mtext> &amp; </mtext><mi>q</mi>"
            "<mo>&gt;</mo><mn>0</mn></math>");
  EXPECT_EQ(escape_markup("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
}

TEST(LatexMathml, UnknownInputStaysVisibleAndIsReported) {
  std::vector<std::string> unknown;
  EXPECT_EQ(latex_to_mathml("\\foo{x} & \\\\ }", false, &unknown),
            "<math><merror><mtext>\\foo</mtext></merror><mi>x</mi><merror><mtext>&amp;</mtext></merror>"
            "<merror><mtext>\\\\</mtext></merror><merror><mtext>}</mtext></merror></math>");
  EXPECT_EQ(unknown, (std::vector<std::string>{"\\foo", "&", "\\\\", "}"}));
  unknown.clear();
  (void)latex_to_mathml("\\begin{cases} a \\end{aligned", true, &unknown);
  EXPECT_EQ(unknown.size(), 2u);
  // Nothing can run it out of stack or past its text. (Built by append: GCC 12 warns
  // falsely of string concatenation in a braced list.)
  std::vector<std::string> hostile{"\\frac", "\\sqrt[x", "\\left", "\\begin{aligned", "", ""};
  hostile[0].append(500, '{');
  hostile[4].assign(100000, '{');
  hostile[5].assign(2000, '^');
  hostile[5].push_back('x');
  for (const std::string& text : hostile) {
    try {
      (void)latex_to_mathml(text, true);
    } catch (const LatexNestingError&) {
    }
  }
}

// Well-formed XML, with HTML's void elements (hr, br) allowed unclosed: every tag closed
// in order, attributes quoted, no bare < or & in text.
::testing::AssertionResult well_formed(const std::string& html) {
  std::vector<std::string> open;
  for (std::size_t i = 0; i < html.size(); ++i) {
    if (html[i] == '&') {
      const std::size_t semi = html.find(';', i);
      if (semi == std::string::npos || semi - i > 10)
        return ::testing::AssertionFailure() << "bare & at " << i << ": " << html.substr(i, 40);
      continue;
    }
    if (html[i] != '<') {
      if (html[i] == '>') return ::testing::AssertionFailure() << "bare > at " << i << ": " << html.substr(i, 40);
      continue;
    }
    const std::size_t end = html.find('>', i);
    if (end == std::string::npos) return ::testing::AssertionFailure() << "unclosed tag at " << i;
    const std::string tag = html.substr(i + 1, end - i - 1);
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0 || tag.find('<') != std::string::npos)
      return ::testing::AssertionFailure() << "bad tag <" << tag << ">";
    const std::string name = tag.substr(tag.front() == '/' ? 1 : 0, tag.find_first_of(" />", 1) - (tag.front() == '/'));
    if (tag.front() == '/') {
      if (open.empty() || open.back() != name)
        return ::testing::AssertionFailure() << "</" << name << "> closes <" << (open.empty() ? "" : open.back())
                                             << "> at " << i << ": " << html.substr(i > 80 ? i - 80 : 0, 120);
      open.pop_back();
    } else if (tag.back() != '/' && name != "hr" && name != "br") {
      open.push_back(name);
    }
    i = end;
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> never closed";
  return ::testing::AssertionSuccess();
}

TEST(LatexMathml, WellFormedCheckCatchesMistakes) {
  EXPECT_TRUE(well_formed("<p>a &amp; <math><mi>x</mi><mspace width=\"1em\"/></math></p><hr>"));
  EXPECT_FALSE(well_formed("<p><em>a</p></em>"));
  EXPECT_FALSE(well_formed("<p>a & b</p>"));
  EXPECT_FALSE(well_formed("<p>a < b</p>"));
  EXPECT_FALSE(well_formed("<math><mi>x</mi>"));
}

// Every shipped mechanism's worked solution (each case, and their agreement) as its page
// shows it: no command outside the converter's subset, and well-formed.
TEST(LatexMathml, EveryShippedReportConvertsWhole) {
  int reports = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("mechanisms"))) {
    if (entry.path().extension() != ".toml") continue;
    const MechanismSolution solution =
        work_out_mechanism(read_mechanism_file(entry.path()), {CaseId::maximal, CaseId::generalized, CaseId::reduced});
    const std::string markdown = mechanism_markdown(solution, ReportOptions{});
    std::vector<std::string> unknown;
    const std::string html = markdown_to_html(markdown, &unknown);
    EXPECT_TRUE(unknown.empty()) << entry.path().filename() << ": " << unknown.size() << " unknown, the first "
                                 << (unknown.empty() ? "" : unknown.front());
    EXPECT_EQ(html.find("<merror"), std::string::npos) << entry.path().filename();
    EXPECT_TRUE(well_formed(html)) << entry.path().filename();
    // Every math span of the Markdown became one <math> element.
    std::size_t dollars = 0, maths = 0;
    for (std::size_t at = markdown.find("$$"); at != std::string::npos; at = markdown.find("$$", at + 2)) ++dollars;
    for (std::size_t at = html.find("<math display=\"block\">"); at != std::string::npos;
         at = html.find("<math display=\"block\">", at + 1))
      ++maths;
    EXPECT_EQ(maths * 2, dollars) << entry.path().filename();
    EXPECT_GT(maths, 10u) << entry.path().filename();
    ++reports;
  }
  EXPECT_GE(reports, 16);
}

// A page takes the worked solution whole up to its limit, and beyond it a paragraph saying
// which `linkage solve` prints it (a long chain's runs to megabytes).
TEST(LatexMathml, APageTakesTheEquationsUpToItsLimit) {
  const MechanismSolution solution =
      work_out_mechanism(read_mechanism_file(test::source_path("mechanisms/two-blocks.toml")), {CaseId::reduced});
  const std::string whole = markdown_to_html(mechanism_markdown(solution, ReportOptions{}));
  EXPECT_EQ(mechanism_html(solution, ReportOptions{}), whole);
  EXPECT_LT(whole.size(), kPageEquationsLimit);
  const std::string expected =
      "<p>The worked solution is longer than a page holds (more than 0.001 MB of HTML): <code>linkage solve --case 3 "
      "--format markdown</code> prints it, with this clip&#39;s mechanism and settings.</p>\n";
  EXPECT_EQ(mechanism_html(solution, ReportOptions{}, 1000), expected);  // its Markdown is over the limit
  const std::string at_limit = mechanism_html(solution, ReportOptions{}, whole.size() - 1);  // only its HTML is
  EXPECT_NE(at_limit.find("longer than a page holds"), std::string::npos);
  EXPECT_EQ(mechanism_html(solution, ReportOptions{}, whole.size()), whole);
}

}  // namespace
}  // namespace linkage
