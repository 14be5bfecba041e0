#include "report/expression_print.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "core/interrupt.hpp"
#include "report/notation.hpp"

namespace linkage {

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// Binding strength of printed text, for parentheses.
enum class Prec { sum = 1, product = 2, power = 3, atom = 4 };

struct Piece {
  std::string text;
  Prec prec = Prec::atom;
};

// base^exponent; the exponent is a GiNaC numeric except in rare symbolic powers.
struct Factor {
  ex base;
  ex exponent;
};

// coefficient × factors, the unit both products and the terms of sums are handled in.
struct Product {
  numeric coefficient{1};
  std::vector<Factor> factors;
};

// Rank bands beyond sym::role_band's: functions sit between coordinates and
// accelerations, parenthesized sums after them (see the header).
constexpr int kFunctionBand = 7000;
constexpr int kCompoundBand = 7500;

bool is_varying(sym::Role role) {
  return role == sym::Role::time || role == sym::Role::coordinate || role == sym::Role::length ||
         role == sym::Role::rate || role == sym::Role::acceleration || role == sym::Role::force;
}

const std::string& spelling(const sym::SymbolInfo& info, Style style) {
  return style == Style::unicode ? info.unicode : style == Style::ascii ? info.ascii : info.latex;
}

bool is_one(const ex& e) { return is_a<numeric>(e) && ex_to<numeric>(e).is_equal(numeric(1)); }

bool is_bare_sum(const Product& p) {
  return abs(p.coefficient).is_equal(numeric(1)) && p.factors.size() == 1 && is_a<GiNaC::add>(p.factors[0].base) &&
         is_one(p.factors[0].exponent);
}

std::string superscript(long n) {
  static constexpr std::array<std::string_view, 10> kDigits{"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = n < 0 ? "⁻" : "";
  for (char c : std::to_string(n < 0 ? -n : n)) out += kDigits[static_cast<std::size_t>(c - '0')];
  return out;
}

// Functions with a notation here, in the order they sort on the same argument.
constexpr std::array<std::string_view, 5> kFunctions{"sin", "cos", "tan", "exp", "log"};

int function_order(const std::string& name) {
  for (std::size_t i = 0; i < kFunctions.size(); ++i)
    if (kFunctions[i] == name) return static_cast<int>(i);
  throw std::logic_error("expression_print: no notation for the function " + name);
}

class Printer {
 public:
  Printer(const sym::SymbolTable& table, Style style, const ValueText* values)
      : table_(table), style_(style), values_(values) {}

  // The whole expression, sign included; text styles mark every sum operator for wrapping (the outermost first).
  [[nodiscard]] std::string expression(const ex& e, bool top) const {
    check(e);
    return signed_piece(build(e), top).text;
  }

  // coefficient × unknown for equation_sides: whether it is subtracted, and its text.
  [[nodiscard]] std::pair<bool, std::string> term(const ex& coefficient, const std::string& unknown) const {
    check(coefficient);
    Product p = build(coefficient);
    const std::string space = style_ == Style::latex ? " \\, " : " ";
    if (is_bare_sum(p)) {
      // A sum coefficient in parentheses; one of negative terms only keeps its minus outside.
      const ex s = p.coefficient < 0 ? -p.factors[0].base : p.factors[0].base;
      const std::vector<Product> items = sum_items(s);
      const bool negative = std::all_of(items.begin(), items.end(), [](const Product& i) { return i.coefficient < 0; });
      return {negative, paren(sum(negative ? -s : s, false).text) + space + unknown};
    }
    const bool negative = p.coefficient < 0;
    p.coefficient = abs(p.coefficient);
    const Fraction f = fraction(p);
    if (f.numerator.empty() && f.denominator.empty()) return {negative, unknown};
    if (f.numerator.empty()) {  // 1/m: Fx/m
      if (style_ == Style::latex) return {negative, "\\frac{" + unknown + "}{" + join(f.denominator) + "}"};
      const bool single = f.denominator.size() == 1 && f.denominator[0].prec >= Prec::power;
      return {negative, unknown + (single ? "/" + f.denominator[0].text : " / " + paren(join(f.denominator)))};
    }
    if (!f.denominator.empty()) {
      // The unknown joins the numerator: "a sin θ₂ Fx / 2", not "a sin θ₂ / 2 Fx".
      Fraction with_unknown = f;
      with_unknown.numerator.push_back({unknown, Prec::atom});
      with_unknown.symbol_denominator = false;
      return {negative, fraction_text(with_unknown, space)};
    }
    return {negative, magnitude(p, false).text + space + unknown};
  }

 private:
  struct Fraction {
    std::vector<Piece> numerator, denominator;
    bool symbol_denominator = false;  // the denominator is one symbol (for "Fx/m")
  };

  // --- symbols ----------------------------------------------------------------------

  [[nodiscard]] const sym::SymbolInfo& info(const GiNaC::symbol& s) const {
    const sym::SymbolInfo* found = table_.find(s);
    if (found == nullptr)
      throw std::logic_error("expression_print: the symbol " + s.get_name() + " is not in the symbol table");
    return *found;
  }

  // Throws for anything without a notation before any printing starts.
  void check(const ex& e) const {
    for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
      const ex& node = *i;
      if (is_a<GiNaC::symbol>(node)) {
        (void)info(ex_to<GiNaC::symbol>(node));
      } else if (is_a<numeric>(node)) {
        if (!ex_to<numeric>(node).is_real())
          throw std::logic_error("expression_print: no notation for the complex number in " + ginac_text(e));
      } else if (is_a<GiNaC::function>(node)) {
        (void)function_order(ex_to<GiNaC::function>(node).get_name());
        if (node.nops() != 1) throw std::logic_error("expression_print: functions take one argument");
      } else if (is_a<GiNaC::constant>(node)) {
        if (!node.is_equal(GiNaC::Pi)) throw std::logic_error("expression_print: no notation for " + ginac_text(node));
      } else if (!is_a<GiNaC::add>(node) && !is_a<GiNaC::mul>(node) && !is_a<GiNaC::power>(node)) {
        throw std::logic_error("expression_print: no notation for " + ginac_text(node));
      }
    }
  }

  // For error messages only (a programmer reads them).
  static std::string ginac_text(const ex& e) {
    std::ostringstream out;
    out << e;
    return out.str();
  }

  [[nodiscard]] int lowest_rank(const ex& e) const {
    int lowest = 0;
    bool any = false;
    for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i) {
      if (!is_a<GiNaC::symbol>(*i)) continue;
      const int rank = info(ex_to<GiNaC::symbol>(*i)).rank;
      lowest = any ? std::min(lowest, rank) : rank;
      any = true;
    }
    return lowest;
  }

