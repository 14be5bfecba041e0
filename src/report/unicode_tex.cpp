#include "report/unicode_tex.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "core/limits.hpp"
#include "report/notation.hpp"
#include "report/text_layout.hpp"

namespace linkage {
namespace {

// How a symbol reads in prose: a letter takes dots and scripts (θ̇₁), an operator stands
// alone (×); `from_tex` symbols are only read from TeX (prose keeps · and … as they are).
using Kind = TexSymbolKind;

struct Symbol {
  std::string_view text;  // UTF-8
  std::string_view tex;
  Kind kind = Kind::letter;
};

// Where several TeX names share a character, the first is the one prose gets. Accents
// (\dot) are combining marks, written after their base.
// clang-format off
constexpr std::array<Symbol, 98> kSymbols{{
    {"α", "\\alpha"}, {"β", "\\beta"}, {"γ", "\\gamma"}, {"δ", "\\delta"}, {"ε", "\\varepsilon"}, {"ε", "\\epsilon"},
    {"ζ", "\\zeta"}, {"η", "\\eta"}, {"θ", "\\theta"}, {"ϑ", "\\vartheta"}, {"ι", "\\iota"}, {"κ", "\\kappa"},
    {"λ", "\\lambda"}, {"μ", "\\mu"}, {"ν", "\\nu"}, {"ξ", "\\xi"}, {"π", "\\pi"}, {"ρ", "\\rho"}, {"σ", "\\sigma"},
    {"τ", "\\tau"}, {"υ", "\\upsilon"}, {"φ", "\\varphi"}, {"φ", "\\phi"}, {"ϕ", "\\phi"}, {"χ", "\\chi"},
    {"ψ", "\\psi"}, {"ω", "\\omega"}, {"Γ", "\\Gamma"}, {"Δ", "\\Delta"}, {"Θ", "\\Theta"}, {"Λ", "\\Lambda"},
    {"Ξ", "\\Xi"}, {"Π", "\\Pi"}, {"Σ", "\\Sigma"}, {"Φ", "\\Phi"}, {"Ψ", "\\Psi"}, {"Ω", "\\Omega"},
    {"ẋ", "\\dot{x}"}, {"ẍ", "\\ddot{x}"}, {"ẏ", "\\dot{y}"}, {"ÿ", "\\ddot{y}"}, {"ℓ", "\\ell"}, {"∂", "\\partial"},
    {"∇", "\\nabla"}, {"−", "-", Kind::op}, {"×", "\\times", Kind::op}, {"·", "\\cdot", Kind::from_tex},
    {"∙", "\\cdot", Kind::op}, {"⋅", "\\cdot", Kind::op}, {"÷", "\\div", Kind::op}, {"±", "\\pm", Kind::op},
    {"∓", "\\mp", Kind::op}, {"→", "\\to", Kind::op}, {"→", "\\rightarrow", Kind::op}, {"←", "\\leftarrow", Kind::op},
    {"⇒", "\\Rightarrow", Kind::op}, {"⇒", "\\implies", Kind::op}, {"⟹", "\\Longrightarrow", Kind::op},
    {"≈", "\\approx", Kind::op}, {"≠", "\\neq", Kind::op}, {"≠", "\\ne", Kind::op}, {"≤", "\\le", Kind::op},
    {"≤", "\\leq", Kind::op}, {"≥", "\\ge", Kind::op}, {"≥", "\\geq", Kind::op}, {"≪", "\\ll", Kind::op},
    {"≫", "\\gg", Kind::op}, {"≡", "\\equiv", Kind::op}, {"∝", "\\propto", Kind::op}, {"∼", "\\sim", Kind::op},
    {"∈", "\\in", Kind::op}, {"∞", "\\infty", Kind::op}, {"‖", "\\|", Kind::op}, {"‖", "\\lVert", Kind::op},
    {"‖", "\\rVert", Kind::op}, {"⟨", "\\langle", Kind::op}, {"⟩", "\\rangle", Kind::op}, {"√", "\\surd", Kind::op},
    {"∑", "\\sum", Kind::op}, {"∫", "\\int", Kind::op}, {"°", "^{\\circ}", Kind::op}, {"′", "'", Kind::op},
    {"″", "''", Kind::op}, {"▶", "\\blacktriangleright", Kind::op}, {"sin", "\\sin", Kind::from_tex},
    {"cos", "\\cos", Kind::from_tex}, {"tan", "\\tan", Kind::from_tex}, {"exp", "\\exp", Kind::from_tex},
    {"ln", "\\ln", Kind::from_tex}, {"log", "\\log", Kind::from_tex}, {"  ", "\\quad", Kind::from_tex},
    {"    ", "\\qquad", Kind::from_tex}, {"…", "\\dots", Kind::from_tex}, {"…", "\\ldots", Kind::from_tex},
    {"\u0307", "\\dot", Kind::from_tex}, {"\u0308", "\\ddot", Kind::from_tex}, {"\u0302", "\\hat", Kind::from_tex},
    {"\u0304", "\\bar", Kind::from_tex}}};
// clang-format on

// The symbol a character is in prose: a letter or an operator.
const Symbol* prose_symbol(char32_t cp) {
  const std::string text = encode_utf8(cp);
  for (const Symbol& s : kSymbols)
    if (s.text == text) return s.kind == Kind::from_tex ? nullptr : &s;
  return nullptr;
}

// The Unicode text of the TeX command \name.
std::string_view from_tex(std::string_view name) {
  const std::optional<TexCommand> c = tex_command(name);
  return c ? c->text : std::string_view{};
}

// Sub- and superscript forms; digits and signs have both, letters only a few.
struct Script {
  char ascii;
  char32_t sub, sup;
};
constexpr std::array<Script, 27> kScripts{
    {{'0', U'₀', U'⁰'}, {'1', U'₁', U'¹'}, {'2', U'₂', U'²'}, {'3', U'₃', U'³'}, {'4', U'₄', U'⁴'}, {'5', U'₅', U'⁵'},
     {'6', U'₆', U'⁶'}, {'7', U'₇', U'⁷'}, {'8', U'₈', U'⁸'}, {'9', U'₉', U'⁹'}, {'+', U'₊', U'⁺'}, {'-', U'₋', U'⁻'},
     {'=', U'₌', U'⁼'}, {'(', U'₍', U'⁽'}, {')', U'₎', U'⁾'}, {'a', U'ₐ', 0},    {'e', U'ₑ', 0},    {'o', U'ₒ', 0},
     {'x', U'ₓ', 0},    {'h', U'ₕ', 0},    {'k', U'ₖ', 0},    {'l', U'ₗ', 0},    {'m', U'ₘ', 0},    {'n', U'ₙ', U'ⁿ'},
     {'p', U'ₚ', 0},    {'s', U'ₛ', 0},    {'t', U'ₜ', 0}}};

// --- Unicode -> TeX -----------------------------------------------------------------

bool is_mark(char32_t cp) { return cp == 0x0307 || cp == 0x0308 || script_char(cp); }

// ¹ ² ³ are Latin-1: pdflatex prints them in text as they are (m/s² stays upright), so
// after a plain letter or alone they are left alone.
bool latin1_superscript(char32_t cp) { return cp == U'¹' || cp == U'²' || cp == U'³'; }

bool ascii_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// Ends an inline math span. Digits right after it join it: pandoc does not take a "$"
// followed by a digit as closing ("8$\times$8" would stay text), so "8×8" is "8$\times 8$".
void close_math(std::string_view s, std::size_t& i, std::string& out) {
  if (i < s.size() && s[i] >= '0' && s[i] <= '9') {
    if (std::isalpha(static_cast<unsigned char>(out.back())) != 0) out += ' ';
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') out += s[i++];
  }
  out += '$';
}

// Converts prose (no math or code inside) run by run.
void convert_prose(std::string_view s, std::string& out) {
  std::size_t i = 0;
  while (i < s.size()) {
    const Utf8Char d = decode_utf8(s, i);
    const Symbol* symbol = d.size > 1 ? prose_symbol(d.cp) : nullptr;
    const bool letter = symbol != nullptr && symbol->kind == Kind::letter;
    const bool ascii_base = d.size == 1 && ascii_letter(s[i]) && i + 1 < s.size() &&
                            is_mark(decode_utf8(s, i + 1).cp) && !latin1_superscript(decode_utf8(s, i + 1).cp);
    const bool bare_mark = is_mark(d.cp) && !latin1_superscript(d.cp);  // 10⁻⁹: marks with no letter before
    if (!letter && !ascii_base && !bare_mark) {
      if (symbol != nullptr) {
        out += concat({"$", symbol->tex});
        i += d.size;
        close_math(s, i, out);
        continue;
      }
      out.append(s.substr(i, d.size));
      i += d.size;
      continue;
    }
    // A symbol: base, dots, subscripts, superscripts.
    std::string base = letter ? std::string(symbol->tex) : bare_mark ? "{}" : std::string(1, s[i]);
    if (!bare_mark) i += d.size;
    std::string sub, sup;
    int dots = 0;
    while (i < s.size()) {
      const Utf8Char m = decode_utf8(s, i);
      const auto script = script_char(m.cp);
      if (m.cp == 0x0307 || m.cp == 0x0308)
        dots += m.cp == 0x0307 ? 1 : 2;
      else if (script)
        (script->superscript ? sup : sub) += script->ascii;
      else
        break;
      i += m.size;
    }
    if (dots > 0) base = concat({dots == 1 ? "\\dot{" : "\\ddot{", base, "}"});
    out += "$" + base;
    if (!sub.empty()) out += concat({"_{", sub, "}"});
    if (!sup.empty()) out += concat({"^{", sup, "}"});
    close_math(s, i, out);
  }
}

// --- TeX -> Unicode -----------------------------------------------------------------

// Marks where a function name starts, so run() can put a space before it when needed.
constexpr char kWordStart = '\x01';

class Converter {
 public:
  explicit Converter(std::string_view s) : s_(s) {}

