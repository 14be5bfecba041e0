#pragma once
// Unicode math in Markdown prose (θ₂, ẍ₁, m/s², −, ×), as the text reports and lesson
// captions write it, turned into TeX inline math ($\theta_{2}$), so that a handout goes
// through pandoc's default PDF engine (pdflatex) and any TeX reader.
#include <string>
#include <string_view>

namespace linkage {

/// `markdown` with every run of Unicode math outside math spans ($...$, $$...$$), code
/// spans and fenced code written as TeX inline math. A symbol is a base (a Greek letter,
/// a dotted x or y, or an ASCII letter followed by a mark) with its dots, subscripts and
/// superscripts: "θ̈₂" -> "$\ddot{\theta}_{2}$", "m²" -> "$m^{2}$"; operators stand alone:
/// "−" -> "$-$", "×" -> "$\times$". Other text, typographic punctuation (’ “ ” – — …) and
/// accented letters pass through unchanged.
[[nodiscard]] std::string tex_math_in_prose(std::string_view markdown);

/// TeX math for one Unicode character: a Greek letter ("\theta"), a dotted x or y
/// ("\dot{x}"), or an operator ("\times", "-"); empty for any other character.
[[nodiscard]] std::string_view tex_symbol(char32_t cp);

}  // namespace linkage
