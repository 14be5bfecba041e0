#include "report/latex_math.hpp"

#include <cctype>

#include "report/notation.hpp"
#include "report/text_layout.hpp"

namespace linkage {

using expr::Style;

std::string latex_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
      case '%':
      case '$':
      case '#':
      case '_':
      case '{':
      case '}':
        out += '\\';
        out += c;
        break;
      case '~':
        out += "\\textasciitilde{}";
        break;
      case '^':
        out += "\\textasciicircum{}";
        break;
      case '\\':
        out += "\\textbackslash{}";
        break;
      default:
        out += c;
    }
  }
  return out;
}

namespace {

// Roughly how many characters wide LaTeX math prints: \sin counts 3, other commands
// 1 (\theta) or 0 (\left, \frac, \dot), braces and script markers nothing.
std::size_t visible_length(std::string_view tex) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < tex.size(); ++i) {
    const char c = tex[i];
    if (c == '\\') {
      std::size_t end = i + 1;
      while (end < tex.size() && std::isalpha(static_cast<unsigned char>(tex[end])) != 0) ++end;
      const std::string_view name = tex.substr(i + 1, end - i - 1);
      if (name.empty()) ++end;  // \, \; \\ and the like
      if (name == "sin" || name == "cos")
        n += 3;
      else if (!name.empty() && name != "left" && name != "right" && name != "frac" && name != "dot" &&
               name != "mathrm")
        n += 1;
      i = end - 1;
      continue;
    }
    if (c != '{' && c != '}' && c != '^' && c != '_' && c != ' ' && c != kBreakMark) ++n;
  }
  return n;
}

// The pieces of a formula between break marks outside all parentheses and braces,
// joined greedily into rows of at most `limit` visible characters.
std::vector<std::string> wrap_math(std::string_view tex, std::size_t limit) {
  std::vector<std::string> pieces(1);
  int depth = 0;
  for (char c : tex) {
    if (c == '(' || c == '{') ++depth;
    if (c == ')' || c == '}') --depth;
    if (c == kBreakMark) {
      if (depth == 0) pieces.emplace_back();
      continue;
    }
    pieces.back() += c;
  }
  std::vector<std::string> rows(1, pieces.front());
  for (std::size_t i = 1; i < pieces.size(); ++i) {
    if (visible_length(rows.back()) + visible_length(pieces[i]) <= limit) {
      rows.back() += pieces[i];
    } else {
      std::string_view piece = pieces[i];
      while (piece.starts_with(' ')) piece.remove_prefix(1);
      rows.emplace_back(piece);
    }
  }
  return rows;
}

// `first` followed by `tex` wrapped onto align rows; continuation rows are indented
// with \quad under the relation.
std::string aligned_rows(const std::string& pad, const std::string& first, std::string_view tex, std::size_t limit) {
  const std::vector<std::string> rows = wrap_math(tex, limit);
  std::string out = pad + first + rows.front();
  for (std::size_t i = 1; i < rows.size(); ++i) out += " \\\\\n" + pad + "  &\\quad " + rows[i];
  return out;
}

}  // namespace

std::string derivation_rows(const DerivationGroup& group, int digits, std::string_view indent) {
  constexpr std::size_t kRowLimit = 64;  // about the width of a 12 cm text block
  std::string out;
  const std::string pad(indent);
  for (std::size_t i = 0; i < group.steps.size(); ++i) {
    const DerivationStep& step = group.steps[i];
    const std::string formula = step.formula.print(Style::latex, Spelling::symbolic, digits);
    const std::string substituted = step.formula.print(Style::latex, Spelling::substituted, digits);
    const std::string result =
        format_number(step.quantity.value, Style::latex, digits) + "\\ " + unit_text(step.unit, Style::latex);
    out += aligned_rows(pad, std::string(step.quantity.latex) + " &= ", formula, kRowLimit) + " \\\\\n";
    if (visible_length(substituted) + visible_length(result) + 3 <= kRowLimit) {
      out += pad + "  &= " + strip_marks(substituted) + " = " + result;
    } else {
      out += aligned_rows(pad, "  &= ", substituted, kRowLimit) + " \\\\\n";
      out += pad + "  &= " + result;
    }
    out += i + 1 < group.steps.size() ? " \\\\[1ex]\n" : "\n";
  }
  return out;
}

