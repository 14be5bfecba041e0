#include "report/latex_math.hpp"

#include <algorithm>
#include <cctype>

#include "report/notation.hpp"
#include "report/text_layout.hpp"

namespace linkage {

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

std::string latex_heading(std::string_view title, std::string_view text) {
  std::string out = concat({"\n% ---- ", title, " ----\n\\par\\medskip\\noindent\\textbf{", latex_escape(title), ".}"});
  if (!text.empty()) out += concat({" ", text});
  return out + "\n";
}

// \sin counts 3, other commands 1 (\theta) or 0 (\left, \frac, \dot), braces and
// script markers nothing.
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
      else if (name == "times" || name == "cdot")
        n += 2;  // a binary operator with the medium spaces around it
      else if (!name.empty() && name != "left" && name != "right" && name != "frac" && name != "dot" &&
               name != "mathrm")
        n += 1;
      i = end - 1;
      continue;
    }
    const bool binary = (c == '+' || c == '-' || c == '=') && i > 0 && tex[i - 1] == ' ';
    if (binary)
      n += 2;  // the operator and the medium spaces around it
    else if (c != '{' && c != '}' && c != '^' && c != '_' && c != ' ' && c != kBreakMark)
      ++n;
  }
  return n;
}

std::string mark_sums(std::string_view tex) {
  std::string out;
  int depth = 0;
  for (std::size_t i = 0; i < tex.size(); ++i) {
    const char c = tex[i];
    if (c == '(' || c == '{') ++depth;
    if (c == ')' || c == '}') --depth;
    const bool operator_follows = i + 2 < tex.size() && (tex[i + 1] == '+' || tex[i + 1] == '-') && tex[i + 2] == ' ';
    if (depth == 0 && c == ' ' && operator_follows && !out.empty()) out += kBreakMark;
    out += c;
  }
  return out;
}

namespace {

// The pieces of a formula between break marks outside all parentheses and braces,
// joined greedily into rows of at most `limit` visible characters (`first_limit` for
// the first row).
std::vector<std::string> wrap_math(std::string_view tex, std::size_t limit, std::size_t first_limit) {
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
    if (visible_length(rows.back()) + visible_length(pieces[i]) <= (rows.size() == 1 ? first_limit : limit)) {
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
  const std::vector<std::string> rows = wrap_math(tex, limit, limit);
  std::string out = pad + first + rows.front();
  for (std::size_t i = 1; i < rows.size(); ++i) out += " \\\\\n" + pad + "  &\\quad " + rows[i];
  return out;
}

constexpr std::size_t kRowLimit = 64;  // about the width of a 12 cm text block

}  // namespace

std::string step_rows(const std::vector<MathStep>& steps, std::string_view indent) {
  std::string out;
  const std::string pad(indent);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const MathStep& step = steps[i];
    if (step.formula.empty()) {
      out += concat({pad, step.quantity, " &= ", step.result});
    } else if (step.substituted.empty()) {
      out += aligned_rows(pad, step.quantity + " &= ", step.formula, kRowLimit);
      out += visible_length(wrap_math(step.formula, kRowLimit, kRowLimit).back()) + visible_length(step.result) + 3 <=
                     kRowLimit
                 ? concat({" = ", step.result})
                 : concat({" \\\\\n", pad, "  &= ", step.result});
    } else {
      out += aligned_rows(pad, step.quantity + " &= ", step.formula, kRowLimit) + " \\\\\n";
      // Numbers that cannot wrap (inside a fraction) and would run off the page are left
      // out: the formula and the value say what the step does.
      const std::vector<std::string> numbers = wrap_math(step.substituted, kRowLimit, kRowLimit);
      const bool fits = std::all_of(numbers.begin(), numbers.end(),
                                    [](const std::string& row) { return visible_length(row) <= kRowLimit; });
      if (!fits) {
        out += pad + "  &= " + step.result;
      } else if (visible_length(step.substituted) + visible_length(step.result) + 3 <= kRowLimit) {
        out += pad + "  &= " + strip_marks(step.substituted) + " = " + step.result;
      } else {
        out += aligned_rows(pad, "  &= ", step.substituted, kRowLimit) + " \\\\\n";
        out += pad + "  &= " + step.result;
      }
    }
    out += i + 1 < steps.size() ? " \\\\[1ex]\n" : "\n";
  }
  return out;
}

