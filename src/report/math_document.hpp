#pragma once
// The building blocks the LaTeX and Markdown reports share (solve's derivation,
// mechanism_latex; the modes, modes_report): a heading, a paragraph, a display, a list
// and a table, written in either format. The caller gives LaTeX math and text already
// in the format; the document decides how each block is written around it.
#include <string>
#include <string_view>
#include <vector>

namespace linkage {

/// Markdown text with its special characters (\ ` * _ [ ] < > |) escaped.
[[nodiscard]] std::string markdown_escape(std::string_view text);

class MathDocument {
 public:
  enum class Format { latex, markdown };
  explicit MathDocument(Format format) : format_(format) {}

  [[nodiscard]] bool latex() const { return format_ == Format::latex; }
  /// The indentation of math rows: LaTeX's environments indent, Markdown's $$ does not.
  [[nodiscard]] std::string pad() const { return latex() ? "  " : ""; }
  /// Plain text escaped for the format.
  [[nodiscard]] std::string text(std::string_view plain) const;
  /// A run-in heading (LaTeX) or a ## heading (Markdown) with `note` (in the format) after it.
  void heading(std::string_view title, std::string_view note);
  void paragraph(std::string_view formatted);
  /// A paragraph that starts afresh in LaTeX rather than continuing after a display.
  void new_paragraph(std::string_view formatted);
  /// A $$ block (Markdown, or the body of another display).
  void math(std::string_view body);
  /// One unnumbered display: equation* or $$.
  void display(std::string_view body);
  /// Rows for align* (Markdown: aligned in $$).
  void aligned(std::string_view rows);
  /// An equation's label at the end of its row.
  [[nodiscard]] std::string tag(std::string_view label) const;
  void list(const std::vector<std::string>& items);
  /// `align` holds one of l, r per column; cells are already in the format.
  void table(const std::vector<std::string>& headers, std::string_view align,
             const std::vector<std::vector<std::string>>& rows);
  [[nodiscard]] static std::string inline_math(std::string_view tex);
  /// A number in a table cell: LaTeX math, or plain Markdown as the homework's tables.
  [[nodiscard]] std::string number_cell(double value, int digits) const;
  [[nodiscard]] std::string unit_cell(const std::string& ascii) const;

 protected:
  Format format_;
  std::string out_;
};

}  // namespace linkage
