#pragma once
// The lesson's Markdown (say text, questions, explanations) and the reports' for a
// terminal, for LaTeX and for HTML (a clip's page). The text is CommonMark with GitHub's pipe tables and strikethrough,
// and $...$ and $$...$$ LaTeX math, parsed by md4c; raw HTML is not interpreted.
#include <string>
#include <string_view>
#include <vector>

namespace linkage {

/// Plain text for a terminal `width` columns wide: paragraphs and list items wrapped at
/// spaces (nested lists indented per level), emphasis markers dropped, links as
/// "text (url)", headings underlined, quotes behind a bar, code indented, tables with
/// their columns lined up, math in Unicode. Throws Error::input naming the line and
/// column for nesting beyond kMaxNesting (see check_markdown).
[[nodiscard]] std::string markdown_to_text(std::string_view markdown, std::size_t width);

/// A LaTeX fragment: paragraphs, \subsection*, itemize/enumerate, quote, verbatim,
/// \[ \], tabular; inline markup converted, special characters escaped, and Greek
/// letters, sub/superscript digits, dotted symbols (θ̇₁) and operators (× − ≤) in math,
/// so it compiles with pdflatex.
[[nodiscard]] std::string markdown_to_latex(std::string_view markdown);

/// An HTML fragment: headings, paragraphs, lists, quotes, code, tables (columns aligned by
/// align attributes), emphasis and links (kept only to http, https, mailto or relative
/// targets); $...$ and $$...$$ as MathML (latex_mathml.hpp), whose unknown commands are
/// appended to `unknown` if given. Every text is escaped: raw HTML in the Markdown is text.
[[nodiscard]] std::string markdown_to_html(std::string_view markdown, std::vector<std::string>* unknown = nullptr);

/// Text-mode LaTeX of one line of inline Markdown (used for titles and captions); a
/// start that would open a block ("1. ", "# ") is kept as text.
[[nodiscard]] std::string inline_latex(std::string_view text);

/// "line 3, column 17" of the character `at` points to in `markdown` (columns count
/// characters, not bytes).
[[nodiscard]] std::string text_position(std::string_view markdown, const char* at);

/// Throws Error::input, starting with `origin` (e.g. "file:3:8: step 1 (say): text"),
/// for Markdown these functions refuse: math, lists and quotes, or emphasis and links
/// nested more than kMaxNesting levels deep. So a lesson fails when it is read, not
/// halfway through a run.
void check_markdown(std::string_view markdown, const std::string& origin);

}  // namespace linkage