std::string equation_row(std::string_view lhs, std::string_view rhs, std::string_view suffix, std::size_t limit,
                         std::string_view indent) {
  const std::string pad(indent);
  if (visible_length(lhs) + visible_length(rhs) + 1 <= limit) return concat({pad, lhs, " &= ", rhs, suffix});
  // A short right side stays whole after the left side's last row, else it wraps too.
  const std::size_t right_width = visible_length(rhs) + 1;
  const bool right_whole = 2 * right_width <= limit;
  const std::size_t left_limit = right_whole ? limit - right_width : limit;
  std::vector<std::string> left = wrap_math(mark_sums(lhs), left_limit, left_limit);
  std::string out = pad + left.front();
  // A continued left side starts with its operator: {} keeps it binary.
  for (std::size_t i = 1; i < left.size(); ++i) out += concat({" \\\\\n", pad, "{} ", left[i]});
  const std::size_t used = visible_length(left.back());
  const std::vector<std::string> right = right_whole
                                             ? std::vector<std::string>{std::string(rhs)}
                                             : wrap_math(mark_sums(rhs), limit, used + 8 < limit ? limit - used : 8);
  out += concat({" &= ", right.front()});
  for (std::size_t i = 1; i < right.size(); ++i) out += concat({" \\\\\n", pad, "  &\\quad ", right[i]});
  return out + std::string(suffix);
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

std::string inline_column(const std::vector<std::string>& entries, std::string_view indent,
                          std::string_view environment) {
  std::string out = concat({indent, "\\begin{", environment, "} "});
  for (std::size_t i = 0; i < entries.size(); ++i) out += concat({i == 0 ? "" : " \\\\ ", entries[i]});
  return out + concat({" \\end{", environment, "}\n"});
}

std::string column_vector(const std::vector<std::string>& entries, const std::vector<std::string>& row_comments,
                          std::string_view indent) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& e : entries) rows.push_back({e});
  return bmatrix(rows, row_comments, indent);
}

std::string matrix_equation(const std::vector<std::vector<std::string>>& A, const std::vector<std::string>& unknowns,
                            const std::vector<std::string>& B, const std::vector<std::string>& labels,
                            const MatrixLayout& layout, std::string_view indent) {
  std::vector<std::string> comments;
  if (layout.row_comments)
    for (const std::string& label : labels) comments.push_back(parenthesized(label));
  return bmatrix(A, comments, indent) + inline_column(unknowns, indent) + std::string(indent) +
         (layout.break_before_equals ? "\\\\ =\n" : "=\n") + column_vector(B, comments, indent);
}

std::string solution_equation(const std::vector<std::string>& unknowns, const std::vector<std::string>& values,
                              const std::vector<std::string>& units, std::string_view indent) {
  return inline_column(unknowns, indent) + std::string(indent) + "=\n" + inline_column(values, indent) +
         inline_column(units, indent, "matrix");
}

std::string solution_markdown(const std::vector<SolutionRow>& rows, int digits) {
  std::string out = "\n| unknown | value | unit | meaning |\n| :-- | --: | :-- | :-- |\n";
  for (const SolutionRow& row : rows)
    out += concat({"| $", row.latex, "$ | ", format_number(row.value, Style::unicode, digits), " | ",
                   unit_text(row.unit, Style::unicode), " | ", row.meaning, " |\n"});
  return out;
}

std::string residual_line(double residual, double condition) {
  return "\\lVert A q - B \\rVert_2 = " + format_number(residual, Style::latex, 2) +
         ", \\qquad \\kappa_2(A) = " + format_number(condition, Style::latex, 3);
}

std::string agreement_tabular(const std::vector<int>& cases, const std::vector<AgreementRow>& rows, int digits) {
  std::string out = "\\begin{center}\n\\begin{tabular}{l" + std::string(cases.size() + 1, 'r') + "}\n ";
  for (int c : cases) out += " & Case " + std::to_string(c);
  out += " & $\\max|\\Delta|$ \\\\\n  \\hline\n";
  for (const AgreementRow& row : rows) {
    out += "  $" + row.latex + "$";
    for (std::size_t i = 0; i < row.values.size(); ++i)
      out += row.values[i] ? concat({" & $", format_number(*row.values[i], Style::latex, digits), "$",
                                     row.recovered[i] ? "$^{*}$" : ""})
                           : std::string(" & --");
    out += " & $" + format_number(row.max_abs_difference, Style::latex, 2) + "$ \\\\\n";
  }
  return out + "\\end{tabular}\n\\end{center}\n";
}

std::string agreement_markdown(const std::vector<int>& cases, const std::vector<AgreementRow>& rows, int digits) {
  std::string out = "\n| unknown |";
  std::string rule = "| :-- |";
  for (int c : cases) {
    out += " Case " + std::to_string(c) + " |";
    rule += " --: |";
  }
  out += " max \\|Δ\\| |\n" + rule + " --: |\n";
  for (const AgreementRow& row : rows) {
    out += "| $" + row.latex + "$ |";
    for (std::size_t i = 0; i < row.values.size(); ++i)
      out += row.values[i] ? concat({" ", format_number(*row.values[i], Style::unicode, digits),
                                     row.recovered[i] ? "\\*" : "", " |"})
                           : std::string(" - |");
    out += concat({" ", format_number(row.max_abs_difference, Style::unicode, 2), " |\n"});
  }
  return out;
}

}  // namespace linkage
