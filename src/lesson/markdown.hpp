#pragma once
// The lesson's Markdown (say text, questions, explanations) for a terminal and for
// LaTeX. Only the Markdown lessons use is understood: paragraphs, headings, bullet and
// numbered lists, block quotes, fenced code, $$ math blocks $$, pipe tables, and inline
// **bold**, *emphasis*, `code`, $math$ and [links](url).
#include <string>
#include <string_view>

namespace linkage::lesson {

/// Plain text for a terminal `width` columns wide: paragraphs and list items wrapped at
/// spaces, emphasis markers and math dollars dropped, links as "text (url)", headings
/// underlined, quotes and code indented, tables kept as written. Throws Error::input
/// naming the line and column for nesting beyond kMaxNesting (see check_markdown).
[[nodiscard]] std::string markdown_to_text(std::string_view markdown, std::size_t width);

/// A LaTeX fragment: paragraphs, \subsection*, itemize/enumerate, quote, verbatim,
/// \[ \], tabular; inline markup converted, special characters escaped, and Greek
/// letters, sub/superscript digits, dotted symbols (θ̇₁) and operators (× − ≤) in math,
/// so it compiles with pdflatex.
[[nodiscard]] std::string markdown_to_latex(std::string_view markdown);

/// Text-mode LaTeX of one line of inline Markdown (used for titles and captions).
[[nodiscard]] std::string inline_latex(std::string_view text);

/// Throws Error::input, starting with `origin` (e.g. "file:3:8: step 1 (say): text"),
/// for Markdown these functions refuse: math or lists nested more than kMaxNesting
/// levels deep. So a lesson fails when it is read, not halfway through a run.
void check_markdown(std::string_view markdown, const std::string& origin);

}  // namespace linkage::lesson
