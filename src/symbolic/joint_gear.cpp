// Gear joint: two gears in mesh, a (bodies[0]) and b (bodies[1]), each pinned to the same
// carrier c (a body or the ground) at its centre C_a, C_b; pitch radii r1, r2; s = +1 for
// an external mesh, -1 for an internal one (a ring gear).
//   rows:   r1 (th_a - th_c) + s r2 (th_b - th_c) - c_G = 0, c_G the rest of the row at
//           the initial state (the mesh keeps its initial phase); angles only, the pins
//           hold the centres r1 + s r2 apart
//   force:  F t, the tooth force b exerts on a at the pitch point P = C_a + r1 e, e = (C_b -
//           C_a) / (r1 + s r2) the unit from C_a to P, t = k x e the common tangent; as
//           acting at C_a, with the moment r1 F; the opposite wrench on b acts there too
//           (about C_b the moment s r2 F), so each pin's force includes the tooth force
//   tree:   none: a mesh never carries a body (JointMotion::loop), it closes a loop
#include <stdexcept>

#include "symbolic/joints.hpp"

namespace linkage::sym {
namespace {

std::vector<GiNaC::ex> rows(const JointEnds& ends) {
  const GiNaC::ex& carrier = ends.carrier.angle;
  return {ends.radii[0] * (ends.a.angle - carrier) + ends.mesh * ends.radii[1] * (ends.b.angle - carrier) -
          ends.constant};
}

std::vector<ForceUnknown> unknowns(const Joint& joint, bool, const std::string& on) {
  return {{"force", spell_indexed("F", 0, joint.name), "N",
           "tooth force on " + on + " along the common tangent at the pitch point"}};
}

void force(JointSystem& joint, const JointEnds& ends) {
  const Vec2 d = world_point(ends.b, ends.point_b) - world_point(ends.a, ends.point_a);
  const GiNaC::ex apart = ends.radii[0] + ends.mesh * ends.radii[1];
  const Vec2 tangent{-d.y / apart, d.x / apart};  // k x e
  const GiNaC::ex F = joint.unknowns.at(0);
  joint.force = F * tangent;
  joint.moment = ends.radii[0] * F;
}

Placement place(const JointEnds&, bool, const TreeCoordinates&) {
  throw std::logic_error("a gear's mesh carries no body in the tree");
}

GiNaC::ex no_coordinate(const JointEnds&) { return 0; }

}  // namespace

extern const JointStages kGearJoint{
    rows,  unknowns,           force,         false, place, nullptr, no_coordinate, false, "m",
    "m/s", JointDrawing::gear, no_coordinate, "",    "",    true,    true,          "c",   "m"};

}  // namespace linkage::sym
