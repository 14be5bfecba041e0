// Slider joint, axis u (unit, in the frame of a) and normal n = k x u: b's point moves
// along the line through a's point, the two bodies at equal angles.
//   rows:   n . (p_b - p_a) = 0,   th_b - th_a = 0
//   force:  N n, the force b exerts on a, acting at p_b, and a moment M; the opposite on b
//   tree:   prismatic: its own coordinate s = u . (p_b - p_a); the child keeps the
//           parent's angle
//   driver: prescribes s
#include "symbolic/joints.hpp"

namespace linkage::sym {
namespace {

Vec2 unit_local(const Vec2& axis) {
  const GiNaC::ex length = GiNaC::sqrt(axis.x * axis.x + axis.y * axis.y);
  return {axis.x / length, axis.y / length};
}

Vec2 normal_of(const Vec2& u) { return {-u.y, u.x}; }

/// The unit axis in the world.
Vec2 world_axis(const JointEnds& ends) { return rotate(ends.a.angle, unit_local(ends.axis)); }

std::vector<GiNaC::ex> rows(const JointEnds& ends) {
  const Vec2 d = world_point(ends.b, ends.point_b) - world_point(ends.a, ends.point_a);
  const Vec2 n = normal_of(world_axis(ends));
  return {n.x * d.x + n.y * d.y, ends.b.angle - ends.a.angle};
}

std::vector<ForceUnknown> unknowns(const Joint& joint, bool, const std::string& on) {
  return {{"normal", spell_indexed("N", 0, joint.name), "N", "slider force across the axis on " + on},
          {"moment", spell_indexed("M", 0, joint.name), "N m", "slider moment on " + on}};
}

void force(JointSystem& joint, const JointEnds& ends) {
  const Vec2 n = normal_of(world_axis(ends));
  joint.force = GiNaC::ex(joint.unknowns.at(0)) * n;
  joint.moment = joint.unknowns.at(1);
}

Placement place(const JointEnds& ends, bool child_is_b, const TreeCoordinates& coordinates) {
  const GiNaC::ex& s = coordinates.travel;
  Placement child;
  if (child_is_b) {
    child.angle = ends.a.angle;
    const Vec2 u = world_axis(ends);
    child.position = world_point(ends.a, ends.point_a) + s * u - rotate(child.angle, ends.point_b);
  } else {
    child.angle = ends.b.angle;
    JointEnds as_placed = ends;
    as_placed.a.angle = child.angle;
    const Vec2 u = world_axis(as_placed);
    child.position = world_point(ends.b, ends.point_b) - s * u - rotate(child.angle, ends.point_a);
  }
  return child;
}

GiNaC::ex coordinate(const JointEnds& ends) {
  const Vec2 u = world_axis(ends);
  const Vec2 d = world_point(ends.b, ends.point_b) - world_point(ends.a, ends.point_a);
  return u.x * d.x + u.y * d.y;
}

const OwnCoordinate kTravel{
    "s", {"m", "m/s", "m/s^2"}, {"position along slider ", "velocity along slider ", "acceleration along slider "}};

}  // namespace

extern const JointStages kSliderJoint{
    rows,         unknowns,           force,      true, place, &kTravel, coordinate, true, "m, rad",
    "m/s, rad/s", JointDrawing::rail, coordinate, "F",  "N"};

}  // namespace linkage::sym
