// Slider joint, axis u (unit, in the frame of a) and normal n = k x u. Position rows:
//   n . (p_b - p_a) = 0,   th_b - th_a = 0.
// Coordinate s = u . (p_b - p_a). Force: N n, the force b exerts on a, acting at p_b, and
// a moment M; the opposite on b.
#include "symbolic/joints.hpp"

namespace linkage::sym {
namespace {

Vec2 unit_local(const Vec2& axis) {
  const GiNaC::ex length = GiNaC::sqrt(axis.x * axis.x + axis.y * axis.y);
  return {axis.x / length, axis.y / length};
}

Vec2 normal_of(const Vec2& u) { return {-u.y, u.x}; }

}  // namespace

Vec2 slider_axis(const JointEnds& ends) { return rotate(ends.a.angle, unit_local(ends.axis)); }

std::vector<GiNaC::ex> slider_constraints(const JointEnds& ends) {
  const Vec2 d = world_point(ends.b, ends.point_b) - world_point(ends.a, ends.point_a);
  const Vec2 n = normal_of(slider_axis(ends));
  return {n.x * d.x + n.y * d.y, ends.b.angle - ends.a.angle};
}

void slider_force(JointSystem& joint, const JointEnds& ends, const SymbolTable& table) {
  if (table.find(joint.unknowns.at(0)) == nullptr || table.find(joint.unknowns.at(1)) == nullptr)
    throw std::logic_error("slider force symbols missing");
  const Vec2 n = normal_of(slider_axis(ends));
  joint.force = GiNaC::ex(joint.unknowns[0]) * n;
  joint.moment = joint.unknowns[1];
}

Placement slider_place(const JointEnds& ends, bool child_is_b, const GiNaC::ex& s) {
  Placement child;
  if (child_is_b) {
    child.angle = ends.a.angle;
    const Vec2 u = slider_axis(ends);
    child.position = world_point(ends.a, ends.point_a) + s * u - rotate(child.angle, ends.point_b);
  } else {
    child.angle = ends.b.angle;
    JointEnds as_placed = ends;
    as_placed.a.angle = child.angle;
    const Vec2 u = slider_axis(as_placed);
    child.position = world_point(ends.b, ends.point_b) - s * u - rotate(child.angle, ends.point_a);
  }
  return child;
}

}  // namespace linkage::sym