  [[nodiscard]] bool varying(const ex& e) const {
    for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i)
      if (is_a<GiNaC::symbol>(*i) && is_varying(info(ex_to<GiNaC::symbol>(*i)).role)) return true;
    return false;
  }

  // --- products ---------------------------------------------------------------------

  static void multiply(Product& into, const Product& by) {
    into.coefficient *= by.coefficient;
    for (const Factor& f : by.factors) {
      auto same = std::find_if(into.factors.begin(), into.factors.end(),
                               [&](const Factor& g) { return g.base.is_equal(f.base); });
      if (same == into.factors.end()) {
        into.factors.push_back(f);
        continue;
      }
      same->exponent = same->exponent + f.exponent;
      if (same->exponent.is_zero()) into.factors.erase(same);
    }
  }

  static Product raise(Product p, const numeric& n) {
    p.coefficient = p.coefficient.power(n);
    for (Factor& f : p.factors) f.exponent = f.exponent * n;
    return p;
  }

  static ex to_ex(const Product& p) {
    ex out = p.coefficient;
    for (const Factor& f : p.factors) out *= GiNaC::pow(f.base, f.exponent);
    return out;
  }

  // `e` as coefficient × factors, with the common factor of every sum pulled out.
  [[nodiscard]] Product build(const ex& e) const {
    if (is_a<numeric>(e)) return {ex_to<numeric>(e), {}};
    if (is_a<GiNaC::mul>(e)) {
      Product p;
      for (std::size_t i = 0; i < e.nops(); ++i)
        multiply(p, is_a<GiNaC::add>(e.op(i)) ? sum_power(e.op(i), numeric(1)) : build(e.op(i)));
      return p;
    }
    if (is_a<GiNaC::add>(e)) return factored_sum(e);
    if (is_a<GiNaC::power>(e) && is_a<GiNaC::add>(e.op(0)) && is_a<numeric>(e.op(1)) &&
        ex_to<numeric>(e.op(1)).is_integer())
      return sum_power(e.op(0), ex_to<numeric>(e.op(1)));
    if (is_a<GiNaC::power>(e)) return {numeric(1), {{e.op(0), e.op(1)}}};
    return {numeric(1), {{e, numeric(1)}}};
  }

  // sum^n as a factor. GiNaC keeps c (a - b) or -c (b - a) depending on its hash order;
  // the sum is written with fewer negative terms, on a tie with the term that sorts last
  // positive ("m (x₂ - x₁)"), whatever GiNaC kept.
  [[nodiscard]] Product sum_power(const ex& sum, const numeric& n) const {
    const std::vector<Product> terms = terms_of(sum);
    const auto negatives =
        std::count_if(terms.begin(), terms.end(), [](const Product& t) { return t.coefficient < 0; });
    const auto positives = static_cast<std::ptrdiff_t>(terms.size()) - negatives;
    bool flip = negatives > positives;
    if (negatives == positives) {
      std::size_t last = 0;
      for (std::size_t i = 1; i < terms.size(); ++i)
        if (compare_keys(term_key(terms[i]), term_key(terms[last])) > 0) last = i;
      flip = terms[last].coefficient < 0;
    }
    if (!flip) return raise(factored_sum(sum), n);
    Product p = raise(factored_sum(-sum), n);
    if (!n.is_even()) p.coefficient = -p.coefficient;
    return p;
  }

  // The factor every one of `terms` has (with the lowest power), and with it the numeric
  // magnitude they share and the sign if all are negative; nothing numeric on its own.
  static Product common_factor(const std::vector<Product>& terms) {
    Product common;
    for (const Factor& f : terms.front().factors) {
      std::optional<ex> exponent = f.exponent;
      for (std::size_t t = 1; t < terms.size() && exponent; ++t) {
        auto same = std::find_if(terms[t].factors.begin(), terms[t].factors.end(),
                                 [&](const Factor& g) { return g.base.is_equal(f.base); });
        if (same == terms[t].factors.end()) {
          exponent.reset();
        } else if (is_a<numeric>(*exponent) && is_a<numeric>(same->exponent)) {
          const numeric a = ex_to<numeric>(*exponent), b = ex_to<numeric>(same->exponent);
          if (a.csgn() != b.csgn())
            exponent.reset();
          else
            exponent = a.is_positive() ? std::min(a, b) : std::max(a, b);
        } else if (!exponent->is_equal(same->exponent)) {
          exponent.reset();
        }
      }
      if (exponent) common.factors.push_back({f.base, *exponent});
    }
    if (common.factors.empty()) return common;
    const numeric magnitude = abs(terms.front().coefficient);
    const bool shared = std::all_of(terms.begin(), terms.end(),
                                    [&](const Product& t) { return abs(t.coefficient).is_equal(magnitude); });
    const bool negative = std::all_of(terms.begin(), terms.end(), [](const Product& t) { return t.coefficient < 0; });
    common.coefficient = shared ? magnitude : numeric(1);
    if (negative) common.coefficient = -common.coefficient;
    return common;
  }

  // common × (the terms divided by it), the sum itself a factor.
  static Product pull_out(const Product& common, const std::vector<Product>& terms) {
    ex rest = 0;
    for (const Product& t : terms) {
      Product q = t;
      q.coefficient = t.coefficient / common.coefficient;
      multiply(q, raise(Product{numeric(1), common.factors}, numeric(-1)));
      rest += to_ex(q);
    }
    Product out = common;
    if (is_a<GiNaC::add>(rest))
      out.factors.push_back({rest, numeric(1)});
    else
      multiply(out, Product{numeric(1), {{rest, numeric(1)}}});
    return out;
  }

  [[nodiscard]] std::vector<Product> terms_of(const ex& sum) const {
    std::vector<Product> terms;
    for (std::size_t i = 0; i < sum.nops(); ++i) terms.push_back(build(sum.op(i)));
    return terms;
  }

  [[nodiscard]] Product factored_sum(const ex& sum) const {
    const std::vector<Product> terms = terms_of(sum);
    const Product common = common_factor(terms);
    if (common.factors.empty()) return {numeric(1), {{sum, numeric(1)}}};
    return pull_out(common, terms);
  }

  // --- order --------------------------------------------------------------------------

  // Where a factor's base sorts: its rank, then (only on a tie) its ASCII text.
  [[nodiscard]] std::vector<int> base_rank(const ex& base) const {
    if (is_a<GiNaC::symbol>(base)) return {info(ex_to<GiNaC::symbol>(base)).rank};
    if (is_a<numeric>(base) || is_a<GiNaC::constant>(base)) return {0};
    if (is_a<GiNaC::function>(base))
      return {kFunctionBand, lowest_rank(base.op(0)), function_order(ex_to<GiNaC::function>(base).get_name())};
    return {kCompoundBand, lowest_rank(base)};
  }

  [[nodiscard]] std::string canonical(const ex& e) const {
    return Printer(table_, Style::ascii, nullptr).expression(e, false);
  }

  // -1, 0, 1 as a sorts before, with or after b.
  [[nodiscard]] int compare_factors(const Factor& a, const Factor& b) const {
    const std::vector<int> ra = base_rank(a.base), rb = base_rank(b.base);
    if (ra != rb) return ra < rb ? -1 : 1;
    if (!a.base.is_equal(b.base)) {
      const std::string ta = canonical(a.base), tb = canonical(b.base);
      if (ta != tb) return ta < tb ? -1 : 1;
    }
    if (is_a<numeric>(a.exponent) && is_a<numeric>(b.exponent)) {
      const numeric ea = ex_to<numeric>(a.exponent), eb = ex_to<numeric>(b.exponent);
      if (!ea.is_equal(eb)) return ea < eb ? -1 : 1;
      return 0;
    }
    const std::string ta = canonical(a.exponent), tb = canonical(b.exponent);
    return ta == tb ? 0 : ta < tb ? -1 : 1;
  }

  void sort_factors(std::vector<Factor>& factors) const {
    std::stable_sort(factors.begin(), factors.end(),
                     [&](const Factor& a, const Factor& b) { return compare_factors(a, b) < 0; });
  }

  // -1, 0, 1: the factor lists compared factor by factor, a shorter prefix first.
  [[nodiscard]] int compare_lists(const std::vector<Factor>& a, const std::vector<Factor>& b) const {
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
      if (const int c = compare_factors(a[i], b[i]); c != 0) return c;
    return a.size() == b.size() ? 0 : a.size() < b.size() ? -1 : 1;
  }

  // A term's place in a sum (see the header, Sums 3).
  struct TermKey {
    int kind = 0;  // 0 varying, 1 constants only, 2 a number
    std::vector<Factor> varying, constant;
    double degree = 0;
    const Product* term = nullptr;
  };

  [[nodiscard]] TermKey term_key(const Product& t) const {
    TermKey k;
    k.term = &t;
    for (const Factor& f : t.factors) {
      (varying(f.base) ? k.varying : k.constant).push_back(f);
      k.degree += is_a<numeric>(f.exponent) ? std::abs(ex_to<numeric>(f.exponent).to_double()) : 1;
    }
    sort_factors(k.varying);
    sort_factors(k.constant);
    k.kind = !k.varying.empty() ? 0 : !k.constant.empty() ? 1 : 2;
    return k;
  }

  [[nodiscard]] int compare_keys(const TermKey& a, const TermKey& b) const {
    if (a.kind != b.kind) return a.kind < b.kind ? -1 : 1;
    if (const int c = compare_lists(a.varying, b.varying); c != 0) return c;
    if (a.kind == 1 && a.degree != b.degree) return a.degree < b.degree ? -1 : 1;
    if (const int c = compare_lists(a.constant, b.constant); c != 0) return c;
    if (!a.term->coefficient.is_equal(b.term->coefficient)) return a.term->coefficient < b.term->coefficient ? -1 : 1;
    return 0;
  }

  // The sum's items in print order: terms, and groups of terms with the same constant
  // factors as one product (see the header, Sums 2 to 4).
  [[nodiscard]] std::vector<Product> sum_items(const ex& sum) const {
    const std::vector<Product> terms = terms_of(sum);
    std::vector<TermKey> keys;
    keys.reserve(terms.size());
    for (const Product& t : terms) keys.push_back(term_key(t));

    struct Item {
      std::vector<std::size_t> members;
      std::size_t first = 0;  // the member that sorts first
    };
    std::vector<Item> items;
    for (std::size_t i = 0; i < terms.size(); ++i) {
      auto same = std::find_if(items.begin(), items.end(), [&](const Item& item) {
        const TermKey& other = keys[item.members.front()];
        return !keys[i].constant.empty() && compare_lists(keys[i].constant, other.constant) == 0;
      });
      if (same == items.end()) {
        items.push_back({{i}, i});
        continue;
      }
      same->members.push_back(i);
      if (compare_keys(keys[i], keys[same->first]) < 0) same->first = i;
    }
    std::stable_sort(items.begin(), items.end(),
                     [&](const Item& a, const Item& b) { return compare_keys(keys[a.first], keys[b.first]) < 0; });

    std::vector<Product> out;
    for (const Item& item : items) {
      if (item.members.size() == 1) {
        out.push_back(terms[item.first]);
        continue;
      }
      std::vector<Product> group;
      for (std::size_t m : item.members) group.push_back(terms[m]);
      out.push_back(pull_out(common_factor(group), group));
    }
    // No leading minus while a positive item exists: the first positive item moves first.
    auto positive = std::find_if(out.begin(), out.end(), [](const Product& p) { return p.coefficient > 0; });
    if (positive != out.end()) std::rotate(out.begin(), positive, positive + 1);
    return out;
  }

  // --- text ---------------------------------------------------------------------------

  [[nodiscard]] bool substituted() const { return values_ != nullptr; }

  [[nodiscard]] std::string paren(const std::string& inner) const {
    return style_ == Style::latex ? "\\left(" + inner + "\\right)" : "(" + inner + ")";
  }

  [[nodiscard]] std::string times() const {
    if (!substituted()) return " ";
    return style_ == Style::unicode ? " × " : style_ == Style::ascii ? " * " : " \\times ";
  }

  [[nodiscard]] std::string join(const std::vector<Piece>& pieces) const {
    std::string out;
    for (const Piece& p : pieces) {
      if (!out.empty()) out += times();
      out += pieces.size() > 1 && p.prec == Prec::sum ? paren(p.text) : p.text;
    }
    return out;
  }

  // A non-negative number: an integer, or a float in shortest round-trip form.
  // A decimal the mechanism file wrote (0.3 is read exactly as 3/10) prints as one: a
  // fraction whose denominator is a multiple of 5 made of 2s and 5s only. The structural
  // fractions of the derivation (1/2, 1/12, 5/16) stay fractions.
  [[nodiscard]] static bool decimal(const numeric& n) {
    if (!n.is_rational() || n.is_integer()) return false;
    numeric q = n.denom();
    if (!GiNaC::irem(q, numeric(5)).is_zero()) return false;
    while (GiNaC::irem(q, numeric(2)).is_zero()) q = q / 2;
    while (GiNaC::irem(q, numeric(5)).is_zero()) q = q / 5;
    return q.is_equal(numeric(1)) && abs(n.numer()) < numeric(1000000000);
  }

  [[nodiscard]] Piece number(const numeric& n) const {
    if (n.is_integer()) {
      std::ostringstream out;
      out << n;
      return {out.str(), Prec::atom};
    }
    if (decimal(n)) {
      const std::string text = format_number(n.to_double(), style_, 0);
      return {text, text.find(' ') == std::string::npos ? Prec::atom : Prec::product};
    }
    if (n.is_rational()) {
      Piece p = number(n.numer());
      const Piece q = number(n.denom());
      if (style_ == Style::latex) return {"\\frac{" + p.text + "}{" + q.text + "}", Prec::atom};
      return {p.text + "/" + q.text, Prec::product};
    }
    const std::string text = format_number(n.to_double(), style_, 0);
    return {text, text.find(' ') == std::string::npos ? Prec::atom : Prec::product};
  }

  // A symbol's spelling, or its value; `bare` leaves a negative value unparenthesized.
  [[nodiscard]] Piece symbol(const GiNaC::symbol& s, bool bare = false) const {
    const sym::SymbolInfo& i = info(s);
    if (!substituted()) return {spelling(i, style_), Prec::atom};
    const std::string value = (*values_)(i);
    if (value.starts_with('-')) return bare ? Piece{value, Prec::sum} : Piece{paren(value), Prec::atom};
    return {value, value.find(' ') == std::string::npos ? Prec::atom : Prec::product};
  }

  // A function's argument and whether it goes without parentheses ("sin θ₁", "cos 0.1").
  [[nodiscard]] std::pair<std::string, bool> argument(const ex& arg) const {
    if (is_a<GiNaC::symbol>(arg) || is_a<GiNaC::constant>(arg) ||
        (is_a<numeric>(arg) && !ex_to<numeric>(arg).is_negative() &&
         (ex_to<numeric>(arg).is_integer() || !ex_to<numeric>(arg).is_rational()))) {
      const Piece p = is_a<GiNaC::symbol>(arg) ? symbol(ex_to<GiNaC::symbol>(arg), true) : base(arg);
      return {p.text, p.prec == Prec::atom};
    }
    return {expression(arg, false), false};
  }

  // sin θ₁, sin² θ₁ (`power` > 1), sin(θ₁ - θ₂), exp(x), ln x.
  [[nodiscard]] Piece function(const ex& f, long power) const {
    const std::string name = ex_to<GiNaC::function>(f).get_name();
    const auto [arg, simple] = argument(f.op(0));
    if (name == "exp") {
      if (style_ == Style::latex) return {"e^{" + arg + "}", Prec::power};
      return {"exp(" + arg + ")", Prec::atom};
    }
    const std::string shown = name == "log" && style_ != Style::ascii ? "ln" : name;
    if (style_ == Style::ascii) {
      const std::string call = shown + "(" + arg + ")";
      return power == 1 ? Piece{call, Prec::atom} : Piece{call + "^" + std::to_string(power), Prec::power};
    }
    if (style_ == Style::unicode) {
      const std::string head = shown + (power == 1 ? "" : superscript(power));
      return simple ? Piece{head + " " + arg, Prec::product} : Piece{head + "(" + arg + ")", Prec::atom};
    }
    const std::string head = "\\" + shown + (power == 1 ? "" : "^" + latex_exponent(std::to_string(power)));
    if (!simple) return {head + "\\left(" + arg + "\\right)", Prec::atom};
    return {head + (arg.starts_with('\\') ? "" : " ") + arg, Prec::product};
  }

  static std::string latex_exponent(const std::string& e) { return e.size() == 1 ? e : "{" + e + "}"; }

  // A factor's base on its own.
  [[nodiscard]] Piece base(const ex& b) const {
    if (is_a<GiNaC::symbol>(b)) return symbol(ex_to<GiNaC::symbol>(b));
    if (is_a<numeric>(b)) {
      const numeric n = ex_to<numeric>(b);
      const Piece p = number(abs(n));
      return n.is_negative() ? Piece{paren("-" + p.text), Prec::atom} : p;
    }
    if (is_a<GiNaC::constant>(b))
      return {style_ == Style::unicode ? "π" : style_ == Style::ascii ? "pi" : "\\pi", Prec::atom};
    if (is_a<GiNaC::function>(b)) return function(b, 1);
    return signed_piece(build(b), false);
  }

  // base^exponent for a positive exponent (denominators pass theirs negated).
  [[nodiscard]] Piece factor(const ex& b, const ex& exponent) const {
    if (is_one(exponent)) return base(b);
    if (is_a<numeric>(exponent)) {
      const numeric n = ex_to<numeric>(exponent);
      if (n.is_equal(numeric(1, 2))) {
        const Piece p = base(b);
        if (style_ == Style::latex) return {"\\sqrt{" + p.text + "}", Prec::atom};
        if (style_ == Style::ascii) return {"sqrt(" + p.text + ")", Prec::atom};
        return {"√" + (p.prec == Prec::atom ? p.text : paren(p.text)), Prec::atom};
      }
      if (n.is_pos_integer() && is_a<GiNaC::function>(b) && ex_to<GiNaC::function>(b).get_name() != "exp")
        return function(b, n.to_long());
      if (n.is_pos_integer()) {
        const std::string text = raised_base(base(b));
        if (style_ == Style::unicode) return {text + superscript(n.to_long()), Prec::power};
        if (style_ == Style::ascii) return {text + "^" + number(n).text, Prec::power};
        return {text + "^" + latex_exponent(number(n).text), Prec::power};
      }
    }
    const std::string text = raised_base(base(b));
    const Piece e = signed_piece(build(exponent), false);
    if (style_ == Style::latex) return {text + "^{" + e.text + "}", Prec::power};
    return {text + "^" + (e.prec == Prec::atom ? e.text : "(" + e.text + ")"), Prec::power};
  }

  // A base as it goes under an exponent: parenthesized unless atomic; LaTeX braces one
  // that has a superscript of its own ({I_{zz}^{C}}^2).
  [[nodiscard]] std::string raised_base(const Piece& p) const {
    if (p.prec < Prec::atom) return paren(p.text);
    if (style_ == Style::latex && p.text.find('^') != std::string::npos) return "{" + p.text + "}";
    return p.text;
  }

  // The numerator and denominator pieces of a product's magnitude, each in factor order.
  [[nodiscard]] Fraction fraction(Product p) const {
    Fraction f;
    const numeric magnitude = abs(p.coefficient);
    if (magnitude.is_rational() && !decimal(magnitude)) {
      if (!magnitude.numer().is_equal(numeric(1))) f.numerator.push_back(number(magnitude.numer()));
      if (!magnitude.denom().is_equal(numeric(1))) f.denominator.push_back(number(magnitude.denom()));
    } else if (!magnitude.is_equal(numeric(1))) {
      f.numerator.push_back(number(magnitude));
    }
    sort_factors(p.factors);
    std::size_t symbols_below = 0;
    for (const Factor& x : p.factors) {
      if (is_a<numeric>(x.exponent) && ex_to<numeric>(x.exponent).is_negative()) {
        f.denominator.push_back(factor(x.base, -x.exponent));
        if (is_a<GiNaC::symbol>(x.base) && is_one(-x.exponent)) ++symbols_below;
      } else {
        f.numerator.push_back(factor(x.base, x.exponent));
      }
    }
    f.symbol_denominator = f.denominator.size() == 1 && symbols_below == 1;
    return f;
  }

  // numerator / denominator of a coefficient times an unknown (equation_sides).
  [[nodiscard]] std::string fraction_text(const Fraction& f, const std::string& space) const {
    std::string top;
    for (const Piece& piece : f.numerator)
      top += (top.empty() ? "" : space) + (piece.prec == Prec::sum ? paren(piece.text) : piece.text);
    if (style_ == Style::latex) return "\\frac{" + top + "}{" + join(f.denominator) + "}";
    const bool single = f.denominator.size() == 1 && f.denominator[0].prec >= Prec::power;
    return top + " / " + (single ? f.denominator[0].text : paren(join(f.denominator)));
  }

  // The product without its sign.
  [[nodiscard]] Piece magnitude(const Product& p, bool top) const {
    if (is_bare_sum(p)) return sum(p.factors[0].base, top);
    if (p.factors.empty()) return number(abs(p.coefficient));  // 2, 1/12, \frac{1}{12}, 0.5
    const Fraction f = fraction(p);
    if (f.numerator.empty() && f.denominator.empty()) return {"1", Prec::atom};
    if (f.denominator.empty())
      return {join(f.numerator), f.numerator.size() == 1 ? f.numerator[0].prec : Prec::product};
    if (style_ == Style::latex) {
      const std::string top_text = f.numerator.empty()       ? "1"
                                   : f.numerator.size() == 1 ? f.numerator[0].text
                                                             : join(f.numerator);
      return {"\\frac{" + top_text + "}{" + join(f.denominator) + "}", Prec::atom};
    }
    std::string numerator = f.numerator.empty() ? "1" : join(f.numerator);
    if (f.numerator.size() == 1 && f.numerator[0].prec == Prec::sum) numerator = paren(numerator);
    const bool compact = !substituted() && f.symbol_denominator &&
                         (f.numerator.empty() || (f.numerator.size() == 1 && f.numerator[0].prec == Prec::atom));
    if (compact) return {numerator + "/" + f.denominator[0].text, Prec::product};
    const bool single = f.denominator.size() == 1 && f.denominator[0].prec >= Prec::power;
    return {numerator + " / " + (single ? f.denominator[0].text : paren(join(f.denominator))), Prec::product};
  }

  [[nodiscard]] Piece signed_piece(const Product& p, bool top) const {
    const Piece m = magnitude(p, top);
    if (!(p.coefficient < 0)) return m;
    return {"-" + (m.prec == Prec::sum ? paren(m.text) : m.text), Prec::sum};
  }

  [[nodiscard]] Piece sum(const ex& s, bool /*top*/) const {
    const std::string mark = style_ != Style::latex ? std::string(1, kBreakMark) : "";
    std::string out;
    for (const Product& item : sum_items(s)) {
      throw_if_interrupted();  // a long chain's entries are sums of thousands of terms
      const Piece m = magnitude(item, false);
      const std::string text = m.prec == Prec::sum ? paren(m.text) : m.text;
      const bool negative = item.coefficient < 0;
      if (out.empty())
        out = (negative ? "-" : "") + text;
      else
        out += mark + (negative ? " - " : " + ") + text;
    }
    return {out, Prec::sum};
  }

  const sym::SymbolTable& table_;
  Style style_;
  const ValueText* values_;  // nullptr: symbols print as their spelling
};

}  // namespace

