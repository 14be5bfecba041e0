#pragma once
// A document in three formats: plain text for a terminal, Markdown and LaTeX (a lesson
// prints to all three at once). The caller says *what* to show; a Writer decides how it
// looks. Writers accumulate text; take() hands it over.
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/result_table.hpp"
#include "report/mechanism_solution.hpp"
#include "report/modes_report.hpp"
#include "report/report_options.hpp"

namespace linkage {

enum class DocumentFormat { text, markdown, latex };

/// A file a step wrote, as the reader should see it.
struct FigureRef {
  enum class Kind { image, video, file };
  std::filesystem::path path;  // where it is (the output folder joined with the name)
  std::string name;            // the file name, relative to the output folder
  Kind kind = Kind::image;
  std::string caption;
};

class Writer {
 public:
  virtual ~Writer() = default;
  /// The lesson's title and its description (Markdown).
  virtual void title(const std::string& title, const std::string& description) = 0;
  /// A step's heading.
  virtual void heading(const std::string& text) = 0;
  /// A Markdown paragraph (say steps, questions, notes).
  virtual void markdown(const std::string& text) = 0;
  /// The worked solution of a solve step.
  virtual void worked_solution(const MechanismSolution& worked, const ReportOptions& options) = 0;
  /// The small vibrations of a modes step, as `linkage modes` prints them (`checks`: --verify's).
  virtual void modes(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                     const std::vector<ModeCheck>* checks, const ReportOptions& options) = 0;
  virtual void table(const ResultTable& table, const std::string& caption) = 0;
  /// A still, a clip, a plot or a data file. Writers that link files link only files
  /// that exist.
  virtual void figure(const FigureRef& figure) = 0;
  /// An exercise shown with its answer (not asked).
  virtual void exercise(const std::string& question, const std::string& answer, const std::string& explanation) = 0;

  /// The text written since the last take().
  [[nodiscard]] virtual std::string take() { return std::exchange(out_, {}); }

 protected:
  std::string out_;
};

/// Markdown: matrices as $$ math, figures as image embeds, clips as <video> with a link,
/// exercise answers folded in <details>.
[[nodiscard]] std::unique_ptr<Writer> make_markdown_writer();
/// A LaTeX fragment (needs amsmath, graphicx, hyperref).
[[nodiscard]] std::unique_ptr<Writer> make_latex_writer(bool relative_files = false);
/// A whole LaTeX document around a LaTeX writer's text: the handout lesson.tex.
[[nodiscard]] std::string latex_document(const std::string& body);
/// Compiles a LaTeX document (NAME.tex) to NAME.pdf beside it with pdflatex; no partial
/// PDF on failure (Error::failure naming NAME.log). Returns the PDF's path.
[[nodiscard]] std::filesystem::path compile_latex_pdf(const std::filesystem::path& tex);
/// The terminal's writer: for text, aligned for `width` columns with symbols in `style`.
[[nodiscard]] std::unique_ptr<Writer> make_writer(DocumentFormat format, std::size_t width, Style style);

}  // namespace linkage
