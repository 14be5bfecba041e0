// Pin joint: a point of a and a point of b coincide.
//   rows:   r_a + R(th_a) s_a - (r_b + R(th_b) s_b) = 0 (x and y)
//   force:  F = (Fx, Fy), the force b exerts on a, at the pin; -F on b; no moment
//   tree:   revolute: the child keeps its own angle; its centre follows from the pin point
//   driver: prescribes th_b - th_a (the ground's angle is 0)
#include "symbolic/joints.hpp"

namespace linkage::sym {
namespace {

std::vector<GiNaC::ex> rows(const JointEnds& ends) {
  const Vec2 d = world_point(ends.a, ends.point_a) - world_point(ends.b, ends.point_b);
  return {d.x, d.y};
}

std::vector<ForceUnknown> unknowns(const Joint& joint, bool single, const std::string& on) {
  // The homework's only joint prints as the spec's Fx, Fy.
  const std::string fx = single ? "Fx" : "Fx_" + joint.name;
  const std::string fy = single ? "Fy" : "Fy_" + joint.name;
  const std::string lx = single ? "F_x" : "F_{x," + joint.name + "}";
  const std::string ly = single ? "F_y" : "F_{y," + joint.name + "}";
  return {{"force_x", {fx, fx, lx}, "N", "pin force on " + on + ", x"},
          {"force_y", {fy, fy, ly}, "N", "pin force on " + on + ", y"}};
}

void force(JointSystem& joint, const JointEnds&) {
  joint.force = {joint.unknowns.at(0), joint.unknowns.at(1)};
  joint.moment = 0;
}

Placement place(const JointEnds& ends, bool child_is_b, const TreeCoordinates& coordinates) {
  const GiNaC::ex& child_angle = coordinates.angle;
  const Placement& parent = child_is_b ? ends.a : ends.b;
  const Vec2& parent_point = child_is_b ? ends.point_a : ends.point_b;
  const Vec2& child_point = child_is_b ? ends.point_b : ends.point_a;
  Placement child;
  child.angle = child_angle;
  child.position = world_point(parent, parent_point) - rotate(child_angle, child_point);
  return child;
}

GiNaC::ex no_coordinate(const JointEnds&) { return 0; }

GiNaC::ex relative_angle(const JointEnds& ends) { return ends.b.angle - ends.a.angle; }

}  // namespace

extern const JointStages kPinJoint{
    rows,           unknowns, force, false, place, nullptr, no_coordinate, false, "m", "m/s", JointDrawing::marker,
    relative_angle, "tau",    "N m"};

}  // namespace linkage::sym
