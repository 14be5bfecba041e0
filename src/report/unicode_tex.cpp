#include "report/unicode_tex.hpp"

#include <array>
#include <cctype>
#include <cstdint>
#include <optional>

namespace linkage {
namespace {

struct Decoded {
  char32_t cp = 0;
  std::size_t size = 1;
};

Decoded decode(std::string_view s, std::size_t i) {
  const auto b = static_cast<unsigned char>(s[i]);
  const auto more = [&](std::size_t n) -> std::optional<Decoded> {
    char32_t cp = b & (n == 1 ? 0x1Fu : n == 2 ? 0x0Fu : 0x07u);
    for (std::size_t k = 1; k <= n; ++k) {
      if (i + k >= s.size()) return std::nullopt;
      const auto c = static_cast<unsigned char>(s[i + k]);
      if ((c & 0xC0u) != 0x80u) return std::nullopt;
      cp = (cp << 6) | (c & 0x3Fu);
    }
    return Decoded{cp, n + 1};
  };
  std::optional<Decoded> d;
  if (b >= 0xF0)
    d = more(3);
  else if (b >= 0xE0)
    d = more(2);
  else if (b >= 0xC0)
    d = more(1);
  return d.value_or(Decoded{b, 1});
}

struct Name {
  char32_t cp;
  const char* tex;
};

constexpr std::array<Name, 41> kLetters{{
    {U'α', "\\alpha"},   {U'β', "\\beta"},   {U'γ', "\\gamma"},   {U'δ', "\\delta"},   {U'ε', "\\varepsilon"},
    {U'ζ', "\\zeta"},    {U'η', "\\eta"},    {U'θ', "\\theta"},   {U'ι', "\\iota"},    {U'κ', "\\kappa"},
    {U'λ', "\\lambda"},  {U'μ', "\\mu"},     {U'ν', "\\nu"},      {U'ξ', "\\xi"},      {U'π', "\\pi"},
    {U'ρ', "\\rho"},     {U'σ', "\\sigma"},  {U'τ', "\\tau"},     {U'υ', "\\upsilon"}, {U'φ', "\\varphi"},
    {U'χ', "\\chi"},     {U'ψ', "\\psi"},    {U'ω', "\\omega"},   {U'Γ', "\\Gamma"},   {U'Δ', "\\Delta"},
    {U'Θ', "\\Theta"},   {U'Λ', "\\Lambda"}, {U'Ξ', "\\Xi"},      {U'Π', "\\Pi"},      {U'Σ', "\\Sigma"},
    {U'Φ', "\\Phi"},     {U'Ψ', "\\Psi"},    {U'Ω', "\\Omega"},   {U'ϕ', "\\phi"},     {U'ẋ', "\\dot{x}"},
    {U'ẍ', "\\ddot{x}"}, {U'ẏ', "\\dot{y}"}, {U'ÿ', "\\ddot{y}"}, {U'ℓ', "\\ell"},     {U'∂', "\\partial"},
    {U'∇', "\\nabla"},
}};

constexpr std::array<Name, 25> kOperators{{
    {U'−', "-"},           {U'×', "\\times"},      {U'∙', "\\cdot"},
    {U'÷', "\\div"},       {U'±', "\\pm"},         {U'→', "\\to"},
    {U'←', "\\leftarrow"}, {U'⇒', "\\Rightarrow"}, {U'≈', "\\approx"},
    {U'≠', "\\neq"},       {U'≤', "\\le"},         {U'≥', "\\ge"},
    {U'∞', "\\infty"},     {U'‖', "\\|"},          {U'√', "\\surd"},
    {U'∑', "\\sum"},       {U'∫', "\\int"},        {U'°', "^{\\circ}"},
    {U'′', "'"},           {U'″', "''"},           {U'▶', "\\blacktriangleright"},
    {U'∝', "\\propto"},    {U'∼', "\\sim"},        {U'⋅', "\\cdot"},
    {U'∈', "\\in"},
}};

const char* find(const auto& table, char32_t cp) {
  for (const Name& n : table)
    if (n.cp == cp) return n.tex;
  return nullptr;
}

// Subscript and superscript digits, signs and the few letters Unicode has.
std::optional<char> subscript(char32_t cp) {
  if (cp >= U'₀' && cp <= U'₉') return static_cast<char>('0' + (cp - U'₀'));
  switch (cp) {
    case U'₊':
      return '+';
    case U'₋':
      return '-';
    case U'ₐ':
      return 'a';
    case U'ₑ':
      return 'e';
    case U'ₒ':
      return 'o';
    case U'ₓ':
      return 'x';
    case U'ₕ':
      return 'h';
    case U'ₖ':
      return 'k';
    case U'ₗ':
      return 'l';
    case U'ₘ':
      return 'm';
    case U'ₙ':
      return 'n';
    case U'ₚ':
      return 'p';
    case U'ₛ':
      return 's';
    case U'ₜ':
      return 't';
    default:
      return std::nullopt;
  }
}

std::optional<char> superscript(char32_t cp) {
  switch (cp) {
    case U'⁰':
      return '0';
    case U'¹':
      return '1';
    case U'²':
      return '2';
    case U'³':
      return '3';
    case U'⁴':
      return '4';
    case U'⁵':
      return '5';
    case U'⁶':
      return '6';
    case U'⁷':
      return '7';
    case U'⁸':
      return '8';
    case U'⁹':
      return '9';
    case U'⁺':
      return '+';
    case U'⁻':
      return '-';
    case U'ⁿ':
      return 'n';
    default:
      return std::nullopt;
  }
}

bool is_mark(char32_t cp) { return cp == 0x0307 || cp == 0x0308 || subscript(cp) || superscript(cp); }

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
    const Decoded d = decode(s, i);
    const char* letter = d.size > 1 ? find(kLetters, d.cp) : nullptr;
    const bool ascii_base = d.size == 1 && ascii_letter(s[i]) && i + 1 < s.size() && is_mark(decode(s, i + 1).cp) &&
                            !latin1_superscript(decode(s, i + 1).cp);
    const bool bare_mark = is_mark(d.cp) && !latin1_superscript(d.cp);  // 10⁻⁹: marks with no letter before
    if (letter == nullptr && !ascii_base && !bare_mark) {
      if (const char* op = d.size > 1 ? find(kOperators, d.cp) : nullptr) {
        out += "$";
        out += op;
        i += d.size;
        close_math(s, i, out);
        continue;
      } else {
        out.append(s.substr(i, d.size));
      }
      i += d.size;
      continue;
    }
    // A symbol: base, dots, subscripts, superscripts.
    std::string base = letter != nullptr ? letter : bare_mark ? "{}" : std::string(1, s[i]);
    if (!bare_mark) i += d.size;
    std::string sub, sup;
    int dots = 0;
    while (i < s.size()) {
      const Decoded m = decode(s, i);
      if (m.cp == 0x0307 || m.cp == 0x0308) {
        dots += m.cp == 0x0307 ? 1 : 2;
      } else if (const auto c = subscript(m.cp)) {
        sub += *c;
      } else if (const auto c2 = superscript(m.cp)) {
        sup += *c2;
      } else {
        break;
      }
      i += m.size;
    }
    if (dots > 0) base = (dots == 1 ? "\\dot{" : "\\ddot{") + base + "}";
    out += "$" + base;
    if (!sub.empty()) out += "_{" + sub + "}";
    if (!sup.empty()) out += "^{" + sup + "}";
    close_math(s, i, out);
  }
}

}  // namespace

std::string_view tex_symbol(char32_t cp) {
  if (const char* letter = find(kLetters, cp)) return letter;
  if (const char* op = find(kOperators, cp)) return op;
  return {};
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

}  // namespace linkage
