#include "symbolic/shaking.hpp"

#include "model/joint_types.hpp"
#include "symbolic/joints.hpp"

namespace linkage::sym {

GroundReaction ground_reaction(const System& system) {
  const Mechanism& m = system.mechanism();
  GroundReaction out;
  const auto add = [&](const Vec2& force, const Vec2& at, const GiNaC::ex& moment) {
    out.force = out.force + force;
    out.moment += cross(at, force) + moment;
  };
  for (const JointSystem& js : system.joints()) {
    const Joint& joint = m.joints[static_cast<std::size_t>(js.index)];
    const int a = m.body_index(joint.bodies[0]), b = m.body_index(joint.bodies[1]);
    const auto [at_a, at_b] = force_points(system, js.index);  // as add_newton_euler applies them
    if (a < 0)
      add(js.force, at_a, js.moment);
    else if (b < 0)
      add(GiNaC::ex(-1) * js.force, at_b, -js.moment);
  }
  for (const DriverSystem& d : system.drivers()) {
    const Joint& joint = m.joints[static_cast<std::size_t>(d.joint)];
    if (m.body_index(joint.bodies[0]) >= 0 && m.body_index(joint.bodies[1]) >= 0) continue;
    for (const Load& load : d.loads) add(GiNaC::ex(-1) * load.force, load.point, -load.moment);
  }
  for (const Spring& spring : m.springs) {
    const bool a_ground = m.body_index(spring.between[0].body) < 0, b_ground = m.body_index(spring.between[1].body) < 0;
    if (a_ground == b_ground) continue;  // between two moving bodies (both ends on the ground: no load)
    const Vec2 at = system.point_position(-1, spring.between[a_ground ? 0 : 1].point);
    for (const Load& load : system.loads())
      if (load.source == spring.name) add(GiNaC::ex(-1) * load.force, at, 0);
  }
  for (const Joint& joint : m.joints) {
    if (m.body_index(joint.bodies[0]) >= 0 && m.body_index(joint.bodies[1]) >= 0) continue;
    if (!joint_type_info(joint.type).torsional_spring || (!joint.stiffness && !joint.damping)) continue;
    for (const Load& load : system.loads())
      if (load.source == joint.name) add({}, {}, -load.moment);
  }
  return out;
}

}  // namespace linkage::sym
