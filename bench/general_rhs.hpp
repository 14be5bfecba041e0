#pragma once
// The homework on the general path: two-blocks.toml's Case 3 through the MechanismDynamics
// that simulate runs, native code attached as simulate's `auto` does (built in, so no
// compiler), as an integrator's f(t, y, dydt) on the closed form's eight values: the same
// coordinates (x1, y1, theta1, theta2, then their rates); the ninth, the work W of
// dampers and loads, is 0 here and not integrated.
#include <memory>
#include <string>

#include "bench/closed_form/params.hpp"
#include "bench/closed_form/state.hpp"

namespace linkage::bench {

class GeneralCase3Rhs {
 public:
  /// The mechanism at `p`: derived and compiled once per distinct Params in the process,
  /// so a run's time holds its integration alone (after a first, untimed construction).
  explicit GeneralCase3Rhs(const Params& p);
  void operator()(double t, const Vec<8>& y, Vec<8>& dydt) const;
  /// What computes the equations, as simulate's summary says it: "compiled (built in)",
  /// or "interpreted (why)" when this program has no native code for it.
  [[nodiscard]] const std::string& evaluator() const;

 private:
  struct Shared;
  std::shared_ptr<Shared> shared_;
};

}  // namespace linkage::bench
