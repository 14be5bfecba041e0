#include "report/math_document.hpp"

#include "core/style.hpp"
#include "report/latex_math.hpp"
#include "report/notation.hpp"

namespace linkage {

std::string markdown_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (std::string_view("\\`*_[]<>|").find(c) != std::string_view::npos) out += '\\';
    out += c;
  }
  return out;
}

std::string MathDocument::text(std::string_view plain) const {
  return latex() ? latex_escape(plain) : markdown_escape(plain);
}

void MathDocument::heading(std::string_view title, std::string_view note) {
  if (latex()) {
    out_ += latex_heading(title, note);
    return;
  }
  out_ += concat({"\n## ", markdown_escape(title), "\n"});
  if (!note.empty()) paragraph(note);
}

void MathDocument::paragraph(std::string_view formatted) {
  out_ += latex() ? concat({formatted, "\n"}) : concat({"\n", formatted, "\n"});
}

void MathDocument::new_paragraph(std::string_view formatted) {
  paragraph(latex() ? concat({"\\par\\noindent ", formatted}) : std::string(formatted));
}

void MathDocument::math(std::string_view body) {
  // A line of "=" alone would underline the lines before it as a heading (CommonMark's
  // setext heading), ending the $$ block's paragraph: written "{}=", the same in TeX.
  std::string text;
  for (std::size_t start = 0; start < body.size();) {
    const std::size_t end = std::min(body.find('\n', start), body.size());
    const std::string_view line = body.substr(start, end - start);
    const std::size_t first = line.find_first_not_of(' ');
    text += first != std::string_view::npos && line.substr(first) == "=" ? concat({line.substr(0, first), "{}="})
                                                                         : std::string(line);
    if (end < body.size()) text += '\n';
    start = end + 1;
  }
  out_ += concat({"\n$$\n", text, "$$\n"});
}

void MathDocument::display(std::string_view body) {
  if (latex())
    out_ += concat({"\\begin{equation*}\n", body, "\\end{equation*}\n"});
  else
    math(body);
}

void MathDocument::aligned(std::string_view rows) {
  if (latex())
    out_ += concat({"\\begin{align*}\n", rows, "\\end{align*}\n"});
  else
    math(concat({"\\begin{aligned}\n", rows, "\\end{aligned}\n"}));
}

std::string MathDocument::tag(std::string_view label) const {
  return latex() ? concat({" \\tag{", label, "}"}) : concat({" && \\text{(", label, ")}"});
}

void MathDocument::list(const std::vector<std::string>& items) {
  if (latex()) {
    out_ += "\\begin{itemize}\n";
    for (const std::string& item : items) out_ += concat({"  \\item ", item, "\n"});
    out_ += "\\end{itemize}\n";
    return;
  }
  out_ += "\n";
  for (const std::string& item : items) out_ += concat({"- ", item, "\n"});
}

void MathDocument::table(const std::vector<std::string>& headers, std::string_view align,
                         const std::vector<std::vector<std::string>>& rows) {
  if (latex()) {
    out_ += concat({"\\begin{center}\n\\begin{tabular}{", align, "}\n  "});
    for (std::size_t c = 0; c < headers.size(); ++c) out_ += concat({c == 0 ? "" : " & ", headers[c]});
    out_ += " \\\\\n  \\hline\n";
    for (const auto& row : rows) {
      out_ += "  ";
      for (std::size_t c = 0; c < row.size(); ++c) out_ += concat({c == 0 ? "" : " & ", row[c]});
      out_ += " \\\\\n";
    }
    out_ += "\\end{tabular}\n\\end{center}\n";
    return;
  }
  out_ += "\n|";
  for (const std::string& h : headers) out_ += concat({" ", h, " |"});
  out_ += "\n|";
  for (char a : align) out_ += a == 'r' ? " --: |" : " :-- |";
  out_ += "\n";
  for (const auto& row : rows) {
    out_ += "|";
    for (const std::string& cell : row) out_ += concat({" ", cell, " |"});
    out_ += "\n";
  }
}

std::string MathDocument::inline_math(std::string_view tex) { return concat({"$", tex, "$"}); }

std::string MathDocument::number_cell(double value, int digits) const {
  return latex() ? inline_math(format_number(value, Style::latex, digits))
                 : format_number(value, Style::unicode, digits);
}

std::string MathDocument::unit_cell(const std::string& ascii) const {
  if (ascii.empty()) return "";
  return latex() ? inline_math(unit_text(ascii, Style::latex)) : unit_text(ascii, Style::unicode);
}

}  // namespace linkage
