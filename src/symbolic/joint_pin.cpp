// Pin joint. Position rows: r_a + R(th_a) s_a - (r_b + R(th_b) s_b) = 0 (x and y).
// Force: F = (Fx, Fy), the force b exerts on a, at the pin; -F on b.
// Tree: the child keeps its own angle; its centre follows from the pin point.
#include "symbolic/joints.hpp"

namespace linkage::sym {

Vec2 world_point(const Placement& body, const Vec2& local) { return body.position + rotate(body.angle, local); }

std::vector<GiNaC::ex> pin_constraints(const JointEnds& ends) {
  const Vec2 d = world_point(ends.a, ends.point_a) - world_point(ends.b, ends.point_b);
  return {d.x, d.y};
}

void pin_force(JointSystem& joint, const SymbolTable& table) {
  const auto& fx = table.find(joint.unknowns.at(0));
  const auto& fy = table.find(joint.unknowns.at(1));
  if (fx == nullptr || fy == nullptr) throw std::logic_error("pin force symbols missing");
  joint.force = {joint.unknowns[0], joint.unknowns[1]};
  joint.moment = 0;
}

Placement pin_place(const JointEnds& ends, bool child_is_b, const GiNaC::ex& child_angle) {
  const Placement& parent = child_is_b ? ends.a : ends.b;
  const Vec2& parent_point = child_is_b ? ends.point_a : ends.point_b;
  const Vec2& child_point = child_is_b ? ends.point_b : ends.point_a;
  Placement child;
  child.angle = child_angle;
  child.position = world_point(parent, parent_point) - rotate(child_angle, child_point);
  return child;
}

}  // namespace linkage::sym
