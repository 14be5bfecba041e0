#include "integrate/load_guard.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/number_format.hpp"

namespace linkage {

LoadGuard::LoadGuard(const sym::System& system, const eval::MechanismDynamics& dynamics) : dynamics_(&dynamics) {
  const Mechanism& m = system.mechanism();
  std::vector<GiNaC::ex> expressions;
  // The values the start's checks read with the state allowed; a load's with t too.
  const auto add = [&](const Quantity& q, const std::string& what, bool time_allowed, bool non_negative) {
    const GiNaC::ex e = system.quantity(q, time_allowed, true);
    if (!e.has(system.time()) && !system.depends_on_state(e)) return;  // checked once at the start
    values_.push_back({what, &q, non_negative});
    expressions.push_back(e);
  };
  for (const Joint& j : m.joints) {
    if (j.stiffness) add(*j.stiffness, "stiffness of joint " + j.name, false, true);
    if (j.damping) add(*j.damping, "damping of joint " + j.name, false, true);
    if (j.rest_angle) add(*j.rest_angle, "rest angle of joint " + j.name, false, false);
  }
  for (const Spring& s : m.springs) {
    add(s.stiffness, "stiffness of spring " + s.name, false, true);
    add(s.rest_length, "rest length of spring " + s.name, false, true);
    add(s.damping, "damping of spring " + s.name, false, true);
  }
  for (const AppliedForce& f : m.forces) {
    add(f.value.x, "force on " + f.body + " x", true, false);
    add(f.value.y, "force on " + f.body + " y", true, false);
  }
  for (const AppliedTorque& t : m.torques) add(t.value, "torque on " + t.body, true, false);
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
