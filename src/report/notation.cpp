#include "report/notation.hpp"

#include <array>

namespace linkage {

using expr::Style;

namespace {

struct InputSpelling {
  std::string_view key, unicode, ascii, latex;
};

constexpr std::array<InputSpelling, kInputKeys.size()> kInputSpellings{{
    {"L", "L", "L", "L"},
    {"w", "w", "w", "w"},
    {"b", "b", "b", "b"},
    {"m", "m", "m", "m"},
    {"g", "g", "g", "g"},
    {"x1", "x₁", "x1", "x_1"},
    {"y1", "y₁", "y1", "y_1"},
    {"theta1", "θ₁", "th1", "\\theta_1"},
    {"theta2", "θ₂", "th2", "\\theta_2"},
    {"x1_dot", "ẋ₁", "x1'", "\\dot{x}_1"},
    {"y1_dot", "ẏ₁", "y1'", "\\dot{y}_1"},
    {"theta1_dot", "θ̇₁", "th1'", "\\dot{\\theta}_1"},
    {"theta2_dot", "θ̇₂", "th2'", "\\dot{\\theta}_2"},
}};

// True when `text` has a + or - between terms outside any parentheses or braces,
// i.e. it needs parentheses as a factor.
bool has_top_level_sum(std::string_view text) {
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(' || c == '{') ++depth;
    if (c == ')' || c == '}') --depth;
    if (depth == 0 && i > 0 && i + 1 < text.size() && (c == '+' || c == '-') && text[i - 1] == ' ' &&
        text[i + 1] == ' ')
      return true;
  }
  return false;
}

// coefficient × unknown, without the coefficient's sign.
std::string term_body(std::string_view magnitude, std::string_view unknown, Style style) {
  if (magnitude == "1") return std::string(unknown);
  constexpr std::string_view latex_reciprocal = "\\frac{1}{";
  if (style != Style::latex && magnitude.starts_with("1/"))
    return std::string(unknown) + "/" + std::string(magnitude.substr(2));
  if (style == Style::latex && magnitude.starts_with(latex_reciprocal))
    return "\\frac{" + std::string(unknown) + "}{" + std::string(magnitude.substr(latex_reciprocal.size()));
  std::string factor(magnitude);
  if (has_top_level_sum(magnitude))
    factor = style == Style::latex ? "\\left(" + factor + "\\right)" : "(" + factor + ")";
  return factor + (style == Style::latex ? " \\, " : " ") + std::string(unknown);
}

}  // namespace

Symbol input_symbol(const InputKey& key, const Inputs& inputs) {
  const InputSpelling& s = kInputSpellings[static_cast<std::size_t>(&key - kInputKeys.data())];
  return {s.unicode, s.ascii, s.latex, inputs.value(key), true};
}

std::string_view unknown_name(Unknown u, Style style) {
  const UnknownInfo& i = info(u);
  return style == Style::unicode ? i.unicode : style == Style::ascii ? i.ascii : i.latex;
}

std::string unit_text(std::string_view ascii_unit, Style style) {
  std::string out;
  for (std::size_t i = 0; i < ascii_unit.size(); ++i) {
    const char c = ascii_unit[i];
    if (style == Style::unicode && c == '^' && i + 1 < ascii_unit.size() && ascii_unit[i + 1] == '2') {
      out += "²";
      ++i;
    } else if (style == Style::latex && c == ' ') {
      out += "\\,";
    } else {
      out += c;
    }
  }
  return style == Style::latex ? "\\mathrm{" + out + "}" : out;
}

std::string concat(std::initializer_list<std::string_view> pieces) {
  std::string out;
  for (std::string_view piece : pieces) out += piece;
  return out;
}

std::string parenthesized(std::string_view label) { return concat({"(", label, ")"}); }

EquationSides equation_sides(const std::vector<std::string>& A_row, const std::string& B_entry,
                             const std::vector<Unknown>& unknowns, Style style) {
  const std::string mark = style == Style::latex ? "" : std::string(1, kBreakMark);
  std::string lhs;
  for (std::size_t c = 0; c < A_row.size() && c < unknowns.size(); ++c) {
    std::string_view coefficient = A_row[c];
    if (coefficient == "0") continue;
    const bool negative = coefficient.starts_with('-');
    if (negative) coefficient.remove_prefix(1);
    const std::string body = term_body(coefficient, unknown_name(unknowns[c], style), style);
    if (lhs.empty())
      lhs = concat({negative ? "-" : "", body});
    else
      lhs += mark + (negative ? " - " : " + ") + body;
  }
  return {lhs.empty() ? std::string(1, '0') : lhs, B_entry};
}

}  // namespace linkage
