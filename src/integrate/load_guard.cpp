#include "integrate/load_guard.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "symbolic/state_values.hpp"

namespace linkage {

LoadGuard::LoadGuard(const sym::System& system, const eval::MechanismDynamics& dynamics) : dynamics_(&dynamics) {
  std::vector<GiNaC::ex> expressions;
  for (const sym::StateValue& v : sym::state_values(system)) {
    values_.push_back({v.what, v.quantity, v.non_negative});
    expressions.push_back(v.value);
  }
  if (values_.empty()) return;
  program_ = dynamics.compile_over_state(expressions);
  out_.resize(program_.output_count());
  scratch_.resize(program_.scratch_size());
}

std::string LoadGuard::check(double t, const Eigen::VectorXd& y) {
  if (values_.empty()) return {};
  dynamics_->evaluate_over_state(program_, t, y, out_.data(), scratch_.data());
  for (std::size_t k = 0; k < values_.size(); ++k) {
    const Value& v = values_[k];
    const double value = out_[k];
    const bool finite = std::isfinite(value);
    if (finite && (!v.non_negative || value >= 0)) continue;
    return where(v.quantity->pos) + v.what + " \"" + v.quantity->text + "\" is " + format_significant(value, 6) +
           " at t = " + format_significant(t, 6) + " s" +
           (finite ? std::string() : " (a division by zero, or the square root or logarithm of a negative number)") +
           "; valid: " + (v.non_negative ? ">= 0" : "a finite number") + " at every state the run reaches";
  }
  return {};
}

void LoadGuard::require(double t, const Eigen::VectorXd& y) {
  if (std::string line = check(t, y); !line.empty()) throw Error::input(line);
}

}  // namespace linkage
