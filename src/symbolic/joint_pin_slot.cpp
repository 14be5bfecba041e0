// Pin-slot joint: a pin P of b slides in a straight slot of a through A, axis u (unit, in
// the frame of a), normal n = k x u; the bodies turn freely.
//   rows:   n . (P - A) = 0
//   force:  N n, the force b exerts on a, acting at P; no moment; the opposite on b
//   tree:   slotted: the joint's travel s = u . (P - A), then the child's own angle
//   driver: none
#include "symbolic/joints.hpp"

namespace linkage::sym {
namespace {

/// The unit axis in the world, the slot's body at `angle_a`.
Vec2 world_axis(const JointEnds& ends, const GiNaC::ex& angle_a) {
  const GiNaC::ex length = GiNaC::sqrt(ends.axis.x * ends.axis.x + ends.axis.y * ends.axis.y);
  return rotate(angle_a, {ends.axis.x / length, ends.axis.y / length});
}

GiNaC::ex dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }

std::vector<GiNaC::ex> rows(const JointEnds& ends) {
  const Vec2 u = world_axis(ends, ends.a.angle);
  return {dot({-u.y, u.x}, world_point(ends.b, ends.point_b) - world_point(ends.a, ends.point_a))};
}

std::vector<ForceUnknown> unknowns(const Joint& joint, bool, const std::string& on) {
  return {{"normal", spell_indexed("N", 0, joint.name), "N", "pin-slot force on " + on + " across the slot"}};
}

void force(JointSystem& joint, const JointEnds& ends) {
  const Vec2 u = world_axis(ends, ends.a.angle);
  joint.force = GiNaC::ex(joint.unknowns.at(0)) * Vec2{-u.y, u.x};
  joint.moment = 0;
}

Placement place(const JointEnds& ends, bool child_is_b, const TreeCoordinates& coordinates) {
  Placement child;
  child.angle = coordinates.angle;
  if (child_is_b) {
    const Vec2 pin = world_point(ends.a, ends.point_a) + coordinates.travel * world_axis(ends, ends.a.angle);
    child.position = pin - rotate(child.angle, ends.point_b);
  } else {
    const Vec2 on_slot = world_point(ends.b, ends.point_b) - coordinates.travel * world_axis(ends, child.angle);
    child.position = on_slot - rotate(child.angle, ends.point_a);
  }
  return child;
}

GiNaC::ex coordinate(const JointEnds& ends) {
  return dot(world_axis(ends, ends.a.angle), world_point(ends.b, ends.point_b) - world_point(ends.a, ends.point_a));
}

const OwnCoordinate kTravel{
    "s", {"m", "m/s", "m/s^2"}, {"position along slot ", "velocity along slot ", "acceleration along slot "}};

}  // namespace

extern const JointStages kPinSlotJoint{
    rows,  unknowns,           force,   true, place, &kTravel, coordinate, false, "m",
    "m/s", JointDrawing::slot, nullptr, "",   "",    true};

}  // namespace linkage::sym
