#include "report/text_report.hpp"

#include <langinfo.h>

#include <clocale>
#include <cstring>

#include "report/derivation.hpp"
#include "report/notation.hpp"
#include "report/sections.hpp"
#include "report/text_layout.hpp"

namespace linkage {

using expr::Style;

expr::Style text_style_from_locale() {
  const char* current = std::setlocale(LC_CTYPE, nullptr);
  const std::string previous = current != nullptr ? current : "C";
  Style style = Style::ascii;
  if (std::setlocale(LC_CTYPE, "") != nullptr) {
    const char* codeset = nl_langinfo(CODESET);
    if (codeset != nullptr && (std::strcmp(codeset, "UTF-8") == 0 || std::strcmp(codeset, "utf8") == 0))
      style = Style::unicode;
  }
  std::setlocale(LC_CTYPE, previous.c_str());
  return style;
}

namespace {

class TextWriter {
 public:
  TextWriter(const WorkedSolution& worked, const ReportOptions& options)
      : w_(worked), o_(options), style_(options.text_style) {}

  void title() { heading("Worked solution: two blocks joined by a frictionless pin", '='); }
  [[nodiscard]] const std::string& text() const { return out_; }

  void line(const std::string& text) { out_ += text + "\n"; }
  void lines(const std::vector<std::string>& text) {
    for (const auto& l : text) line(l);
  }
  void blank() { out_ += "\n"; }
  void prose(std::string_view text, std::string_view indent = "  ") { lines(wrap_words(text, indent, o_.width)); }

  void heading(std::string_view title, char underline) {
    if (!out_.empty()) blank();
    line(std::string(title));
    line(std::string(display_width(title), underline));
  }

  [[nodiscard]] std::string number(double value) const { return format_number(value, style_, o_.digits); }
  [[nodiscard]] std::string unit(std::string_view ascii) const { return unit_text(ascii, style_); }

  void inputs() {
    heading("Inputs", '-');
    Table table;
    table.headers = {"value", "unit", "meaning"};
    std::string given;
    for (const InputKey& key : kInputKeys) {
      const Symbol symbol = input_symbol(key, w_.inputs);
      table.row_labels.emplace_back(symbol.spelling(style_));
      table.cells.push_back({format_number(symbol.value, style_, 0), unit(key.unit), std::string(key.description)});
      const std::string& origin = w_.inputs.origin(key);
      if (origin != "default") given += (given.empty() ? "" : ", ") + std::string(key.key) + " (" + origin + ")";
    }
    lines(layout_table(table, "  ", o_.width));
    blank();
    prose(given.empty() ? "All inputs are the spec's example (the defaults)."
                        : "Given: " + given + "; the rest are the spec's example.");
  }

  void derivation_group(const DerivationGroup& group) {
    heading(group.title, '-');
    prose(group.note);
    blank();
    std::size_t lhs_width = 0;
    for (const DerivationStep& step : group.steps)
      lhs_width = std::max(lhs_width, display_width(step.quantity.spelling(style_)));
    for (const DerivationStep& step : group.steps) {
      const std::string lhs = "  " + pad_right(step.quantity.spelling(style_), lhs_width);
      const std::string formula = step.formula.print(style_, Spelling::symbolic, o_.digits);
      const std::string substituted = step.formula.print(style_, Spelling::substituted, o_.digits);
      const std::string result = number(step.quantity.value) + " " + unit(step.unit);
      const std::string one_line =
          lhs + " = " + strip_marks(formula) + " = " + strip_marks(substituted) + " = " + result;
      if (display_width(one_line) <= o_.width) {
        line(one_line);
        continue;
      }
      const std::string equals = std::string(display_width(lhs), ' ') + " = ";
      const std::string continuation = std::string(display_width(equals) + 2, ' ');
      lines(wrap(lhs + " = ", formula, continuation, o_.width));
      lines(wrap(equals, substituted, continuation, o_.width));
      line(equals + result);
    }
  }

  [[nodiscard]] std::vector<std::string> equation_labels(const CaseSolution& c) const {
    std::vector<std::string> labels;
    for (std::string_view label : c.equations) labels.push_back(parenthesized(label));
    return labels;
  }

  [[nodiscard]] std::vector<std::string> unknown_headers(const CaseSolution& c) const {
    std::vector<std::string> headers;
    for (Unknown u : c.unknowns) headers.emplace_back(unknown_name(u, style_));
    return headers;
  }

