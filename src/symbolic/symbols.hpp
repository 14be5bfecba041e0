#pragma once
// Every GiNaC symbol of a mechanism's equations with how it is spelt and ordered in print:
// parameters (L, m, g), definitions (D), body inertias (I), the time t, each body's
// maximal coordinates x, y, theta with their rates and accelerations, slider coordinates
// s, and the joint forces. The printers, the exporters and the evaluator all look symbols
// up here; nothing else knows a spelling.
#include <ginac/ginac.h>

#include <deque>
#include <map>
#include <string>

namespace linkage::sym {

enum class Role {
  parameter,     // a number of the file's [parameters]
  definition,    // a named expression of [definitions]
  inertia,       // a body's centroidal moment of inertia
  time,          // t
  coordinate,    // x1, theta1, s
  length,        // a spring's length, a function of the coordinates
  rate,          // x1', theta1'
  acceleration,  // x1'', theta1'' (unknowns)
  force,         // a joint force component or slider moment (unknowns)
};

/// How one symbol prints, its unit and meaning, and where it sorts in a product: factors
/// print in increasing `rank` (numbers, parameters in file order, definitions, inertias,
/// rates, functions of coordinates, unknowns), as the homework writes "m g D cos θ₁".
struct SymbolInfo {
  GiNaC::symbol symbol;
  Role role = Role::parameter;
  std::string key;      // stable name: "L", "1.theta", "1.theta_dot", "1.theta_ddot", "P.force_x"
  std::string unicode;  // "θ̈₁"
  std::string ascii;    // "th1''"
  std::string latex;    // "\ddot{\theta}_1"
  std::string unit;     // ASCII unit: "rad/s^2"
  std::string meaning;  // "angular acceleration of body 1"
  int rank = 0;
};

class SymbolTable {
 public:
  /// Adds a symbol; its rank is the order of addition within its role's band.
  const SymbolInfo& add(SymbolInfo info);
  /// The entry of `symbol`, or nullptr for a symbol this table did not make.
  [[nodiscard]] const SymbolInfo* find(const GiNaC::symbol& symbol) const;
  [[nodiscard]] const SymbolInfo* find(const std::string& key) const;
  [[nodiscard]] const std::deque<SymbolInfo>& all() const { return entries_; }

 private:
  std::deque<SymbolInfo> entries_;  // a deque: entries stay where they are as the table grows
  // Lookups by symbol and by key, and the entries of each role so far: a long chain's
  // table has thousands of entries, looked up for every factor printed.
  std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> by_symbol_;
  std::map<std::string, std::size_t, std::less<>> by_key_;
  std::map<Role, int> in_band_;
};

/// The band of ranks of each role, so a product's factors sort by role first.
[[nodiscard]] int role_band(Role role);

}  // namespace linkage::sym
