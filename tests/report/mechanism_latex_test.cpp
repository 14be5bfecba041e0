// The worked derivation of any mechanism as LaTeX and Markdown: for the homework, built by
// the general procedure, each case prints as the golden files (tests/data/solve/
// example-all.tex and example-all.md) print it; for a four-bar and a slider-crank the
// output is well-formed LaTeX (ASCII, balanced environments and braces) and Markdown.
#include "report/mechanism_latex.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <sstream>

#include "report/latex_math.hpp"
#include "support/mechanisms_in_code.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

const std::vector<CaseId> kCases{CaseId::maximal, CaseId::generalized, CaseId::reduced};

std::string golden(const std::string& name) {
  return test::read_text(std::filesystem::path(LINKAGE_SOURCE_DIR) / "tests" / "data" / "solve" / name);
}

// The text from the line starting with `first` up to (not including) the next line that
// starts with `until` (or the end).
std::string section(const std::string& text, const std::string& first, const std::string& until) {
  const auto begin = text.find("\n" + first);
  if (begin == std::string::npos) return "<missing " + first + ">";
  const auto end = text.find("\n" + until, begin + 1);
  return text.substr(begin + 1, end == std::string::npos ? std::string::npos : end - begin);
}

// The residual and max |Delta| figures are rounding noise of the solver that produced
// them (the homework's block elimination, the mechanism's full-pivot LU), so the
// comparisons put a placeholder where they stand and check them separately.
const std::regex kResidual(R"(\\rVert_2 = [^,]*,)");
std::string mask_residual(const std::string& text) { return std::regex_replace(text, kResidual, R"(\rVert_2 = R,)"); }

// The last cell of each agreement table row: "& $2.8 \times 10^{-17}$ \\" or "| 2.8e-17 |".
std::string mask_last_cell(const std::string& text) {
  static const std::regex latex_cell(R"(& \$[^$]*\$ \\\\\n)");
  static const std::regex markdown_cell(R"(\| [^|]* \|\n)");
  std::string out = std::regex_replace(text, latex_cell, "& D \\\\\n");
  return std::regex_replace(out, markdown_cell, "| D |\n");
}

MechanismSolution homework() { return work_out_mechanism(built::homework(), kCases); }

// Each residual the general route prints is rounding noise: under n eps (|A| |q| + |B|).
void expect_residuals_at_rounding(const MechanismSolution& s) {
  for (const SolvedCase& c : s.cases) {
    const CaseNumbers& n = c.numbers;
    const double scale = n.A.norm() * n.solution.norm() + n.B.norm();
    EXPECT_LE(n.residual, static_cast<double>(n.A.rows()) * std::numeric_limits<double>::epsilon() * scale)
        << "Case " << case_number(c.system.id);
  }
  for (const MechanismAgreement& a : s.agreement) {
    double size = 0;
    for (const auto& v : a.values)
      if (v) size = std::max(size, std::abs(*v));
    EXPECT_LE(a.max_abs_difference, 1e-12 * std::max(size, 1.0));
  }
}

TEST(MechanismLatex, HomeworkCasesAsTheGolden) {
  const MechanismSolution s = homework();
  const std::string ours = mask_residual(mechanism_latex(s, ReportOptions{}));
  const std::string theirs = mask_residual(golden("example-all.tex"));
  for (const char* c : {"1", "2", "3"}) {
    // From the case's heading to the next section, every line: the labelled equations,
    // the symbolic and numeric matrices, the solution and the residual line.
    const std::string heading = std::string("% ---- Case ") + c + ":";
    EXPECT_EQ(section(ours, heading, "% ----"), section(theirs, heading, "% ----")) << "Case " << c;
  }
  // The agreement table, without its note (the homework's names Fx = m x1'' and so on).
  const std::string table = "\\begin{tabular}{lrrrr}";
  EXPECT_EQ(mask_last_cell(section(ours, table, "\\end{center}")),
            mask_last_cell(section(theirs, table, "\\end{center}")));
  expect_residuals_at_rounding(s);
}

TEST(MechanismMarkdown, HomeworkCasesAsTheGolden) {
  const MechanismSolution s = homework();
  const std::string ours = mask_residual(mechanism_markdown(s, ReportOptions{}));
  const std::string theirs = mask_residual(golden("example-all.md"));
  for (const char* c : {"1", "2", "3"}) {
    const std::string heading = std::string("## Case ") + c + ":";
    EXPECT_EQ(section(ours, heading, "## "), section(theirs, heading, "## ")) << "Case " << c;
  }
  const std::string table = "| unknown | Case 1 |";
  EXPECT_EQ(mask_last_cell(section(ours, table, "<end>")), mask_last_cell(section(theirs, table, "<end>")));
}