  void one_case(const CaseSolution& c) {
    heading(c.title, '-');
    std::string q;
    for (Unknown u : c.unknowns) q += (q.empty() ? "" : ", ") + std::string(unknown_name(u, style_));
    prose("Unknowns: q = (" + q + ")");
    prose("I stands for I_zz^C; D = L/2 - b as above.");

    const SymbolicSystem symbolic = symbolic_system(c.id, style_);
    const std::vector<std::string> labels = equation_labels(c);
    if (o_.shows(ReportPart::symbolic)) {
      blank();
      line("  Equations, one per row of A q = B:");
      for (std::size_t r = 0; r < symbolic.A.size(); ++r) {
        const EquationSides eq = equation_sides(symbolic.A[r], symbolic.B[r], c.unknowns, style_);
        const std::string first = "    " + labels[r] + "  ";
        const std::string text = eq.lhs + kBreakMark + " = " + eq.rhs;
        lines(wrap(first, text, std::string(display_width(first) + 4, ' '), o_.width));
      }
    }

    Table table;
    table.headers = unknown_headers(c);
    table.headers.emplace_back("B");
    table.row_labels = labels;
    table.separator_before = c.unknowns.size();
    for (std::size_t r = 0; r < symbolic.A.size(); ++r) {
      table.cells.push_back(symbolic.A[r]);
      table.cells.back().push_back(symbolic.B[r]);
    }
    if (o_.shows(ReportPart::symbolic)) {
      blank();
      line("  Symbolic A | B:");
      lines(layout_table(table, "    ", o_.width));
    }

    for (Eigen::Index r = 0; r < c.A.rows(); ++r) {
      auto& row = table.cells[static_cast<std::size_t>(r)];
      for (Eigen::Index col = 0; col < c.A.cols(); ++col) row[static_cast<std::size_t>(col)] = number(c.A(r, col));
      row.back() = number(c.B[r]);
    }
    if (o_.shows(ReportPart::numeric)) {
      blank();
      line("  Numeric A | B:");
      lines(layout_table(table, "    ", o_.width));
    }

    Table solution;
    solution.headers = {"value", "unit", "meaning"};
    for (std::size_t i = 0; i < c.unknowns.size(); ++i) {
      const UnknownInfo& u = info(c.unknowns[i]);
      solution.row_labels.emplace_back(unknown_name(c.unknowns[i], style_));
      solution.cells.push_back(
          {number(c.solution[static_cast<Eigen::Index>(i)]), unit(u.unit), std::string(u.description)});
    }
    if (o_.shows(ReportPart::solution)) {
      blank();
      line("  Solution:");
      lines(layout_table(solution, "    ", o_.width));
    }
    if (!o_.shows(ReportPart::residual)) return;
    blank();
    const bool uni = style_ == Style::unicode;
    line(std::string(uni ? "  Residual ‖A q - B‖₂ = " : "  Residual ||A q - B||_2 = ") +
         format_number(c.residual, style_, 2));
    line(std::string(uni ? "  Condition number κ₂(A) = " : "  Condition number cond_2(A) = ") +
         format_number(c.condition_number, style_, 3) + " (largest / smallest singular value)");
  }

  void agreement() {
    heading("The cases agree", '-');
    prose(
        "Every unknown from every case, and the largest difference between cases. A * marks a value "
        "the case does not solve for but recovers from the equations it eliminated: Fx = m " +
        std::string(unknown_name(Unknown::x1_ddot, style_)) + ", Fy = m (" +
        std::string(unknown_name(Unknown::y1_ddot, style_)) + " + g), " +
        std::string(unknown_name(Unknown::x2_ddot, style_)) + " = -Fx/m, " +
        std::string(unknown_name(Unknown::y2_ddot, style_)) + " = -g - Fy/m.");
    Table table;
    for (const CaseSolution& c : w_.cases) table.headers.push_back("Case " + std::to_string(c.id));
    table.headers.emplace_back(style_ == Style::unicode ? "max |Δ|" : "max |diff|");
    table.separator_before = w_.cases.size();
    for (const Agreement& a : w_.agreement) {
      table.row_labels.emplace_back(unknown_name(a.unknown, style_));
      std::vector<std::string> row;
      for (std::size_t i = 0; i < a.values.size(); ++i)
        row.push_back(number(a.values[i]) + (a.recovered[i] ? "*" : ""));
      row.push_back(format_number(a.max_abs_difference, style_, 2));
      table.cells.push_back(std::move(row));
    }
    blank();
    lines(layout_table(table, "    ", o_.width));
  }

 private:
  const WorkedSolution& w_;
  const ReportOptions& o_;
  Style style_;
  std::string out_;
};

}  // namespace

std::string text_report(const WorkedSolution& worked, const ReportOptions& options) {
  TextWriter writer(worked, options);
  return write_sections(writer, worked, options);
}

}  // namespace linkage
