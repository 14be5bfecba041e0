#include "report/code_printer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "core/interrupt.hpp"
#include "core/number_format.hpp"

namespace linkage {

namespace {

constexpr int kSum = 1, kProduct = 2, kPower = 3, kAtom = 4;

// A product's factors print after its number, in this order: constants, then the symbol
// table's bands (parameters ... rates), functions of the coordinates, sums, the rest.
constexpr int kConstantRank = 500, kFunctionRank = 7000, kSumRank = 7500, kOtherRank = 9500;

std::string integer_text(const GiNaC::numeric& n) {
  std::ostringstream out;
  out << n;
  return out.str();
}

bool is_integer(const GiNaC::ex& e) {
  return GiNaC::is_exactly_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_integer();
}

bool is_negative_rational(const GiNaC::ex& e) {
  return GiNaC::is_exactly_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_rational() &&
         GiNaC::ex_to<GiNaC::numeric>(e).is_negative();
}

// A decimal of the mechanism file (read exactly: 0.3 is 3/10) prints as that decimal: a
// fraction whose denominator is a multiple of 5 made of 2s and 5s only, as the worked
// solution prints it. The derivation's own fractions (1/2, 1/12) stay fractions. Either
// way the value is the double nearest the fraction.
bool file_decimal(const GiNaC::numeric& n) {
  if (!n.is_rational() || n.is_integer() || !GiNaC::irem(n.denom(), 5).is_zero()) return false;
  GiNaC::numeric rest = n.denom();
  while (GiNaC::irem(rest, 2).is_zero()) rest = rest / 2;
  while (GiNaC::irem(rest, 5).is_zero()) rest = rest / 5;
  return rest.is_equal(1) && GiNaC::abs(n.numer()) < GiNaC::numeric(1000000000);
}

struct Ranked {
  int rank;
  std::string text;
  bool operator<(const Ranked& other) const { return std::tie(rank, text) < std::tie(other.rank, other.text); }
};

}  // namespace

CodePrinter::CodePrinter(CodeLanguage language, const sym::SymbolTable& table,
                         std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> names)
    : language_(language), table_(table), names_(std::move(names)) {}

std::string CodePrinter::operator()(const GiNaC::ex& e) const { return print(e).text; }

std::string CodePrinter::wrapped(const GiNaC::ex& e, int level) const {
  const Text t = print(e);
  return t.level < level ? "(" + t.text + ")" : t.text;
}

CodePrinter::Text CodePrinter::print(const GiNaC::ex& e) const {
  if (GiNaC::is_exactly_a<GiNaC::numeric>(e)) return print_number(GiNaC::ex_to<GiNaC::numeric>(e));
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const auto it = names_.find(e);
    if (it == names_.end()) {
      std::ostringstream name;
      name << e;
      throw std::logic_error("code export: no identifier for the symbol " + name.str());
    }
    return {it->second, kAtom};
  }
  if (GiNaC::is_exactly_a<GiNaC::constant>(e)) {
    if (e.is_equal(GiNaC::Pi)) return {language_ == CodeLanguage::python ? "np.pi" : "pi", kAtom};
    throw std::logic_error("code export: a constant other than pi");
  }
  if (GiNaC::is_exactly_a<GiNaC::add>(e)) return print_sum(e);
  if (GiNaC::is_exactly_a<GiNaC::mul>(e)) {
    GiNaC::numeric coefficient = 1;
    GiNaC::exvector factors;
    for (const GiNaC::ex& op : e) {
      if (GiNaC::is_exactly_a<GiNaC::numeric>(op))
        coefficient *= GiNaC::ex_to<GiNaC::numeric>(op);
      else
        factors.push_back(op);
    }
    return signed_product(coefficient, factors);
  }
  if (GiNaC::is_exactly_a<GiNaC::power>(e)) {
    // A negative power is a denominator: 1/x^2, 1/sqrt(x); a sum's power may change sign.
    if (is_negative_rational(e.op(1)) || (GiNaC::is_exactly_a<GiNaC::add>(e.op(0)) && is_integer(e.op(1))))
      return signed_product(1, {e});
    return print_power(e.op(0), e.op(1));
  }
  if (GiNaC::is_a<GiNaC::function>(e)) return print_function(e);
  throw std::logic_error(std::string("code export: cannot print a GiNaC ") +
                         GiNaC::ex_to<GiNaC::basic>(e).class_name());
}

