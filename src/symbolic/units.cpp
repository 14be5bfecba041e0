#include "symbolic/units.hpp"

#include <array>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace linkage::sym {
namespace {

using GiNaC::ex;

struct Base {
  GiNaC::symbol kg{"kg"}, m{"m"}, s{"s"};
};
const Base& base() {
  static const Base b;
  return b;
}

std::optional<ex> named_unit(const std::string& name) {
  const Base& u = base();
  if (name == "kg") return ex(u.kg);
  if (name == "m") return ex(u.m);
  if (name == "s") return ex(u.s);
  if (name == "rad" || name == "1") return ex(1);
  if (name == "N") return u.kg * u.m / GiNaC::pow(u.s, 2);
  if (name == "J") return u.kg * GiNaC::pow(u.m, 2) / GiNaC::pow(u.s, 2);
  if (name == "W") return u.kg * GiNaC::pow(u.m, 2) / GiNaC::pow(u.s, 3);
  if (name == "Hz") return 1 / ex(u.s);
  return std::nullopt;
}

// "kg m^2" or "N s": factors separated by spaces or '*', each NAME or NAME^INTEGER.
std::optional<ex> product_of(const std::string& text) {
  std::string spaced = text;
  for (char& c : spaced)
    if (c == '*') c = ' ';
  std::istringstream in(spaced);
  ex out = 1;
  for (std::string factor; in >> factor;) {
    const auto caret = factor.find('^');
    const auto unit = named_unit(factor.substr(0, caret));
    if (!unit) return std::nullopt;
    int power = 1;
    if (caret != std::string::npos) {
      try {
        std::size_t used = 0;
        power = std::stoi(factor.substr(caret + 1), &used);
        if (used != factor.size() - caret - 1) return std::nullopt;
      } catch (const std::exception&) {
        return std::nullopt;
      }
    }
    out *= GiNaC::pow(*unit, power);
  }
  return out;
}

}  // namespace

std::optional<ex> parse_unit(const std::string& unit) {
  const auto slash = unit.find('/');
  const auto numerator = product_of(unit.substr(0, slash));
  if (!numerator) return std::nullopt;
  if (slash == std::string::npos) return numerator;
  std::string rest = unit.substr(slash + 1);
  if (rest.size() >= 2 && rest.front() == '(' && rest.back() == ')') rest = rest.substr(1, rest.size() - 2);
  if (rest.find('/') != std::string::npos) return std::nullopt;
  const auto denominator = product_of(rest);
  if (!denominator) return std::nullopt;
  return *numerator / *denominator;
}

std::optional<std::string> unit_of(const ex& e, const SymbolTable& table) {
  if (e.is_zero()) return std::nullopt;
  GiNaC::exmap with_units;
  for (const SymbolInfo& info : table.all()) {
    if (info.role != Role::parameter || !e.has(info.symbol)) continue;
    const auto unit = parse_unit(info.unit);
    if (!unit) return std::nullopt;
    with_units[info.symbol] = info.symbol * *unit;
  }
  const ex ratio = GiNaC::normal(e.subs(with_units) / e);
  for (const auto& [symbol, scaled] : with_units)
    if (ratio.has(symbol)) return std::nullopt;  // the terms have different units
  const Base& u = base();
  const std::array<std::pair<const GiNaC::symbol*, const char*>, 3> order{{{&u.kg, "kg"}, {&u.m, "m"}, {&u.s, "s"}}};
  std::string up, down;
  int down_count = 0;
  for (const auto& [symbol, name] : order) {
    int p = 0;
    try {
      p = ratio.degree(*symbol);  // a monomial: its exponent, negative in the denominator
    } catch (const std::runtime_error&) {
      return std::nullopt;  // a fractional power, such as the square root of a length
    }
    if (p == 0) continue;
    std::string& side = p > 0 ? up : down;
    if (p < 0) ++down_count;
    if (!side.empty()) side += ' ';
    side += name;
    if (std::abs(p) != 1) {
      side += '^';
      side += std::to_string(std::abs(p));
    }
  }
  if (!GiNaC::is_a<GiNaC::numeric>(ratio.subs(GiNaC::lst{u.kg == 1, u.m == 1, u.s == 1}))) return std::nullopt;
  if (down.empty()) return up;
  std::string out = up.empty() ? std::string("1") : up;
  out += '/';
  if (down_count > 1) {
    out += '(';
    out += down;
    out += ')';
  } else {
    out += down;
  }
  return out;
}

}  // namespace linkage::sym
