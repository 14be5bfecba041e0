#include "report/document_writer.hpp"

#include <chrono>
#include <system_error>

#include "core/error.hpp"
#include "core/run_program.hpp"
#include "report/latex_math.hpp"
#include "report/markdown.hpp"
#include "report/mechanism_latex.hpp"
#include "report/mechanism_text.hpp"
#include "report/text_layout.hpp"
#include "report/unicode_tex.hpp"

namespace linkage {
namespace {

// A handout compiles in seconds; a document that loops (TeX can) is stopped.
constexpr std::chrono::seconds kPdfTimeout{120};

// The table as a Markdown pipe table: the first column left, the others right.
std::string pipe_table(const ResultTable& table) {
  std::string out;
  auto row = [&](const std::vector<std::string>& cells) {
    out += "|";
    for (const std::string& c : cells) out += concat({" ", c, " |"});
    out += "\n";
  };
  row(table.headers);
  out += "|";
  for (std::size_t i = 0; i < table.headers.size(); ++i) out += i == 0 ? " --- |" : " ---: |";
  out += "\n";
  for (const auto& r : table.rows) row(r);
  return out;
}

bool file_exists(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::is_regular_file(p, ec);
}

class TextWriter final : public Writer {
 public:
  TextWriter(std::size_t width, Style style) : width_(width), style_(style) {}

  void title(const std::string& title, const std::string& description) override {
    const std::string rule(std::min<std::size_t>(width_, std::max<std::size_t>(display_width(title), 1)), '=');
    out_ += rule + "\n" + title + "\n" + rule + "\n";
    if (!description.empty()) {
      out_ += "\n";
      out_ += markdown_to_text(description, width_);
    }
  }
  void heading(const std::string& text) override {
    out_ += "\n" + text + "\n" + std::string(display_width(text), '-') + "\n";
  }
  void markdown(const std::string& text) override {
    out_ += "\n";
    out_ += markdown_to_text(text, width_);
  }
  void worked_solution(const MechanismSolution& worked, const ReportOptions& options) override {
    ReportOptions o = options;
    o.width = width_;
    o.text_style = style_;
    out_ += "\n";
    out_ += mechanism_text(worked, o);
  }
  void modes(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
             const std::vector<ModeCheck>* checks, const ReportOptions& options) override {
    ReportOptions o = options;
    o.width = width_;
    o.text_style = style_;
    out_ += "\n";
    out_ += modes_text(system, linear, modes, o, checks);
  }
  void table(const ResultTable& table, const std::string& caption) override {
    Table t;
    t.headers.assign(table.headers.begin() + 1, table.headers.end());
    for (const auto& row : table.rows) {
      t.row_labels.push_back(row.front());
      t.cells.emplace_back(row.begin() + 1, row.end());
    }
    out_ += "\n";
    if (!caption.empty()) out_ += markdown_to_text(caption, width_);
    for (const std::string& line : layout_table(t, "  ", width_)) out_ += line + "\n";
  }
  void figure(const FigureRef& f) override {
    const char* what = f.kind == FigureRef::Kind::video   ? "Clip: "
                       : f.kind == FigureRef::Kind::image ? "Figure: "
                                                          : "File: ";
    out_ += "\n";
    out_ += what + f.path.string() + "\n";
    if (!f.caption.empty()) out_ += markdown_to_text(f.caption, width_);
  }
  void exercise(const std::string& question, const std::string& answer, const std::string& explanation) override {
    out_ += "\n";
    out_ += markdown_to_text("**Exercise.** " + question, width_);
    out_ += markdown_to_text("**Answer:** " + answer + (explanation.empty() ? "" : ". " + explanation), width_);
  }

 private:
  std::size_t width_;
  Style style_;
};

class MarkdownWriter final : public Writer {
 private:
  // A report's headings two levels below the lesson's step headings.
  static std::string shifted(const std::string& report) {
    std::string out;
    std::size_t start = 0;
    while (start < report.size()) {
      std::size_t end = report.find('\n', start);
      if (end == std::string::npos) end = report.size();
      const std::string_view line(report.data() + start, end - start);
      if (line.starts_with("#")) out += "##";
      out += std::string(line) + "\n";
      start = end + 1;
    }
    return out;
  }