CodePrinter::Text CodePrinter::print_number(const GiNaC::numeric& n) const {
  if (!n.is_real()) throw std::logic_error("code export: a complex number in an expression");
  const bool negative = n.is_negative();
  const GiNaC::numeric magnitude = GiNaC::abs(n);
  std::string text;
  int level = kAtom;
  if (magnitude.is_integer()) {
    text = integer_text(magnitude);
  } else if (file_decimal(magnitude)) {
    text = format_roundtrip(magnitude.to_double());
  } else if (magnitude.is_rational()) {
    text = integer_text(magnitude.numer()) + "/" + integer_text(magnitude.denom());
    level = kProduct;
  } else {
    const double value = magnitude.to_double();
    if (!std::isfinite(value)) throw std::logic_error("code export: a number that is not finite");
    text = format_roundtrip(value);
  }
  if (negative) return {"-" + text, kProduct};
  return {text, level};
}

CodePrinter::Text CodePrinter::print_sum(const GiNaC::ex& e, std::size_t* negatives) const {
  std::vector<std::pair<std::string, bool>> terms;  // |term| and whether it is subtracted
  for (const GiNaC::ex& term : e) {
    throw_if_interrupted();  // a long chain's entries are sums of thousands of terms
    if (GiNaC::is_exactly_a<GiNaC::numeric>(term)) {
      const auto& n = GiNaC::ex_to<GiNaC::numeric>(term);
      terms.emplace_back(print_number(GiNaC::abs(n)).text, n.is_negative());
    } else if (GiNaC::is_exactly_a<GiNaC::mul>(term)) {
      GiNaC::numeric coefficient = 1;
      GiNaC::exvector factors;
      for (const GiNaC::ex& op : term) {
        if (GiNaC::is_exactly_a<GiNaC::numeric>(op))
          coefficient *= GiNaC::ex_to<GiNaC::numeric>(op);
        else
          factors.push_back(op);
      }
      bool negative = false;
      terms.emplace_back(print_product(coefficient, factors, negative).text, negative);
    } else {
      terms.emplace_back(print(term).text, false);
    }
  }
  // Added terms first: a sum reads "a*b - c" rather than "-c + a*b".
  std::sort(terms.begin(), terms.end(),
            [](const auto& a, const auto& b) { return std::tie(a.second, a.first) < std::tie(b.second, b.first); });
  if (negatives != nullptr)
    *negatives = static_cast<std::size_t>(
        std::count_if(terms.begin(), terms.end(), [](const auto& term) { return term.second; }));
  std::string out;
  for (const auto& [text, negative] : terms) {
    if (out.empty())
      out = negative ? "-" + text : text;
    else
      out += (negative ? " - " : " + ") + text;
  }
  return {out, kSum};
}

CodePrinter::Text CodePrinter::signed_product(const GiNaC::numeric& coefficient, const GiNaC::exvector& factors) const {
  bool negative = false;
  const Text magnitude = print_product(coefficient, factors, negative);
  return negative ? Text{"-" + magnitude.text, kProduct} : magnitude;
}

CodePrinter::Text CodePrinter::print_product(const GiNaC::numeric& coefficient, const GiNaC::exvector& factors,
                                             bool& negative) const {
  if (!coefficient.is_real()) throw std::logic_error("code export: a complex number in an expression");
  std::vector<Ranked> numerator, denominator;
  bool flip = false;
  for (const GiNaC::ex& f : factors) {
    bool flipped = false;
    if (GiNaC::is_exactly_a<GiNaC::power>(f) && is_negative_rational(f.op(1))) {
      const GiNaC::ex positive = GiNaC::pow(f.op(0), -f.op(1));
      denominator.push_back({rank(f), factor_text(positive, flipped)});
    } else {
      numerator.push_back({rank(f), factor_text(f, flipped)});
    }
    flip = flip != flipped;
  }
  std::sort(numerator.begin(), numerator.end());
  std::sort(denominator.begin(), denominator.end());

  negative = coefficient.is_negative() != flip;
  const GiNaC::numeric magnitude = GiNaC::abs(coefficient);
  std::vector<std::string> top, bottom;
  if (magnitude.is_rational() && !file_decimal(magnitude)) {
    if (magnitude.numer() != 1) top.push_back(integer_text(magnitude.numer()));
    if (magnitude.denom() != 1) bottom.push_back(integer_text(magnitude.denom()));
  } else {
    top.push_back(print_number(magnitude).text);
  }
  for (const Ranked& r : numerator) top.push_back(r.text);
  for (const Ranked& r : denominator) bottom.push_back(r.text);
  // One factor alone keeps its own precedence: x^2 is a power, not a product.
  if (top.size() == 1 && bottom.empty() && factors.size() == 1) {
    const GiNaC::ex& f = factors[0];
    if (GiNaC::is_exactly_a<GiNaC::power>(f) && GiNaC::is_exactly_a<GiNaC::add>(f.op(0))) return {top[0], kPower};
    return print(f);
  }

  auto join = [](const std::vector<std::string>& parts) {
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : "*") + p;
    return out;
  };
  std::string out = top.empty() ? "1" : join(top);
  if (bottom.size() == 1)
    out += "/" + bottom[0];
  else if (bottom.size() > 1)
    out += "/(" + join(bottom) + ")";
  return {out, kProduct};
}

