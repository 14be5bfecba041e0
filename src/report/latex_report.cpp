#include "report/latex_report.hpp"

#include "report/derivation.hpp"
#include "report/latex_math.hpp"
#include "report/notation.hpp"
#include "report/sections.hpp"

namespace linkage {

using expr::Style;

namespace {

// "Given: m (--m), ...; the rest are the spec's example." or the all-defaults sentence.
std::string provenance(const Inputs& inputs) {
  std::string given;
  for (const InputKey& key : kInputKeys) {
    const std::string& origin = inputs.origin(key);
    if (origin != "default") given += (given.empty() ? "" : ", ") + std::string(key.key) + " (" + origin + ")";
  }
  return given.empty() ? "All inputs are the spec's example (the defaults)."
                       : "Given: " + given + "; the rest are the spec's example.";
}

std::vector<int> case_ids(const WorkedSolution& w) {
  std::vector<int> ids;
  for (const CaseSolution& c : w.cases) ids.push_back(c.id);
  return ids;
}

std::vector<AgreementRow> agreement_rows(const WorkedSolution& w) {
  std::vector<AgreementRow> rows;
  for (const Agreement& a : w.agreement)
    rows.push_back({std::string(unknown_name(a.unknown, Style::latex)),
                    std::vector<std::optional<double>>(a.values.begin(), a.values.end()), a.recovered,
                    a.max_abs_difference});
  return rows;
}

class LatexWriter {
 public:
  LatexWriter(const WorkedSolution& worked, const ReportOptions& options)
      : w_(worked), digits_(options.digits), o_(options) {}

  void title() {
    out_ += "% Worked solution of the two-block linkage, from `linkage solve --format latex`.\n";
    out_ += "% Paste into a document or a slide; needs \\usepackage{amsmath}.\n";
  }

  void derivation_group(const DerivationGroup& group) {
    heading(group.title, group.note);
    out_ += "\\begin{align*}\n" + derivation_rows(group, digits_, "  ") + "\\end{align*}\n";
  }

  [[nodiscard]] const std::string& text() const { return out_; }

  void heading(std::string_view title, std::string_view text) { out_ += latex_heading(title, text); }

  void inputs() {
    heading("Inputs", latex_escape(provenance(w_.inputs)));
    out_ += "\\begin{center}\n\\begin{tabular}{llll}\n";
    for (const InputKey& key : kInputKeys) {
      const Symbol s = input_symbol(key, w_.inputs);
      out_ += "  $" + std::string(s.latex) + "$ & $" + format_number(s.value, Style::latex, 0) + "$ & $" +
              unit_text(key.unit, Style::latex) + "$ & " + latex_escape(key.description) + " \\\\\n";
    }
    out_ += "\\end{tabular}\n\\end{center}\n";
  }

  // A q = B over two lines; narrower column gaps (3pt, from 5pt) so 8 columns fit.
  void matrix_display(const std::string& equation) {
    out_ += "\\begin{multline*}\n  \\setlength{\\arraycolsep}{3pt}\n" + equation + "\\end{multline*}\n";
  }

  void one_case(const CaseSolution& c) {
    const bool symbolic = o_.shows(ReportPart::symbolic);
    heading(c.title, symbolic ? "The equations, one per row of $A q = B$:" : "");
    if (symbolic) {
      out_ += "\\begin{align*}\n";
      const std::vector<std::string> rows = equation_rows(c);
      for (std::size_t r = 0; r < rows.size(); ++r)
        out_ +=
            "  " + rows[r] + " \\tag{" + std::string(c.equations[r]) + "}" + (r + 1 < rows.size() ? " \\\\\n" : "\n");
      out_ += "\\end{align*}\n";
      out_ += "In matrix form, rows in the order of the equations:\n";
      matrix_display(matrix_equation(c, {false, true, true}, digits_, "  "));
    }
    if (o_.shows(ReportPart::numeric)) {
      out_ += "Numerically:\n";
      matrix_display(matrix_equation(c, {true, true, true}, digits_, "  "));
    }
    if (o_.shows(ReportPart::solution)) {
      out_ += "Solution:\n";
      out_ += "\\begin{equation*}\n" + solution_equation(c, digits_, "  ") + "\\end{equation*}\n";
    }
    if (o_.shows(ReportPart::residual))
      out_ += "\\begin{equation*}\n  " + residual_line(c.residual, c.condition_number) + "\n\\end{equation*}\n";
  }