  std::string run() {
    std::string out = sequence('\0');
    // Tidy the spacing the commands leave behind.
    std::string tidy;
    for (char c : out) {
      if (c == kWordStart) {
        if (!tidy.empty() && std::string_view(" ([{\n").find(tidy.back()) == std::string_view::npos) tidy += ' ';
        continue;
      }
      // No space before a line end or closing punctuation, none after an opening one.
      if (c == '\n' || c == ',' || c == ';' || c == ')' || c == ']')
        while (!tidy.empty() && tidy.back() == ' ') tidy.pop_back();
      if (!(c == ' ' && (tidy.empty() || std::string_view(" \n([").find(tidy.back()) != std::string_view::npos)))
        tidy += c;
    }
    while (!tidy.empty() && (tidy.back() == ' ' || tidy.back() == '\n')) tidy.pop_back();
    return tidy;
  }

 private:
  // Everything up to `stop` (a closing brace) or the end.
  std::string sequence(char stop) {
    std::string out;
    while (pos_ < s_.size() && s_[pos_] != stop) out += atom();
    if (pos_ < s_.size()) ++pos_;  // the stop character
    return out;
  }

  // One group: {…} or a single command or character.
  std::string group() {
    while (pos_ < s_.size() && s_[pos_] == ' ') ++pos_;
    if (pos_ >= s_.size()) return {};
    // Every recursion passes through here or an opening brace, a level deeper each time.
    const NestingLevel level(depth_);
    if (level.too_deep()) throw LatexNestingError(s_.data() + pos_);
    if (s_[pos_] == '{') {
      ++pos_;
      return sequence('}');
    }
    return atom();
  }

