#include "columns/expression_column.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "symbolic/expression_reader.hpp"
#include "symbolic/units.hpp"

namespace linkage {

namespace {

bool column_name(std::string_view name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front())) != 0) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; });
}

std::string trimmed(std::string_view text) {
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!text.empty() && space(text.front())) text.remove_prefix(1);
  while (!text.empty() && space(text.back())) text.remove_suffix(1);
  return std::string(text);
}

/// A dimension as powers of kg, m and s (rad counts as 1); nullopt: unknown or inconsistent.
using Dimension = std::array<GiNaC::numeric, 3>;

std::optional<Dimension> dimension_of_unit(const std::string& unit) {
  const auto parsed = sym::parse_unit(unit);
  if (!parsed) return std::nullopt;
  static const GiNaC::symbol kg = GiNaC::ex_to<GiNaC::symbol>(*sym::parse_unit("kg"));
  static const GiNaC::symbol m = GiNaC::ex_to<GiNaC::symbol>(*sym::parse_unit("m"));
  static const GiNaC::symbol s = GiNaC::ex_to<GiNaC::symbol>(*sym::parse_unit("s"));
  return Dimension{parsed->degree(kg), parsed->degree(m), parsed->degree(s)};
}

/// Dimensional analysis over the expression's tree: a sum's terms must agree, a function's
/// argument must be a pure number (atan2's two and abs's one: any, alike).
class Dimensions {
 public:
  explicit Dimensions(std::map<GiNaC::ex, Dimension, GiNaC::ex_is_less> known) : known_(std::move(known)) {}

  std::optional<Dimension> of(const GiNaC::ex& e) const {
    if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return Dimension{};
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      const auto it = known_.find(e);
      return it == known_.end() ? std::nullopt : std::optional<Dimension>(it->second);
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
      std::optional<Dimension> first;
      for (std::size_t k = 0; k < e.nops(); ++k) {
        const auto d = of(e.op(k));
        if (!d || (first && *first != *d)) return std::nullopt;
        first = d;
      }
      return first;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      Dimension product{};
      for (std::size_t k = 0; k < e.nops(); ++k) {
        const auto d = of(e.op(k));
        if (!d) return std::nullopt;
        for (std::size_t i = 0; i < 3; ++i) product[i] += (*d)[i];
      }
      return product;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
      const auto base = of(e.op(0));
      if (!base || !GiNaC::is_a<GiNaC::numeric>(e.op(1))) return std::nullopt;
      Dimension power{};
      for (std::size_t i = 0; i < 3; ++i) power[i] = (*base)[i] * GiNaC::ex_to<GiNaC::numeric>(e.op(1));
      return power;
    }
    if (GiNaC::is_a<GiNaC::function>(e)) {
      const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
      std::optional<Dimension> first;
      for (std::size_t k = 0; k < e.nops(); ++k) {
        const auto d = of(e.op(k));
        if (!d || (first && *first != *d)) return std::nullopt;
        first = d;
      }
      if (name == "abs") return first;
      if (!first || (name != "atan2" && *first != Dimension{})) return std::nullopt;
      return Dimension{};
    }
    return std::nullopt;
  }

 private:
  std::map<GiNaC::ex, Dimension, GiNaC::ex_is_less> known_;
};

/// "kg m^2/s^3" from powers, in units.cpp's spelling; N and W by name; "" for a pure number.
std::string unit_text(const Dimension& d) {
  static const char* const names[] = {"kg", "m", "s"};
  std::string up, down;
  int down_count = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (d[i].is_zero()) continue;
    if (!d[i].is_integer()) return "";
    const int p = d[i].to_int();
    std::string& side = p > 0 ? up : down;
    down_count += p < 0 ? 1 : 0;
    if (!side.empty()) side.push_back(' ');
    side.append(names[i]);
    if (std::abs(p) != 1) side.append("^").append(std::to_string(std::abs(p)));
  }
  std::ostringstream text;  // a stream: g++ 12 warns falsely on short string assignments here
  text << (up.empty() && !down.empty() ? "1" : up);
  if (!down.empty()) text << '/' << (down_count > 1 ? "(" : "") << down << (down_count > 1 ? ")" : "");
  const std::string out = text.str();
  if (out == "kg m/s^2") return "N";
  if (out == "kg m^2/s^3") return "W";
  return out;
}

/// An angle: a sum of angle columns and inverse trigonometric functions, each times a pure
/// number, and pure numbers (pi/2 - gamma): printed in rad, so --angles deg converts it.
bool is_angle(const GiNaC::ex& expanded, const std::vector<std::pair<GiNaC::symbol, MechanismColumn>>& inputs) {
  const auto pure = [](const GiNaC::ex& x) {
    return GiNaC::is_a<GiNaC::numeric>(x) || GiNaC::is_a<GiNaC::constant>(x);
  };
  const auto angle = [&](const GiNaC::ex& x) {
    for (const auto& [symbol, column] : inputs)
      if (x.is_equal(symbol)) return column.unit == "rad";
    if (!GiNaC::is_a<GiNaC::function>(x)) return false;
    const std::string name = GiNaC::ex_to<GiNaC::function>(x).get_name();
    return name == "asin" || name == "acos" || name == "atan" || name == "atan2";
  };
  bool any = false;
  const auto term_ok = [&](const GiNaC::ex& term) {
    if (pure(term)) return true;
    if (angle(term)) return any = true;
    if (!GiNaC::is_a<GiNaC::mul>(term)) return false;
    int angles = 0;
    for (std::size_t k = 0; k < term.nops(); ++k) {
      if (angle(term.op(k)))
        ++angles;
      else if (!pure(term.op(k)))
        return false;
    }
    any = any || angles == 1;
    return angles <= 1;  // pi/2 is a pure number too
  };
  if (!GiNaC::is_a<GiNaC::add>(expanded)) return term_ok(expanded) && any;
  for (std::size_t k = 0; k < expanded.nops(); ++k)
    if (!term_ok(expanded.op(k))) return false;
  return any;
}

