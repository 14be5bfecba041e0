#include "lesson/latex_text.hpp"

#include <array>
#include <cctype>
#include <utility>

#include "core/limits.hpp"

namespace linkage::lesson {
namespace {

using Pair = std::pair<std::string_view, std::string_view>;

constexpr std::array<Pair, 71> kSymbols{{
    {"alpha", "α"},
    {"beta", "β"},
    {"gamma", "γ"},
    {"delta", "δ"},
    {"epsilon", "ε"},
    {"varepsilon", "ε"},
    {"zeta", "ζ"},
    {"eta", "η"},
    {"theta", "θ"},
    {"vartheta", "ϑ"},
    {"kappa", "κ"},
    {"lambda", "λ"},
    {"mu", "μ"},
    {"nu", "ν"},
    {"xi", "ξ"},
    {"pi", "π"},
    {"rho", "ρ"},
    {"sigma", "σ"},
    {"tau", "τ"},
    {"phi", "φ"},
    {"varphi", "φ"},
    {"chi", "χ"},
    {"psi", "ψ"},
    {"omega", "ω"},
    {"Gamma", "Γ"},
    {"Delta", "Δ"},
    {"Theta", "Θ"},
    {"Lambda", "Λ"},
    {"Sigma", "Σ"},
    {"Phi", "Φ"},
    {"Psi", "Ψ"},
    {"Omega", "Ω"},
    {"cdot", "·"},
    {"times", "×"},
    {"pm", "±"},
    {"mp", "∓"},
    {"approx", "≈"},
    {"neq", "≠"},
    {"ne", "≠"},
    {"le", "≤"},
    {"leq", "≤"},
    {"ge", "≥"},
    {"geq", "≥"},
    {"ll", "≪"},
    {"gg", "≫"},
    {"to", "→"},
    {"rightarrow", "→"},
    {"implies", "⇒"},
    {"Longrightarrow", "⟹"},
    {"infty", "∞"},
    {"partial", "∂"},
    {"nabla", "∇"},
    {"int", "∫"},
    {"sum", "Σ"},
    {"propto", "∝"},
    {"equiv", "≡"},
    {"lVert", "‖"},
    {"rVert", "‖"},
    {"|", "‖"},
    {"langle", "⟨"},
    {"rangle", "⟩"},
    {"sin", "sin"},
    {"cos", "cos"},
    {"tan", "tan"},
    {"exp", "exp"},
    {"ln", "ln"},
    {"log", "log"},
    {"quad", "  "},
    {"qquad", "    "},
    {"dots", "…"},
    {"ldots", "…"},
}};

constexpr std::array<Pair, 4> kAccents{{{"dot", "\u0307"}, {"ddot", "\u0308"}, {"hat", "\u0302"}, {"bar", "\u0304"}}};

// Digits and signs have Unicode sub- and superscript forms everywhere; letters only
// patchily (there is a subscript x but no y), so letters keep the _ and ^ marks.
constexpr std::array<Pair, 15> kSub{{
    {"0", "₀"},
    {"1", "₁"},
    {"2", "₂"},
    {"3", "₃"},
    {"4", "₄"},
    {"5", "₅"},
    {"6", "₆"},
    {"7", "₇"},
    {"8", "₈"},
    {"9", "₉"},
    {"+", "₊"},
    {"-", "₋"},
    {"=", "₌"},
    {"(", "₍"},
    {")", "₎"},
}};
constexpr std::array<Pair, 15> kSup{{
    {"0", "⁰"},
    {"1", "¹"},
    {"2", "²"},
    {"3", "³"},
    {"4", "⁴"},
    {"5", "⁵"},
    {"6", "⁶"},
    {"7", "⁷"},
    {"8", "⁸"},
    {"9", "⁹"},
    {"+", "⁺"},
    {"-", "⁻"},
    {"=", "⁼"},
    {"(", "⁽"},
    {")", "⁾"},
}};

template <std::size_t N>
std::string_view lookup(const std::array<Pair, N>& table, std::string_view key) {
  for (const Pair& p : table)
    if (p.first == key) return p.second;
  return {};
}

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

  // A sub- or superscript in Unicode when every character has a form, else marked by
  // `mark` ("_" or "^"), in parentheses unless it is letters and digits only.
  std::string script(const auto& table, char mark) {
    const std::string body = group();
    std::string mapped;
    bool plain = !body.empty();
    for (char c : body) plain = plain && std::isalnum(static_cast<unsigned char>(c));
    for (std::size_t i = 0; i < body.size(); ++i) {
      const std::string_view m = lookup(table, std::string_view(&body[i], 1));
      if (m.empty() || static_cast<unsigned char>(body[i]) >= 0x80) break;
      mapped += m;
      if (i + 1 == body.size()) return mapped;
    }
    std::string out(1, mark);
    return plain ? out + body : out + "(" + body + ")";
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
        return " ";
      case '\n':
        return " ";  // only \\ breaks a line
      case '_':
        return script(kSub, '_');
      case '^':
        return script(kSup, '^');
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
      return wrap(a) + "/" + wrap(b);
    }
    if (name == "sqrt") return "√" + wrap(group());
    if (const std::string_view mark = lookup(kAccents, name); !mark.empty()) {
      std::string base = group();
      return base + std::string(mark);
    }
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
    if (name == "tag") return "   (" + group() + ")";
    if (const std::string_view symbol = lookup(kSymbols, name); !symbol.empty()) {
      // A function name is a word: apart from what precedes it (see run()) and what follows.
      const bool word = std::isalpha(static_cast<unsigned char>(symbol.front())) != 0;
      return word ? kWordStart + std::string(symbol) + " " : std::string(symbol);
    }
    return std::string(name);
  }

  // Parentheses around a fraction's part unless it is one symbol.
  static std::string wrap(const std::string& part) {
    const bool simple = part.find_first_of(" +-−·×/") == std::string::npos;
    return simple ? part : "(" + part + ")";
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  int matrix_depth_ = 0;
  int depth_ = 0;
};

}  // namespace

LatexNestingError::LatexNestingError(const char* at)
    : Error(ExitCode::bad_input,
            "the math is nested more than " + std::to_string(kMaxNesting) +
                " levels deep (each {...} and each argument of \\sqrt, \\frac, ^ or _ is a level)"),
      at_(at) {}

std::string latex_to_unicode(std::string_view latex) { return Converter(latex).run(); }

}  // namespace linkage::lesson