  // A sub- or superscript in Unicode when every character has a form (digits and signs:
  // letters have too few forms to mix), else marked by `mark` ("_" or "^"), in
  // parentheses unless it is letters and digits only.
  std::string script(char mark) {
    const std::string body = group();
    std::string mapped;
    bool plain = !body.empty();
    for (char c : body) plain = plain && std::isalnum(static_cast<unsigned char>(c));
    for (std::size_t i = 0; i < body.size() && std::isalpha(static_cast<unsigned char>(body[i])) == 0; ++i) {
      const auto* s =
          std::find_if(kScripts.begin(), kScripts.end(), [&](const Script& e) { return e.ascii == body[i]; });
      if (s == kScripts.end()) break;
      mapped += encode_utf8(mark == '^' ? s->sup : s->sub);
      if (i + 1 == body.size()) return mapped;
    }
    std::string out(1, mark);
    return plain ? out + body : concat({out, "(", body, ")"});
  }

  std::string atom() {
    const char c = s_[pos_];
    if (c == '\\') return command();
    ++pos_;
    switch (c) {
      case '{': {
        const NestingLevel level(depth_);
        if (level.too_deep()) throw LatexNestingError(s_.data() + pos_ - 1);
        return sequence('}');
      }
      case '}':
        return {};
      case '&':
        return matrix_depth_ > 0 ? ", " : "";
      case '~':
      case '\n':  // only \\ breaks a line
        return " ";
      case '_':
      case '^':
        return script(c);
      default:
        return std::string(1, c);
    }
  }