TEST(MechanismLatex, MaskingKeepsEverythingButTheNoise) {
  // The masks replace exactly the residual figure and the max |Delta| cell.
  EXPECT_EQ(mask_residual(R"(\lVert A q - B \rVert_2 = 2.5 \times 10^{-15}, \qquad \kappa_2(A) = 1761)"),
            R"(\lVert A q - B \rVert_2 = R, \qquad \kappa_2(A) = 1761)");
  EXPECT_EQ(mask_last_cell("  $F_x$ & $0.0017575$ & $0$ \\\\\n"), "  $F_x$ & $0.0017575$ & D \\\\\n");
  EXPECT_EQ(mask_last_cell("| $F_x$ | 0.0017575 | 2.6e-18 |\n"), "| $F_x$ | 0.0017575 | D |\n");
}

// ---- well-formed output for any mechanism ----

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// Every \begin{env} closed by its \end{env} in order, and every unescaped brace matched
// (LaTeX comments skipped).
void expect_balanced_latex(const std::string& tex) {
  std::vector<std::string> environments;
  int braces = 0;
  for (std::size_t i = 0; i < tex.size(); ++i) {
    const char c = tex[i];
    if (c == '%' && (i == 0 || tex[i - 1] != '\\')) {
      i = tex.find('\n', i);
      if (i == std::string::npos) break;
      continue;
    }
    if (c == '\\' && i + 1 < tex.size()) {
      for (const char* command : {"begin{", "end{"}) {
        const std::string_view rest(tex.data() + i + 1, tex.size() - i - 1);
        if (!rest.starts_with(command)) continue;
        const auto close = tex.find('}', i);
        const std::string name = tex.substr(i + 1 + std::strlen(command), close - i - 1 - std::strlen(command));
        if (command[0] == 'b') {
          environments.push_back(name);
        } else {
          ASSERT_FALSE(environments.empty()) << "\\end{" << name << "} closes nothing";
          ASSERT_EQ(environments.back(), name);
          environments.pop_back();
        }
      }
      ++i;  // an escaped character (\{, \\) counts as none
      continue;
    }
    if (c == '{') ++braces;
    if (c == '}') --braces;
    ASSERT_GE(braces, 0) << "a } closes nothing near: " << tex.substr(i > 80 ? i - 80 : 0, 160);
  }
  EXPECT_TRUE(environments.empty()) << environments.back() << " is not closed";
  EXPECT_EQ(braces, 0);
  // A \left( must close on its own row: a wrapped formula breaks only between terms.
  std::istringstream rows(tex);
  for (std::string row; std::getline(rows, row);) EXPECT_EQ(count(row, "\\left"), count(row, "\\right")) << row;
}

void expect_no_bad_numbers(const std::string& text) {
  const std::regex bad(R"(\b(nan|inf|NaN|Inf)\b)");
  EXPECT_FALSE(std::regex_search(text, bad));
}

TEST(MechanismLatex, FourBarAndSliderCrankAreWellFormedAscii) {
  for (const Mechanism& m : {built::four_bar(), built::slider_crank()}) {
    const std::string tex = mechanism_latex(work_out_mechanism(m, kCases), ReportOptions{});
    expect_balanced_latex(tex);
    expect_no_bad_numbers(tex);
    for (std::size_t i = 0; i < tex.size(); ++i)
      ASSERT_LT(static_cast<unsigned char>(tex[i]), 0x80) << "not ASCII near: " << tex.substr(i > 40 ? i - 40 : 0, 80);
    for (const char* part :
         {"Inputs and definitions", "Moments of inertia", "(closes a loop)", "Energy and momentum",
          "Forces and moments on each body", "Newton-Euler equations", "Case 3: ", "The cases agree", "\\tag{17.1}"})
      EXPECT_NE(tex.find(part), std::string::npos) << part;
  }
}

TEST(MechanismLatex, BalanceCheckFindsAnUnclosedEnvironmentOrBrace) {
  EXPECT_NONFATAL_FAILURE(expect_balanced_latex("\\begin{align*}\n x &= 1\n"), "not closed");
  EXPECT_NONFATAL_FAILURE(expect_balanced_latex("$\\frac{1}{2$"), "braces");
}

