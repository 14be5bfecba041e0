#include "symbolic/energy.hpp"

#include "core/interrupt.hpp"
#include "model/joint_types.hpp"

namespace linkage::sym {

using GiNaC::ex;

namespace {

// Index into System::bodies(), -1 for the ground.
int body_of(const System& system, const std::string& name) {
  const auto& bodies = system.mechanism().bodies;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == name) return static_cast<int>(i);
  return -1;
}

// A body's angle and its rate; 0 for the ground and for a point mass.
ex angle_of(const System& system, int body) {
  if (body < 0) return 0;
  const BodySystem& b = system.bodies()[static_cast<std::size_t>(body)];
  return b.rotates ? ex(b.theta.q) : ex(0);
}

ex spring_length(const System& system, const Spring& spring) {
  const Vec2 d = system.point_position(body_of(system, spring.between[1].body), spring.between[1].point) -
                 system.point_position(body_of(system, spring.between[0].body), spring.between[0].point);
  return GiNaC::sqrt(d.x * d.x + d.y * d.y);
}

// th_b - th_a of a pin.
ex relative_angle(const System& system, const Joint& joint) {
  return angle_of(system, body_of(system, joint.bodies[1])) - angle_of(system, body_of(system, joint.bodies[0]));
}

// A spring's elastic force -k (x - rest) has the potential k (x - rest)^2 / 2 only when k
// and rest are constants; with either depending on the state it works as a load does.
struct Elastic {
  ex stiffness, stretch;
  bool conservative = true;
};

Elastic spring_elastic(const System& system, const Spring& spring) {
  const ex k = system.quantity(spring.stiffness, false, true);
  const ex rest = system.quantity(spring.rest_length, false, true);
  return {k, spring_length(system, spring) - rest, !system.depends_on_state(k) && !system.depends_on_state(rest)};
}

Elastic pin_elastic(const System& system, const Joint& joint) {
  const ex k = system.quantity(*joint.stiffness, false, true);
  const ex rest = joint.rest_angle ? system.quantity(*joint.rest_angle, false, true) : ex(0);
  return {k, relative_angle(system, joint) - rest, !system.depends_on_state(k) && !system.depends_on_state(rest)};
}

}  // namespace

ex kinetic_energy(const System& system) {
  ex T = 0;
  for (const BodySystem& b : system.bodies()) {
    T += b.mass * (GiNaC::pow(b.x.q_dot, 2) + GiNaC::pow(b.y.q_dot, 2)) / 2;
    if (b.rotates) T += b.inertia * GiNaC::pow(b.theta.q_dot, 2) / 2;
  }
  return T;
}

ex potential_energy(const System& system) {
  const Mechanism& mechanism = system.mechanism();
  ex V = 0;
  if (mechanism.gravity) {
    const ex g = system.quantity(*mechanism.gravity, false);
    for (const BodySystem& b : system.bodies()) V += b.mass * g * b.y.q;
  }
  for (const Spring& spring : mechanism.springs)
    if (const Elastic e = spring_elastic(system, spring); e.conservative)
      V += e.stiffness * GiNaC::pow(e.stretch, 2) / 2;
  for (const Joint& joint : mechanism.joints) {
    if (!joint_type_info(joint.type).torsional_spring || !joint.stiffness) continue;
    if (const Elastic e = pin_elastic(system, joint); e.conservative) V += e.stiffness * GiNaC::pow(e.stretch, 2) / 2;
  }
  return V;
}

std::vector<PowerTerm> nonconservative_power_terms(const System& system) {
  const Mechanism& mechanism = system.mechanism();
  std::vector<PowerTerm> terms;
  for (const Spring& spring : mechanism.springs) {
    const ex rate = system.time_derivative(spring_length(system, spring));
    if (const Elastic e = spring_elastic(system, spring); !e.conservative)
      terms.push_back({-e.stiffness * e.stretch, rate});
    const ex damping = system.quantity(spring.damping, false, true);
    if (damping.is_zero()) continue;
    terms.push_back({-damping * rate, rate});
  }
  for (const Joint& joint : mechanism.joints) {
    if (!joint_type_info(joint.type).torsional_spring) continue;
    const ex rate = system.time_derivative(relative_angle(system, joint));
    if (joint.stiffness)
      if (const Elastic e = pin_elastic(system, joint); !e.conservative)
        terms.push_back({-e.stiffness * e.stretch, rate});
    if (joint.damping) terms.push_back({-system.quantity(*joint.damping, false, true) * rate, rate});
  }
  for (const AppliedForce& force : mechanism.forces) {
    const Vec2 at = system.point_position(body_of(system, force.body), force.point);
    terms.push_back({system.quantity(force.value.x, true, true), system.time_derivative(at.x)});
    terms.push_back({system.quantity(force.value.y, true, true), system.time_derivative(at.y)});
  }
  for (const AppliedTorque& torque : mechanism.torques)
    terms.push_back({system.quantity(torque.value, true, true),
                     system.time_derivative(angle_of(system, body_of(system, torque.body)))});
  return terms;
}

ex nonconservative_power(const System& system) {
  ex P = 0;
  for (const PowerTerm& term : nonconservative_power_terms(system)) P += term.load * term.rate;
  return P;
}

Vec2 linear_momentum(const System& system) {
  Vec2 p;
  for (const BodySystem& b : system.bodies()) p = p + b.mass * Vec2{b.x.q_dot, b.y.q_dot};
  return p;
}

ex total_mass(const System& system) {
  ex M = 0;
  for (const BodySystem& b : system.bodies()) M += b.mass;
  return M;
}

Vec2 centre_of_mass(const System& system) {
  Vec2 moment;
  for (const BodySystem& b : system.bodies()) moment = moment + b.mass * Vec2{b.x.q, b.y.q};
  const ex M = total_mass(system);
  return {moment.x / M, moment.y / M};
}

Vec2 centre_of_mass_velocity(const System& system) {
  const Vec2 p = linear_momentum(system);
  const ex M = total_mass(system);
  return {p.x / M, p.y / M};
}

ex angular_momentum(const System& system) {
  ex H = 0;
  for (const BodySystem& b : system.bodies()) {
    H += b.mass * (b.x.q * b.y.q_dot - b.y.q * b.x.q_dot);
    if (b.rotates) H += b.inertia * b.theta.q_dot;
  }
  return H;
}

ex angular_momentum_about_centre(const System& system) {
  // sum over body pairs a < b of m_a m_b / M (r_a - r_b) x (r_a' - r_b'), plus the spins:
  // the same as sum m (r - r_c) x (r' - r_c'), written in relative positions that read
  // well (the homework's m (x1 - x2) (y1' - y2') / 2 - ...).
  const std::vector<BodySystem>& bodies = system.bodies();
  const ex M = total_mass(system);
  // n^2 terms, summed once: adding them one by one copied the growing sum each time (n^4,
  // seconds for a long chain, with no chance to stop at a signal).
  GiNaC::exvector terms;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    throw_if_interrupted();
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      const BodySystem &a = bodies[i], &b = bodies[j];
      terms.push_back(a.mass * b.mass / M *
                      ((a.x.q - b.x.q) * (a.y.q_dot - b.y.q_dot) - (a.y.q - b.y.q) * (a.x.q_dot - b.x.q_dot)));
    }
  }
  for (const BodySystem& b : bodies)
    if (b.rotates) terms.push_back(b.inertia * b.theta.q_dot);
  return GiNaC::add(terms);
}

}  // namespace linkage::sym
