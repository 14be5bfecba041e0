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
  info.rank = role_band(info.role) + in_band_[info.role]++;
  by_symbol_.emplace(info.symbol, entries_.size());
  by_key_.emplace(info.key, entries_.size());
  entries_.push_back(std::move(info));
  return entries_.back();
}

const SymbolInfo* SymbolTable::find(const GiNaC::symbol& symbol) const {
  const auto it = by_symbol_.find(symbol);
  return it == by_symbol_.end() ? nullptr : &entries_[it->second];
}

const SymbolInfo* SymbolTable::find(const std::string& key) const {
  const auto it = by_key_.find(key);
  return it == by_key_.end() ? nullptr : &entries_[it->second];
}

}  // namespace linkage::sym
