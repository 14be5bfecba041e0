#include "symbolic/state_values.hpp"

namespace linkage::sym {

std::vector<StateValue> state_values(const System& system) {
  const Mechanism& m = system.mechanism();
  std::vector<StateValue> out;
  // The values the start's checks read with the state allowed; a load's with t too.
  const auto add = [&](const Quantity& q, const std::string& what, bool time_allowed, bool non_negative) {
    const GiNaC::ex e = system.quantity(q, time_allowed, true);
    if (e.has(system.time()) || system.depends_on_state(e)) out.push_back({what, &q, non_negative, e});
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
  return out;
}

}  // namespace linkage::sym