std::string bmatrix(const std::vector<std::vector<std::string>>& rows, const std::vector<std::string>& row_comments,
                    std::string_view indent) {
  const std::string pad(indent);
  std::string out = pad + "\\begin{bmatrix}\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out += pad + "  ";
    for (std::size_t c = 0; c < rows[r].size(); ++c) out += (c == 0 ? "" : " & ") + rows[r][c];
    if (r + 1 < rows.size()) out += " \\\\";
    if (r < row_comments.size() && !row_comments[r].empty()) out += "  % " + row_comments[r];
    out += "\n";
  }
  return out + pad + "\\end{bmatrix}\n";
}

namespace {

std::vector<std::vector<std::string>> as_column(const std::vector<std::string>& entries) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& e : entries) rows.push_back({e});
  return rows;
}

// A short column vector on one line: \begin{bmatrix} a \\ b \end{bmatrix}.
std::string inline_column(const std::vector<std::string>& entries, std::string_view indent,
                          std::string_view environment = "bmatrix") {
  std::string out = concat({indent, "\\begin{", environment, "} "});
  for (std::size_t i = 0; i < entries.size(); ++i) out += concat({i == 0 ? "" : " \\\\ ", entries[i]});
  return out + concat({" \\end{", environment, "}\n"});
}

std::vector<std::string> unknown_names(const CaseSolution& c) {
  std::vector<std::string> names;
  for (Unknown u : c.unknowns) names.emplace_back(unknown_name(u, Style::latex));
  return names;
}

}  // namespace

std::string matrix_equation(const CaseSolution& c, const MatrixLayout& layout, int digits, std::string_view indent) {
  SymbolicSystem entries = symbolic_system(c.id, Style::latex);
  if (layout.numeric) {
    for (Eigen::Index r = 0; r < c.A.rows(); ++r) {
      for (Eigen::Index col = 0; col < c.A.cols(); ++col)
        entries.A[static_cast<std::size_t>(r)][static_cast<std::size_t>(col)] =
            format_number(c.A(r, col), Style::latex, digits);
      entries.B[static_cast<std::size_t>(r)] = format_number(c.B[r], Style::latex, digits);
    }
  }
  std::vector<std::string> labels;
  if (layout.row_comments)
    for (std::string_view label : c.equations) labels.push_back(parenthesized(label));
  return bmatrix(entries.A, labels, indent) + inline_column(unknown_names(c), indent) + std::string(indent) +
         (layout.break_before_equals ? "\\\\ =\n" : "=\n") + bmatrix(as_column(entries.B), labels, indent);
}

std::string solution_equation(const CaseSolution& c, int digits, std::string_view indent) {
  std::vector<std::string> values, units;
  for (std::size_t i = 0; i < c.unknowns.size(); ++i) {
    values.push_back(format_number(c.solution[static_cast<Eigen::Index>(i)], Style::latex, digits));
    units.push_back(unit_text(info(c.unknowns[i]).unit, Style::latex));
  }
  return inline_column(unknown_names(c), indent) + std::string(indent) + "=\n" + inline_column(values, indent) +
         inline_column(units, indent, "matrix");
}

std::vector<std::string> equation_rows(const CaseSolution& c) {
  const SymbolicSystem symbolic = symbolic_system(c.id, Style::latex);
  std::vector<std::string> rows;
  for (std::size_t r = 0; r < symbolic.A.size(); ++r) {
    const EquationSides eq = equation_sides(symbolic.A[r], symbolic.B[r], c.unknowns, Style::latex);
    rows.push_back(eq.lhs + " &= " + eq.rhs);
  }
  return rows;
}

}  // namespace linkage