std::string CodePrinter::factor_text(const GiNaC::ex& factor, bool& flipped) const {
  flipped = false;
  const bool sum = GiNaC::is_exactly_a<GiNaC::add>(factor);
  const bool sum_power = GiNaC::is_exactly_a<GiNaC::power>(factor) && GiNaC::is_exactly_a<GiNaC::add>(factor.op(0)) &&
                         is_integer(factor.op(1));
  if (!sum && !sum_power) return wrapped(factor, kPower);
  // GiNaC gives a sum factor (a - b)^n the sign of its first term in its internal order,
  // which follows symbol creation: choose between the sum and its negation by their text.
  const GiNaC::ex terms = sum ? factor : factor.op(0);
  const GiNaC::numeric n = sum ? GiNaC::numeric(1) : GiNaC::ex_to<GiNaC::numeric>(factor.op(1));
  GiNaC::ex negated = 0;
  for (const GiNaC::ex& term : terms) negated += -term;
  std::size_t plain_negatives = 0, other_negatives = 0;
  const std::string plain = print_sum(terms, &plain_negatives).text;
  const std::string other = print_sum(negated, &other_negatives).text;
  const bool use_other = std::tie(other_negatives, other) < std::tie(plain_negatives, plain);
  flipped = use_other && n.is_odd();
  const std::string op = language_ == CodeLanguage::python ? "**" : ".^";
  return "(" + (use_other ? other : plain) + ")" + (sum ? "" : op + integer_text(n));
}

CodePrinter::Text CodePrinter::print_power(const GiNaC::ex& base, const GiNaC::ex& exponent) const {
  const std::string op = language_ == CodeLanguage::python ? "**" : ".^";
  if (exponent.is_equal(GiNaC::numeric(1, 2)))
    return {(language_ == CodeLanguage::python ? "np.sqrt(" : "sqrt(") + print(base).text + ")", kAtom};
  if (GiNaC::is_exactly_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_nonneg_integer())
    return {wrapped(base, kAtom) + op + print(exponent).text, kPower};
  return {wrapped(base, kAtom) + op + "(" + print(exponent).text + ")", kPower};
}

CodePrinter::Text CodePrinter::print_function(const GiNaC::ex& e) const {
  static constexpr std::array<const char*, 6> kKnown{"sin", "cos", "tan", "exp", "log", "abs"};
  const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
  if (std::find(kKnown.begin(), kKnown.end(), name) == kKnown.end())
    throw std::logic_error("code export: no spelling for the function " + name);
  std::string args;
  for (const GiNaC::ex& arg : e) args += (args.empty() ? "" : ", ") + print(arg).text;
  return {(language_ == CodeLanguage::python ? "np." : "") + name + "(" + args + ")", kAtom};
}

int CodePrinter::rank(const GiNaC::ex& factor) const {
  if (GiNaC::is_a<GiNaC::symbol>(factor)) {
    const sym::SymbolInfo* info = table_.find(GiNaC::ex_to<GiNaC::symbol>(factor));
    return info != nullptr ? info->rank : sym::role_band(sym::Role::time);
  }
  if (GiNaC::is_exactly_a<GiNaC::power>(factor)) return rank(factor.op(0));
  if (GiNaC::is_exactly_a<GiNaC::constant>(factor)) return kConstantRank;
  if (GiNaC::is_a<GiNaC::function>(factor)) return kFunctionRank;
  if (GiNaC::is_exactly_a<GiNaC::add>(factor)) return kSumRank;
  return kOtherRank;
}

}  // namespace linkage