 public:
  void title(const std::string& title, const std::string& description) override {
    out_ += "# " + title + "\n";
    if (!description.empty()) out_ += "\n" + description + "\n";
  }
  void heading(const std::string& text) override { out_ += "\n## " + text + "\n"; }
  void markdown(const std::string& text) override { out_ += "\n" + text + "\n"; }
  void worked_solution(const MechanismSolution& worked, const ReportOptions& options) override {
    out_ += "\n";
    out_ += shifted(mechanism_markdown(worked, options));
  }
  void modes(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
             const std::vector<ModeCheck>* checks, const ReportOptions& options) override {
    out_ += "\n";
    out_ += shifted(modes_markdown(system, linear, modes, options, checks));
  }
  void table(const ResultTable& table, const std::string& caption) override {
    out_ += "\n";
    if (!caption.empty()) out_ += caption + "\n\n";
    out_ += pipe_table(table);
  }
  void figure(const FigureRef& f) override {
    if (!file_exists(f.path)) return;
    const std::string alt = f.caption.empty() ? f.name : f.caption;
    if (f.kind == FigureRef::Kind::file) {
      out_ += "\nFile: [" + f.name + "](" + f.name + ")" + (f.caption.empty() ? "" : " — " + f.caption) + "\n";
      return;
    }
    if (f.kind == FigureRef::Kind::video) {
      // A GIF plays as an image (a <video> element does not take one).
      if (f.path.extension() == ".gif")
        out_ += "\n<img src=\"" + f.name + "\" alt=\"" + f.name + "\" width=\"640\">\n\n";
      else
        out_ += "\n<video src=\"" + f.name + "\" controls muted loop width=\"640\"></video>\n\n";
      out_ += "[▶ " + f.name + "](" + f.name + ")";
    } else {
      // The caption in the image's own paragraph: once in every reader (pandoc makes a
      // lone image a figure captioned with its alt text, which would repeat it).
      out_ += "\n![" + alt + "](" + f.name + ")\n";
      if (!f.caption.empty()) out_ += "*" + f.caption + "*\n";
      return;
    }
    out_ += "\n";
    if (!f.caption.empty()) out_ += "\n*" + f.caption + "*\n";
  }
  // Unicode math in prose (θ₂, m/s², −) as TeX inline math, so pandoc's PDF builds.
  [[nodiscard]] std::string take() override { return tex_math_in_prose(Writer::take()); }
  void exercise(const std::string& question, const std::string& answer, const std::string& explanation) override {
    out_ += "\n**Exercise.** " + question + "\n\n<details><summary>Answer</summary>\n\n" + answer +
            (explanation.empty() ? "" : "\n\n" + explanation) + "\n\n</details>\n";
  }
};

class LatexWriter final : public Writer {
 public:
  /// `relative_files`: figures by their names in the output folder (a handout compiled
  /// there), else by their paths (LaTeX printed to the terminal).
  explicit LatexWriter(bool relative_files) : relative_files_(relative_files) {}
  void title(const std::string& title, const std::string& description) override {
    out_ += "% Needs \\usepackage{amsmath,graphicx,hyperref}.\n\\section*{" + inline_latex(title) + "}\n\n";
    if (!description.empty()) out_ += markdown_to_latex(description);
  }
  void heading(const std::string& text) override { out_ += "\\subsection*{" + inline_latex(text) + "}\n\n"; }
  void markdown(const std::string& text) override { out_ += markdown_to_latex(text); }
  void worked_solution(const MechanismSolution& worked, const ReportOptions& options) override {
    out_ += mechanism_latex(worked, options) + "\n";
  }
  void modes(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
             const std::vector<ModeCheck>* checks, const ReportOptions& options) override {
    out_ += modes_latex(system, linear, modes, options, checks) + "\n";
  }
  void table(const ResultTable& table, const std::string& caption) override {
    std::string tabular = markdown_to_latex(pipe_table(table));
    tabular.pop_back();  // the blank line after it
    out_ += concat({"\\begin{center}\n", tabular, "\\end{center}\n"});
    if (!caption.empty()) out_ += markdown_to_latex(caption);
    out_ += "\n";
  }
  void figure(const FigureRef& f) override {
    if (!file_exists(f.path)) return;
    const std::string file = relative_files_ ? f.name : f.path.generic_string();
    // graphicx reads PNG and PDF: clips, data files and SVG figures are linked instead.
    if (f.kind != FigureRef::Kind::image || f.path.extension() == ".svg") {
      out_ += std::string(f.kind == FigureRef::Kind::video ? "\\noindent Clip: " : "\\noindent File: ") + "\\href{" +
              file + "}{\\texttt{" + latex_escape(f.name) + "}}";
      if (!f.caption.empty()) out_ += " --- " + inline_latex(f.caption);
      out_ += "\n\n";
      return;
    }
    out_ += "\\begin{figure}[h]\n  \\centering\n  \\includegraphics[width=0.8\\linewidth]{" + file + "}\n";
    if (!f.caption.empty()) out_ += "\n  {\\small " + inline_latex(f.caption) + "}\n";
    out_ += "\\end{figure}\n\n";
  }
  void exercise(const std::string& question, const std::string& answer, const std::string& explanation) override {
    out_ +=
        "\\paragraph{Exercise.} " + markdown_to_latex(question) + "\\textbf{Answer:} " + inline_latex(answer) + "\n\n";
    if (!explanation.empty()) out_ += markdown_to_latex(explanation);
  }