/// The unit of an angle (is_angle), of a sum of columns in one unit times pure numbers,
/// else by dimensional analysis ("" when unknown).
std::string unit_of(const ColumnExpression& e, const sym::System* system) {
  const GiNaC::ex expanded = GiNaC::expand(e.value);
  if (is_angle(expanded, e.inputs)) return "rad";
  std::optional<std::string> shared;
  bool linear = !e.inputs.empty();
  GiNaC::exmap zero;
  for (const auto& [symbol, column] : e.inputs) {
    // is_polynomial first: degree() throws on sqrt(x).
    linear = linear && (!shared || *shared == column.unit) && expanded.is_polynomial(symbol) &&
             expanded.degree(symbol) == 1 && GiNaC::is_a<GiNaC::numeric>(expanded.coeff(symbol, 1));
    shared = column.unit;
    zero[symbol] = 0;
  }
  if (linear && expanded.subs(zero).is_zero()) return *shared;
  std::map<GiNaC::ex, Dimension, GiNaC::ex_is_less> known;
  for (const auto& [symbol, column] : e.inputs)
    if (const auto d = dimension_of_unit(column.unit)) known[symbol] = *d;
  if (system != nullptr)
    for (const sym::SymbolInfo& info : system->table().all())
      if (info.role == sym::Role::parameter)
        if (const auto d = dimension_of_unit(info.unit)) known[info.symbol] = *d;
  const auto d = Dimensions(std::move(known)).of(e.value);
  return d ? unit_text(*d) : "";
}

}  // namespace

bool defines_column(std::string_view spec) { return spec.find('=') != std::string_view::npos; }

MechanismColumn expression_column(const std::vector<MechanismColumn>& available, const sym::System* system,
                                  const std::string& spec, const std::string& origin) {
  const std::size_t equals = spec.find('=');
  const std::string name = trimmed(std::string_view(spec).substr(0, equals));
  const std::string text = trimmed(std::string_view(spec).substr(equals + 1));
  if (!column_name(name))
    throw Error::input(origin + ": '" + name + "' in '" + spec +
                       "' is not a name for a column; valid: letters, digits and _, not starting with a digit "
                       "(e.g. gamma=4.theta-3.theta)");
  for (const MechanismColumn& c : available)
    if (c.name == name)
      throw Error::input(origin + ": '" + name + "' in '" + spec +
                         "' is already a column of this mechanism; valid: a new name (e.g. " + name + "_2)");
  if (name == "default" || name == "all")
    throw Error::input(origin + ": '" + name + "' in '" + spec + "' names a group of columns; valid: another name");

  auto e = std::make_shared<ColumnExpression>();
  e->name = name;
  e->text = text;
  e->origin = origin;
  GiNaC::symtab names;
  if (system != nullptr) {
    for (const auto& [n, symbol] : system->names()) names[n] = symbol;
    for (const auto& [symbol, value] : system->parameter_values()) e->fixed[symbol] = value;
    for (const auto& [symbol, expression] : system->constants()) e->fixed[symbol] = expression;
  }
  std::map<std::string, std::size_t> column_of;  // a name -> its index in `available`
  for (std::size_t i = 0; i < available.size(); ++i) {
    column_of[available[i].name] = i;
    if (system != nullptr) column_of.emplace(system->mechanism().unaliased(available[i].name), i);
  }
  std::vector<GiNaC::symbol> symbols(available.size());
  for (const auto& [n, i] : column_of) {
    symbols[i] = GiNaC::symbol(available[i].name);
    names[n] = symbols[i];  // a column's name wins over a parameter's
  }
  const std::string where = origin + ": column '" + name + "'";
  constexpr std::size_t kLongestValidList = 400;  // as an unknown column's: one readable line
  e->value = sym::read_expression(
      text, where,
      {names, "(the mechanism's columns, parameters and definitions)", nullptr, nullptr, {}, kLongestValidList});
  for (std::size_t i = 0; i < available.size(); ++i)
    if (e->value.has(symbols[i])) e->inputs.emplace_back(symbols[i], available[i]);
  if (system != nullptr)
    for (const auto& [n, symbol] : system->names())
      if (!column_of.contains(n) && e->value.has(symbol)) e->parameters.push_back(n);

  MechanismColumn out;
  out.name = name;
  out.unit = unit_of(*e, system);
  out.meaning = name + " = " + text;
  out.quantity = MechanismQuantity::expression;
  out.expression = std::move(e);
  return out;
}

double expression_value(const ColumnExpression& e, double t, const Eigen::VectorXd& y,
                        const eval::MechanismSample& sample, const ColumnOrigin& origin) {
  GiNaC::exmap values = e.fixed;
  for (const auto& [symbol, column] : e.inputs) values[symbol] = column_value(column, t, y, sample, origin);
  const double v = sym::evaluate(e.value, values);
  if (!std::isfinite(v))
    throw Error::input(e.origin + ": column '" + e.name + "' = " + e.text + " is " +
                       (std::isnan(v) ? "not a number" : "infinite") + " at t = " + format_significant(t, 9) +
                       " s; valid: an expression defined all along the run (check divisions, sqrt, log, asin, acos)");
  return v;
}

}  // namespace linkage