// The entries of every one-line column "\begin{bmatrix} a \\ b \end{bmatrix}" that follows
// a line ending in `before`, in order.
std::vector<std::string> columns_after(const std::string& tex, const std::string& before) {
  std::vector<std::string> entries;
  std::istringstream in(tex);
  std::string previous;
  for (std::string line; std::getline(in, line); previous = line) {
    if (!previous.ends_with(before)) continue;
    const std::string open = "\\begin{bmatrix} ", close = " \\end{bmatrix}";
    const auto begin = line.find(open), end = line.find(close);
    if (begin == std::string::npos || end == std::string::npos) continue;
    std::string body = line.substr(begin + open.size(), end - begin - open.size());
    for (std::size_t at; (at = body.find(" \\\\ ")) != std::string::npos; body.erase(0, at + 4))
      entries.push_back(body.substr(0, at));
    entries.push_back(body);
  }
  return entries;
}

// Case 1 of the four-bar has 17 unknowns: A prints in column blocks A_k of at most eight
// columns beside the unknowns q_k they multiply, together every unknown once in order,
// each block with all 17 labelled rows; B once; the numbers split as the symbols do.
TEST(MechanismLatex, WideMatrixSplitsIntoColumnBlocks) {
  const MechanismSolution s = work_out_mechanism(built::four_bar(), {CaseId::maximal});
  const std::string tex = mechanism_latex(s, ReportOptions{});
  EXPECT_EQ(count(tex, "\\begin{multline*}"), 0);
  std::vector<std::string> unknowns;
  for (const GiNaC::symbol& u : s.cases.front().system.unknowns) unknowns.push_back(s.system->table().find(u)->latex);
  ASSERT_EQ(unknowns.size(), 17U);
  std::vector<std::string> twice = unknowns;
  twice.insert(twice.end(), unknowns.begin(), unknowns.end());
  const std::vector<std::string> beside = columns_after(tex, " =");
  // Every q_k of the symbolic and the numeric display, then the solution's column.
  ASSERT_GE(beside.size(), 2 * unknowns.size());
  EXPECT_EQ(std::vector<std::string>(beside.begin(), beside.begin() + 34), twice);
  const int blocks = count(tex, ", \\qquad q_") / 2;
  EXPECT_GE(blocks, 3);
  EXPECT_EQ(count(tex, "B =\n"), 2);
  // Each block's rows carry the labels, so (17.1) ends a row of every block and of B.
  EXPECT_EQ(count(tex, "  % (17.1)\n"), 2 * (blocks + 1));
  std::string sum;
  for (int k = 1; k <= blocks; ++k)
    sum += (k == 1 ? "" : " + ") + ("A_" + std::to_string(k)) + " q_" + std::to_string(k);
  EXPECT_NE(tex.find("$" + sum + " = B$"), std::string::npos) << sum;
  EXPECT_NE(tex.find("\nNumerically:\n"), std::string::npos);
}

// ---- Markdown ----

// Every table row has as many cells as its header; $$ blocks pair up; headings are
// "# " or "## " lines.
void expect_well_formed_markdown(const std::string& md) {
  std::istringstream in(md);
  std::string line;
  int columns = -1;
  int fences = 0;
  bool in_math = false;
  while (std::getline(in, line)) {
    if (line == "$$") {
      ++fences;
      in_math = !in_math;
      continue;
    }
    if (in_math) continue;
    if (line.starts_with("|")) {
      int cells = 0;
      for (std::size_t i = 0; i < line.size(); ++i)
        if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) ++cells;
      if (columns < 0) columns = cells;
      EXPECT_EQ(cells, columns) << line;
    } else {
      columns = -1;
    }
    if (line.starts_with("#")) {
      EXPECT_TRUE(line.starts_with("# ") || line.starts_with("## ")) << line;
    }
  }
  EXPECT_FALSE(in_math) << fences << " $$ lines";
}

TEST(MechanismMarkdown, FourBarAndSliderCrankAreWellFormed) {
  for (const Mechanism& m : {built::four_bar(), built::slider_crank()}) {
    const std::string md = mechanism_markdown(work_out_mechanism(m, kCases), ReportOptions{});
    expect_well_formed_markdown(md);
    expect_no_bad_numbers(md);
    EXPECT_EQ(md.find('%'), std::string::npos) << "a LaTeX comment in Markdown math";
    EXPECT_EQ(md.find("\\tag"), std::string::npos);
    for (const char* part : {"## Inputs and definitions", "## Moments of inertia", "## Newton-Euler equations",
                             "## Case 1: ", "## Case 3: ", "## The cases agree", "\\text{(17.1)}"})
      EXPECT_NE(md.find(part), std::string::npos) << part;
  }
}