  void agreement() {
    heading("The cases agree",
            "Every unknown from every case; $^{*}$ marks a value the case recovers from the equations it "
            "eliminated rather than solves for.");
    out_ += agreement_tabular(case_ids(w_), agreement_rows(w_), digits_);
  }

 private:
  const WorkedSolution& w_;
  int digits_;
  const ReportOptions& o_;
  std::string out_;
};

class MarkdownWriter {
 public:
  MarkdownWriter(const WorkedSolution& worked, const ReportOptions& options)
      : w_(worked), digits_(options.digits), o_(options) {}

  void title() { out_ += "# Worked solution: two blocks joined by a frictionless pin\n"; }

  void derivation_group(const DerivationGroup& group) {
    heading(group.title);
    paragraph(std::string(group.note));
    math("\\begin{aligned}\n" + derivation_rows(group, digits_, "") + "\\end{aligned}\n");
  }

  [[nodiscard]] const std::string& text() const { return out_; }

  void heading(std::string_view title) { out_ += "\n## " + std::string(title) + "\n"; }
  void paragraph(const std::string& text) { out_ += "\n" + text + "\n"; }
  void math(const std::string& body) { out_ += "\n$$\n" + body + "$$\n"; }

  void inputs() {
    heading("Inputs");
    out_ += "\n| symbol | value | unit | meaning |\n| :-- | --: | :-- | :-- |\n";
    for (const InputKey& key : kInputKeys) {
      const Symbol s = input_symbol(key, w_.inputs);
      out_ += "| $" + std::string(s.latex) + "$ | " + format_number(s.value, Style::unicode, 0) + " | " +
              unit_text(key.unit, Style::unicode) + " | " + std::string(key.description) + " |\n";
    }
    paragraph(provenance(w_.inputs));
  }

  void one_case(const CaseSolution& c) {
    heading(c.title);
    if (o_.shows(ReportPart::symbolic)) {
      paragraph("The equations, one per row of $A q = B$:");
      std::string rows;
      const std::vector<std::string> eqs = equation_rows(c);
      for (std::size_t r = 0; r < eqs.size(); ++r)
        rows += eqs[r] + " && \\text{(" + std::string(c.equations[r]) + ")}" + (r + 1 < eqs.size() ? " \\\\\n" : "\n");
      math("\\begin{aligned}\n" + rows + "\\end{aligned}\n");
      paragraph("In matrix form, rows in the order of the equations:");
      math(matrix_equation(c, {false, false, false}, digits_, ""));
    }
    if (o_.shows(ReportPart::numeric)) {
      paragraph("Numerically:");
      math(matrix_equation(c, {true, false, false}, digits_, ""));
    }
    if (o_.shows(ReportPart::solution)) {
      paragraph("Solution:");
      std::vector<SolutionRow> rows;
      for (std::size_t i = 0; i < c.unknowns.size(); ++i) {
        const UnknownInfo& u = info(c.unknowns[i]);
        rows.push_back({std::string(u.latex), c.solution[static_cast<Eigen::Index>(i)], std::string(u.unit),
                        std::string(u.description)});
      }
      out_ += solution_markdown(rows, digits_);
    }
    if (o_.shows(ReportPart::residual)) math(residual_line(c.residual, c.condition_number) + "\n");
  }

  void agreement() {
    heading("The cases agree");
    paragraph(
        "Every unknown from every case; \\* marks a value the case recovers from the equations it "
        "eliminated rather than solves for.");
    out_ += agreement_markdown(case_ids(w_), agreement_rows(w_), digits_);
  }

 private:
  const WorkedSolution& w_;
  int digits_;
  const ReportOptions& o_;
  std::string out_;
};

}  // namespace

std::string latex_report(const WorkedSolution& worked, const ReportOptions& options) {
  LatexWriter writer(worked, options);
  return write_sections(writer, worked, options);
}

std::string markdown_report(const WorkedSolution& worked, const ReportOptions& options) {
  MarkdownWriter writer(worked, options);
  return write_sections(writer, worked, options);
}

}  // namespace linkage
