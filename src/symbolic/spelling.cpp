#include "symbolic/spelling.hpp"

#include <array>
#include <cctype>
#include <string_view>
#include <utility>

namespace linkage::sym {
namespace {

struct Greek {
  std::string_view name, unicode;
};
constexpr std::array<Greek, 35> kGreek{{
    {"alpha", "α"}, {"beta", "β"},   {"gamma", "γ"}, {"delta", "δ"},  {"epsilon", "ε"},  {"zeta", "ζ"},
    {"eta", "η"},   {"theta", "θ"},  {"iota", "ι"},  {"kappa", "κ"},  {"lambda", "λ"},   {"mu", "μ"},
    {"nu", "ν"},    {"xi", "ξ"},     {"rho", "ρ"},   {"sigma", "σ"},  {"tau", "τ"},      {"upsilon", "υ"},
    {"phi", "φ"},   {"chi", "χ"},    {"psi", "ψ"},   {"omega", "ω"},  {"Gamma", "Γ"},    {"Delta", "Δ"},
    {"Theta", "Θ"}, {"Lambda", "Λ"}, {"Xi", "Ξ"},    {"Pi", "Π"},     {"Sigma", "Σ"},    {"Upsilon", "Υ"},
    {"Phi", "Φ"},   {"Psi", "Ψ"},    {"Omega", "Ω"}, {"varphi", "φ"}, {"vartheta", "ϑ"},
}};

const Greek* greek(std::string_view name) {
  for (const Greek& g : kGreek)
    if (g.name == name) return &g;
  return nullptr;
}

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (std::isdigit(static_cast<unsigned char>(c)) == 0) return false;
  return true;
}

std::string subscript_digits(std::string_view digits) {
  static constexpr std::array<std::string_view, 10> kSub{"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
  std::string out;
  for (char c : digits) out += kSub[static_cast<std::size_t>(c - '0')];
  return out;
}

// LaTeX of a subscript: digits as they are, a word upright.
std::string latex_index(std::string_view index) {
  if (all_digits(index) || index.size() == 1) return std::string(index);
  std::string out = "\\mathrm{";
  for (char c : index) {
    if (c == '_')
      out += "\\_";
    else
      out += c;
  }
  return out + "}";
}

// Splits "tau0" into ("tau", "0") and "F_max" into ("F", "max").
std::pair<std::string, std::string> split_index(const std::string& name) {
  if (const auto underscore = name.find('_'); underscore != std::string::npos && underscore > 0)
    return {name.substr(0, underscore), name.substr(underscore + 1)};
  std::size_t end = name.size();
  while (end > 1 && std::isdigit(static_cast<unsigned char>(name[end - 1])) != 0) --end;
  return {name.substr(0, end), name.substr(end)};
}

Spelling with_index(Spelling base, const std::string& index) {
  if (index.empty()) return base;
  base.unicode += all_digits(index) ? subscript_digits(index) : "_" + index;
  base.ascii += all_digits(index) ? index : "_" + index;
  // One character bare, as the homework writes \theta_1; longer ones braced.
  const std::string latex = latex_index(index);
  base.latex += latex.size() == 1 ? "_" + latex : "_{" + latex + "}";
  return base;
}

}  // namespace

Spelling spell_name(const std::string& name) {
  const auto [base, index] = split_index(name);
  Spelling s;
  if (const Greek* g = greek(base)) {
    s = {std::string(g->unicode), base, "\\" + base};
  } else {
    s = {base, base, base.size() == 1 ? base : "\\mathrm{" + base + "}"};
  }
  return with_index(s, index);
}

Spelling spell_indexed(const std::string& base, int dots, const std::string& index) {
  // Unicode: precomposed dotted x and y where they exist, combining dots otherwise.
  Spelling s;
  const bool theta = base == "theta", tau = base == "tau";  // the Greek bases in use
  const std::string letter = theta ? "θ" : tau ? "τ" : base;
  if (dots == 0) {
    s.unicode = letter;
  } else if (base == "x") {
    s.unicode = dots == 1 ? "ẋ" : "ẍ";
  } else if (base == "y") {
    s.unicode = dots == 1 ? "ẏ" : "ÿ";
  } else {
    s.unicode = letter + (dots == 1 ? "\u0307" : "\u0308");
  }
  const std::string ascii_base = theta ? "th" : base;
  const std::string latex_letter = theta ? "\\theta" : tau ? "\\tau" : base;
  s.latex = dots == 0 ? latex_letter : (dots == 1 ? "\\dot{" : "\\ddot{") + latex_letter + "}";
  Spelling out = with_index(s, index);
  // ASCII puts the primes after the index: th1'', x_crank'.
  out.ascii =
      ascii_base + (all_digits(index) ? index : "_" + index) + std::string(static_cast<std::size_t>(dots), '\'');
  return out;
}

}  // namespace linkage::sym
