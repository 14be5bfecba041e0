#include "lesson/expression.hpp"

#include <ginac/ginac.h>

#include <nlohmann/json.hpp>

#include "report/mechanism_solution.hpp"
#include "symbolic/expression_reader.hpp"
#include "symbolic/system.hpp"

namespace linkage::lesson {
namespace {

// One GiNaC symbol per quantity, in table order; pi is GiNaC's constant.
struct QuantitySymbols {
  std::vector<GiNaC::ex> symbols;
  GiNaC::symtab names;
  QuantitySymbols() {
    for (const QuantityInfo& q : kQuantities) {
      const std::string name(q.name);
      symbols.push_back(name == "pi" ? GiNaC::ex(GiNaC::Pi) : GiNaC::ex(GiNaC::symbol(name)));
      names[name] = symbols.back();
    }
  }
};

const QuantitySymbols& quantity_symbols() {
  static const QuantitySymbols table;
  return table;
}

}  // namespace

MechanismNames mechanism_names(const sym::System& system) {
  MechanismNames out;
  for (const sym::SymbolInfo& info : system.table().all()) {
    if (info.role == sym::Role::parameter)
      out[info.symbol.get_name()] = system.parameter_values().at(info.symbol);
    else if (info.role == sym::Role::definition || info.role == sym::Role::inertia)
      out[info.symbol.get_name()] = system.constants().at(info.symbol).subs(system.parameter_values());
  }
  // The initial coordinates and rates (loops closed) and the Case 3 unknowns at the start
  // with what it recovers, by the names and values of `linkage solve --mechanism --format json`.
  const nlohmann::json solved =
      nlohmann::json::parse(mechanism_json(work_out_mechanism(system.mechanism(), case_ids({3}))));
  auto add = [&](const nlohmann::json& values) {
    for (const auto& [name, value] : values.items())
      if (value.is_number()) out[name] = GiNaC::numeric(value.get<double>());
  };
  add(solved.at("state"));
  for (const nlohmann::json& c : solved.at("cases")) {
    add(c.at("solution"));
    if (c.contains("recovered")) add(c.at("recovered"));
  }
  return out;
}

Expression Expression::parse(std::string_view text, const std::string& origin, const MechanismNames* mechanism) {
  Expression e;
  e.text_ = std::string(text);
  if (mechanism == nullptr) {
    e.value_ = std::make_shared<const GiNaC::ex>(sym::read_expression(text, origin, {quantity_symbols().names}));
  } else {
    GiNaC::symtab names = quantity_symbols().names;
    for (const auto& [name, value] : *mechanism) names[name] = value;
    e.value_ = std::make_shared<const GiNaC::ex>(sym::read_expression(text, origin, {names}));
  }
  return e;
}

double Expression::evaluate(const QuantityValues& values) const {
  const QuantitySymbols& table = quantity_symbols();
  GiNaC::exmap at;
  for (std::size_t i = 0; i < kQuantities.size(); ++i)
    if (GiNaC::is_a<GiNaC::symbol>(table.symbols[i]) && value_->has(table.symbols[i]))
      at[table.symbols[i]] = GiNaC::numeric(values[i]);
  return sym::evaluate(*value_, at);
}

const QuantityInfo* Expression::single_quantity() const {
  const QuantitySymbols& table = quantity_symbols();
  for (std::size_t i = 0; i < kQuantities.size(); ++i)
    if (GiNaC::is_a<GiNaC::symbol>(table.symbols[i]) && value_->is_equal(table.symbols[i])) return &kQuantities[i];
  return nullptr;
}

}  // namespace linkage::lesson