std::string print(const GiNaC::ex& e, const sym::SymbolTable& table, Style style) {
  return Printer(table, style, nullptr).expression(e, true);
}

std::string print_substituted(const GiNaC::ex& e, const sym::SymbolTable& table, Style style,
                              const ValueText& value_text) {
  return Printer(table, style, &value_text).expression(e, true);
}

EquationSides equation_sides(const std::vector<GiNaC::ex>& A_row, const GiNaC::ex& B,
                             const std::vector<const sym::SymbolInfo*>& unknowns, const sym::SymbolTable& table,
                             Style style) {
  if (A_row.size() != unknowns.size())
    throw std::logic_error("equation_sides: " + std::to_string(A_row.size()) + " coefficients for " +
                           std::to_string(unknowns.size()) + " unknowns");
  const Printer printer(table, style, nullptr);
  const std::string mark = style == Style::latex ? "" : std::string(1, kBreakMark);
  std::string lhs;
  for (std::size_t c = 0; c < A_row.size(); ++c) {
    throw_if_interrupted();
    if (A_row[c].is_zero()) continue;
    const auto [negative, body] = printer.term(A_row[c], spelling(*unknowns[c], style));
    if (lhs.empty())
      lhs = (negative ? "-" : "") + body;
    else
      lhs += mark + (negative ? " - " : " + ") + body;
  }
  return {lhs.empty() ? "0" : lhs, printer.expression(B, true)};
}

}  // namespace linkage