  std::string command() {
    ++pos_;  // the backslash
    if (pos_ >= s_.size()) return {};
    const std::size_t start = pos_;
    if (!std::isalpha(static_cast<unsigned char>(s_[pos_]))) {
      const char c = s_[pos_++];
      if (c == '\\') return matrix_depth_ > 0 ? "; " : "\n";
      if (c == ',' || c == ';' || c == ':' || c == ' ') return " ";
      if (c == '!') return {};
      if (c == '|') return "‖";
      return std::string(1, c);  // \{ \} \% ...
    }
    while (pos_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    const std::string_view name = s_.substr(start, pos_ - start);
    if (name == "frac" || name == "dfrac" || name == "tfrac") {
      const std::string a = group(), b = group();
      return concat({wrap(a), "/", wrap(b)});
    }
    if (name == "sqrt") return "√" + wrap(group());
    if (name == "dot" || name == "ddot" || name == "hat" || name == "bar") return group() + std::string(from_tex(name));
    if (name == "begin" || name == "end") {
      // A matrix reads inline, [a, b; c, d]; other environments (aligned, ...) vanish.
      const std::string env = group();
      const bool round = env == "pmatrix";
      if (env != "bmatrix" && env != "pmatrix" && env != "matrix") return {};
      matrix_depth_ += name == "begin" ? 1 : -1;
      return name == "begin" ? (round ? "(" : "[") : (round ? ")" : "]");
    }
    if (name == "left" || name == "right" || name == "big" || name == "Big" || name == "bigl" || name == "bigr") {
      if (pos_ < s_.size() && s_[pos_] == '.') ++pos_;
      return {};
    }
    if (name == "mathrm" || name == "text" || name == "mathbf" || name == "boldsymbol" || name == "mathit" ||
        name == "operatorname" || name == "mathcal")
      return group();
    if (name == "tag") return concat({"   (", group(), ")"});
    if (const std::string_view symbol = from_tex(name); !symbol.empty()) {
      // A function name is a word: apart from what precedes it (see run()) and what follows.
      const bool word = std::isalpha(static_cast<unsigned char>(symbol.front())) != 0;
      return word ? concat({std::string_view(&kWordStart, 1), symbol, " "}) : std::string(symbol);
    }
    return std::string(name);
  }

  // Parentheses around a fraction's part unless it is one symbol.
  static std::string wrap(const std::string& part) {
    const bool simple = part.find_first_of(" +-−·×/") == std::string::npos;
    return simple ? part : concat({"(", part, ")"});
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  int matrix_depth_ = 0;
  int depth_ = 0;
};

}  // namespace

std::optional<TexCommand> tex_command(std::string_view name) {
  for (const Symbol& s : kSymbols)
    if (s.tex.starts_with('\\') && s.tex.substr(1) == name) return TexCommand{s.text, s.kind};
  return std::nullopt;
}

std::optional<ScriptChar> script_char(char32_t cp) {
  for (const Script& s : kScripts)
    if (s.sub == cp || s.sup == cp) return ScriptChar{s.ascii, s.sup == cp};
  return std::nullopt;
}

std::string_view tex_symbol(char32_t cp) {
  const Symbol* s = prose_symbol(cp);
  return s != nullptr ? s->tex : std::string_view{};
}

std::string tex_math_in_prose(std::string_view md) {
  std::string out;
  out.reserve(md.size() + md.size() / 8);
  std::size_t i = 0, prose = 0;
  const auto flush = [&](std::size_t end) { convert_prose(md.substr(prose, end - prose), out); };
  bool line_start = true;
  while (i < md.size()) {
    // Fenced code: from a line starting with ``` to the next such line, untouched.
    if (line_start && md.substr(i).starts_with("```")) {
      flush(i);
      std::size_t end = md.find("\n```", i + 3);
      end = end == std::string_view::npos ? md.size() : md.find('\n', end + 4);
      if (end == std::string_view::npos) end = md.size();
      out.append(md.substr(i, end - i));
      i = prose = end;
      continue;
    }
    const char c = md[i];
    if (c == '`' || c == '$') {
      // A code span or a math span ($...$ or $$...$$): copied as it is.
      const std::string_view fence = c == '$' && md.substr(i).starts_with("$$") ? "$$" : md.substr(i, 1);
      const std::size_t close = md.find(fence, i + fence.size());
      if (close != std::string_view::npos) {
        flush(i);
        out.append(md.substr(i, close + fence.size() - i));
        i = prose = close + fence.size();
        line_start = false;
        continue;
      }
    }
    line_start = c == '\n';
    ++i;
  }
  flush(md.size());
  return out;
}

LatexNestingError::LatexNestingError(const char* at)
    : Error(ExitCode::bad_input,
            concat({"the math is nested more than ", std::to_string(kMaxNesting),
                    " levels deep (each {...} and each argument of \\sqrt, \\frac, ^ or _ is a level)"})),
      at_(at) {}

std::string latex_to_unicode(std::string_view latex) { return Converter(latex).run(); }

}  // namespace linkage
