#pragma once
// Math between Unicode and TeX, both ways, from one table of symbols:
// - Unicode math in Markdown prose (θ₂, ẍ₁, m/s², −, ×), as the text reports and lesson
//   captions write it, turned into TeX inline math ($\theta_{2}$), so that a handout goes
//   through pandoc's default PDF engine (pdflatex) and any TeX reader;
// - LaTeX math turned into Unicode text, so a lesson's formulas read in a terminal:
//   \frac{m\,(w^2 + L^2)}{12} -> (m (w² + L²))/12, \ddot{\theta}_1 -> θ̈₁.
#include <optional>
#include <string>
#include <string_view>

#include "core/error.hpp"

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

/// How a TeX command of the table of symbols reads: a letter (θ, takes dots and scripts in
/// prose), an operator (×, stands alone), or read only from TeX (sin, ·, …, \quad's spaces,
/// the accents' combining marks).
enum class TexSymbolKind { letter, op, from_tex };
struct TexCommand {
  std::string_view text;  // UTF-8
  TexSymbolKind kind = TexSymbolKind::letter;
};
/// The command \name (`name` without its backslash) as the table reads it; nullopt for one
/// not in it.
[[nodiscard]] std::optional<TexCommand> tex_command(std::string_view name);

/// A Unicode sub- or superscript character (₂, ⁻, ₐ) as the ASCII character it stands for.
struct ScriptChar {
  char ascii = 0;
  bool superscript = false;
};
[[nodiscard]] std::optional<ScriptChar> script_char(char32_t cp);

/// Thrown (exit code 2) for math nested more than kMaxNesting levels deep. `at` points
/// into the text given to latex_to_unicode, at the first level too many, so a caller
/// holding the whole text can say where that is.
class LatexNestingError : public Error {
 public:
  explicit LatexNestingError(const char* at);
  [[nodiscard]] const char* at() const { return at_; }

 private:
  const char* at_;
};

/// LaTeX math as Unicode text: Greek letters, accents (\dot, \ddot, \hat, \bar), sub- and
/// superscripts (Unicode digits and signs, else _x / ^(x)), \frac, common operators and
/// functions, \left/\right, spacing and font commands, aligned environments (& is
/// dropped and a double backslash breaks the line) and matrices (written [a, b; c, d]).
/// Anything unknown is kept as written without its backslash. Math nested deeper than
/// kMaxNesting (core/limits.hpp) is refused, so hostile text cannot exhaust the stack.
[[nodiscard]] std::string latex_to_unicode(std::string_view latex);

}  // namespace linkage
