// Weld joint: a point of a and a point of b coincide, the bodies at the relative angle
// alpha (`angle`, default 0).
//   rows:   r_a + R(th_a) s_a - (r_b + R(th_b) s_b) = 0 (x and y),   th_b - th_a - alpha = 0
//   force:  F = (Fx, Fy) and a moment M, what b exerts on a, at a's point; the opposite on b
//   tree:   fixed: no coordinate; the child's angle and centre follow from its parent's
//   driver: none
#include "symbolic/joints.hpp"

namespace linkage::sym {
namespace {

std::vector<GiNaC::ex> rows(const JointEnds& ends) {
  const Vec2 d = world_point(ends.a, ends.point_a) - world_point(ends.b, ends.point_b);
  return {d.x, d.y, ends.b.angle - ends.a.angle - ends.angle};
}

std::vector<ForceUnknown> unknowns(const Joint& joint, bool, const std::string& on) {
  return {{"force_x",
           {"Fx_" + joint.name, "Fx_" + joint.name, "F_{x," + joint.name + "}"},
           "N",
           "weld force on " + on + ", x"},
          {"force_y",
           {"Fy_" + joint.name, "Fy_" + joint.name, "F_{y," + joint.name + "}"},
           "N",
           "weld force on " + on + ", y"},
          {"moment", spell_indexed("M", 0, joint.name), "N m", "weld moment on " + on}};
}

void force(JointSystem& joint, const JointEnds&) {
  joint.force = {joint.unknowns.at(0), joint.unknowns.at(1)};
  joint.moment = joint.unknowns.at(2);
}

Placement place(const JointEnds& ends, bool child_is_b, const TreeCoordinates&) {
  const Placement& parent = child_is_b ? ends.a : ends.b;
  const Vec2& parent_point = child_is_b ? ends.point_a : ends.point_b;
  const Vec2& child_point = child_is_b ? ends.point_b : ends.point_a;
  Placement child;
  child.angle = child_is_b ? parent.angle + ends.angle : parent.angle - ends.angle;
  child.position = world_point(parent, parent_point) - rotate(child.angle, child_point);
  return child;
}

GiNaC::ex no_coordinate(const JointEnds&) { return 0; }

}  // namespace

extern const JointStages kWeldJoint{
    rows,    unknowns, force, false, place, nullptr, no_coordinate, true, "m, rad", "m/s, rad/s", JointDrawing::bracket,
    nullptr, "",       ""};

}  // namespace linkage::sym
