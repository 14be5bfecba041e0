#include "lesson/expression.hpp"

#include <ginac/ginac.h>

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
