#include "symbolic/symbols.hpp"

namespace linkage::sym {

int role_band(Role role) {
  switch (role) {
    case Role::parameter:
      return 1000;
    case Role::definition:
      return 2000;
    case Role::inertia:
      return 3000;
    case Role::time:
      return 4000;
    case Role::rate:
      return 5000;
    case Role::coordinate:
      return 6000;
    case Role::length:
      return 5500;
    case Role::acceleration:
      return 8000;
    case Role::force:
      return 9000;
  }
  return 0;
}

const SymbolInfo& SymbolTable::add(SymbolInfo info) {
  int in_band = 0;
  for (const SymbolInfo& e : entries_)
    if (e.role == info.role) ++in_band;
  info.rank = role_band(info.role) + in_band;
  entries_.push_back(std::move(info));
  return entries_.back();
}

const SymbolInfo* SymbolTable::find(const GiNaC::symbol& symbol) const {
  for (const SymbolInfo& e : entries_)
    if (e.symbol.is_equal(symbol)) return &e;
  return nullptr;
}

const SymbolInfo* SymbolTable::find(const std::string& key) const {
  for (const SymbolInfo& e : entries_)
    if (e.key == key) return &e;
  return nullptr;
}

}  // namespace linkage::sym
