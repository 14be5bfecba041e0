#pragma once
// The values a lesson's text and answers may quote about a mechanism, by the names of
// `linkage solve --mechanism --format json` and, where its file has them, its [aliases]
// (the homework's x1, I_zz_P, F_x): worked out from the one symbolic system.
#include <ginac/ginac.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "symbolic/system.hpp"

namespace linkage {

/// The parameters, definitions and body inertias (I, I_1) at the parameter values; the
/// initial coordinates and rates, loops closed ("2.theta", "S.s_dot"); the derived values
/// ("I^P", "P.x", "2.x_dot", "kinetic_energy", "angular_momentum_c"); the centre of mass
/// ("com.x", "com.y", "com.x_dot", "com.y_dot"); Case 3's unknowns at the start and what it
/// recovers ("2.theta_ddot", "B.force_x"); and each case's condition number and residual
/// ("cond1", "residual1", ... "cond3", "residual3"). Cases 1 and 2 are worked out only when
/// one of their names is asked for: a big mechanism pays for them only when quoted. The
/// small vibrations about the equilibrium (`linkage modes`), worked out only when quoted:
/// "modes.count", and for each mode k "modek.omega" (rad/s), "modek.frequency_hz" (Hz),
/// "modek.period" (s), "modek.damping_ratio", "modek.growth_rate" (1/s) and each tree
/// coordinate's share of its shape, "2.theta_modek" (largest independent component 1).
class QuotableValues {
 public:
  /// Works out the state, derived values and Case 3. Throws Error::input as
  /// work_out_mechanism does.
  explicit QuotableValues(std::shared_ptr<const sym::System> system);

  /// Every name, sorted: each key and, where the file has one, its alias.
  [[nodiscard]] const std::vector<std::string>& names() const { return names_; }
  [[nodiscard]] bool has(const std::string& name) const;
  /// The value of `name` (one of names()). Working out a case may throw Error::input (a
  /// singular matrix), as work_out_mechanism does.
  [[nodiscard]] GiNaC::ex value(const std::string& name) const;
  /// Its unit as the reports print it ("kg m^2"); empty for a pure number.
  [[nodiscard]] std::string unit(const std::string& name) const;

 private:
  struct Modes;  // the linearization and its modes
  struct Entry {
    GiNaC::ex value;
    std::string unit;
    int case_number = 0;                       // 1 or 2: worked out when asked for; else known
    std::function<double(const Modes&)> mode;  // a mode's value: worked out when asked for
  };
  [[nodiscard]] const Entry& entry(const std::string& name) const;
  void add(const std::string& key, const GiNaC::ex& value, const std::string& unit, int case_number = 0);
  void add_modes();

  std::shared_ptr<const sym::System> system_;
  std::map<std::string, Entry> entries_;     // by key (unaliased)
  std::map<std::string, std::string> keys_;  // every name -> its key
  std::vector<std::string> names_;
  mutable std::map<int, std::pair<double, double>> cases_;  // case -> (condition, residual)
  mutable std::shared_ptr<const Modes> modes_;
};

}  // namespace linkage