 private:
  bool relative_files_ = false;
};

}  // namespace

std::unique_ptr<Writer> make_markdown_writer() { return std::make_unique<MarkdownWriter>(); }
std::unique_ptr<Writer> make_latex_writer(bool relative_files) { return std::make_unique<LatexWriter>(relative_files); }

std::string latex_document(const std::string& body) {
  return "\\documentclass[11pt]{article}\n"
         "\\usepackage[T1]{fontenc}\n\\usepackage[utf8]{inputenc}\n\\usepackage{lmodern}\n"
         "\\usepackage{amsmath,amssymb,graphicx}\n\\usepackage[margin=2.5cm]{geometry}\n"
         "\\usepackage[hidelinks]{hyperref}\n\\begin{document}\n" +
         body + "\\end{document}\n";
}

std::filesystem::path compile_latex_pdf(const std::filesystem::path& tex) {
  // Made under a temporary job name and renamed, so a failed run leaves no partial PDF
  // (and its log as NAME.log, which the error names). The lesson text in the document may
  // come from anyone: no shell escape (\write18), and no shell reading the command.
  const std::filesystem::path dir = tex.parent_path().empty() ? "." : tex.parent_path();
  const std::string stem = tex.stem().string();
  const std::string job = stem + "-pdf-partial";  // not a dot file: TeX refuses to write those
  ProgramRun run;
  run.argv = {"pdflatex",       "-no-shell-escape", "-interaction=nonstopmode",
              "-halt-on-error", "-jobname=" + job,  tex.filename().string()};
  run.directory = dir;
  run.timeout = kPdfTimeout;
  const ProgramResult result = run_program(run);
  std::error_code ignored;
  for (const char* ext : {".aux", ".out"}) std::filesystem::remove(dir / (job + ext), ignored);
  const std::filesystem::path log = dir / (stem + ".log");
  if (!result.succeeded() || !std::filesystem::exists(dir / (job + ".pdf"))) {
    std::filesystem::remove(dir / (job + ".pdf"), ignored);
    std::filesystem::rename(dir / (job + ".log"), log, ignored);
    throw Error::failure("pdf", "pdflatex could not compile " + tex.string() +
                                    (result.timed_out ? " within " + std::to_string(kPdfTimeout.count()) + " s" : "") +
                                    "; its log is " + log.string());
  }
  std::filesystem::remove(dir / (job + ".log"), ignored);
  std::filesystem::remove(log, ignored);
  std::filesystem::rename(dir / (job + ".pdf"), dir / (stem + ".pdf"));
  return dir / (stem + ".pdf");
}

std::unique_ptr<Writer> make_writer(DocumentFormat format, std::size_t width, Style style) {
  if (format == DocumentFormat::markdown) return make_markdown_writer();
  if (format == DocumentFormat::latex) return make_latex_writer();
  return std::make_unique<TextWriter>(width, style);
}

}  // namespace linkage