TEST(MechanismMarkdown, WellFormedCheckFindsARaggedTable) {
  EXPECT_NONFATAL_FAILURE(expect_well_formed_markdown("| a | b |\n| :-- | --: |\n| 1 |\n"), "cells");
  EXPECT_NONFATAL_FAILURE(expect_well_formed_markdown("\n$$\nx\n"), "$$ lines");
}

// Every mechanism built in code, with every kind of load (springs, dampers, applied
// forces and torques), in both formats; but floating_pair, whose Case 3 entries swell
// to 500 kB of LaTeX and take seconds to derive and print.
std::vector<built::Named> every_built() {
  return {{"homework", built::homework},
          {"double_pendulum", built::double_pendulum},
          {"triple_pendulum", built::triple_pendulum},
          {"spring_pendulum", [] { return built::spring_pendulum(true); }},
          {"double_pendulum_loaded", built::double_pendulum_loaded},
          {"cart_pendulum", built::cart_pendulum},
          {"arm_collar", built::arm_collar},
          {"reversed_joints", built::reversed_joints},
          {"floating_collar", built::floating_collar},
          {"four_bar_loaded", built::four_bar_loaded}};
}

// `m` with a seeded random state as its [initial] (most of them give none).
Mechanism at_random_state(Mechanism m) {
  std::mt19937 rng(12);
  const sym::System system(m);
  const GiNaC::exmap state = built::random_state(system, rng);
  m.initial.clear();
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    m.initial.push_back({g.coordinate.key, sym::to_double(state.at(g.symbols.q)), {}});
    m.initial.push_back({g.coordinate.key + "_dot", sym::to_double(state.at(g.symbols.q_dot)), {}});
  }
  return m;
}

TEST(MechanismLatex, EveryBuiltMechanismIsWellFormed) {
  for (const built::Named& named : every_built()) {
    SCOPED_TRACE(named.name);
    const MechanismSolution s = work_out_mechanism(at_random_state(named.make()), kCases);
    const std::string tex = mechanism_latex(s, ReportOptions{});
    expect_balanced_latex(tex);
    expect_no_bad_numbers(tex);
    EXPECT_TRUE(std::all_of(tex.begin(), tex.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; }));
    expect_well_formed_markdown(mechanism_markdown(s, ReportOptions{}));
  }
}

// ---- parts and wrapping ----

TEST(MechanismLatex, PartsChooseTheSections) {
  ReportOptions only_numbers;
  only_numbers.parts.fill(false);
  only_numbers.parts[static_cast<std::size_t>(ReportPart::numeric)] = true;
  const MechanismSolution s = homework();
  for (const std::string& out : {mechanism_latex(s, only_numbers), mechanism_markdown(s, only_numbers)}) {
    EXPECT_EQ(out.find("Inputs"), std::string::npos);
    EXPECT_EQ(out.find("Newton-Euler"), std::string::npos);
    EXPECT_EQ(out.find("Solution:"), std::string::npos);
    EXPECT_EQ(out.find("agree"), std::string::npos);
    EXPECT_EQ(count(out, "Numerically:"), 3);
  }
}

// A row longer than the limit wraps at its top-level sums onto rows within the limit: the
// four-bar's (3.1), 60 characters, goes over two rows, the second continuing the left
// side; the homework's longest, (6.2) with 50, stays whole (HomeworkCasesAsTheGolden).
TEST(MechanismLatex, LongEquationsWrapAtTheirSums) {
  const std::string tex = mechanism_latex(work_out_mechanism(built::four_bar(), {CaseId::maximal}), ReportOptions{});
  const auto tag = tex.find("\\tag{3.1}");
  ASSERT_NE(tag, std::string::npos);
  const auto begin = tex.rfind("\\tag{2.1} \\\\\n", tag);
  ASSERT_NE(begin, std::string::npos);
  std::istringstream rows(tex.substr(begin, tag - begin));
  std::vector<std::string> lines;
  for (std::string line; std::getline(rows, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 3U) << tex.substr(begin, tag - begin);  // (2.1)'s end, then (3.1) on two rows
  EXPECT_TRUE(lines[1].starts_with("  I_2 \\, \\ddot{\\theta}_2 + ")) << lines[1];
  EXPECT_TRUE(lines[2].starts_with("  {} ")) << lines[2];
  EXPECT_NE(lines[2].find(" &= 0"), std::string::npos) << lines[2];
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::string row = lines[i].substr(0, lines[i].find(" &= "));
    if (row.ends_with(" \\\\")) row.resize(row.size() - 3);
    EXPECT_LE(visible_length(row), 56U) << row;
  }
}

}  // namespace
}  // namespace linkage
