// Rolling joint: a circle of b (centre C, radius R) rolls without slipping on a straight
// line of a through O, axis u (unit, in the frame of a), the circle on the side of
// n = k x u.
//   rows:   n . (C - O) - R = 0,   u . (C - O) + R (th_b - th_a) = 0 (C over O at th_b = th_a)
//   force:  F = N n + f u, the force b exerts on a at the contact point K = C - R n; as
//           acting at C, with the moment (K - C) x F = -R n x F = R f on a; the opposite on b
//   tree:   rolling: the child keeps its own angle; C = O + R n - R (th_b - th_a) u
#include "symbolic/joints.hpp"

namespace linkage::sym {
namespace {

/// The unit axis u and the normal n in the world. sin^2 + cos^2 = 1 in its length, so an
/// incline's axis (cos(alpha), -sin(alpha)) prints as it is, not over sqrt(sin^2 + cos^2).
std::array<Vec2, 2> frame(const JointEnds& ends, const GiNaC::ex& angle_a) {
  const GiNaC::ex w = GiNaC::wild();
  const GiNaC::ex squared = GiNaC::expand(
      GiNaC::expand(ends.axis.x * ends.axis.x + ends.axis.y * ends.axis.y)
          .subs(GiNaC::pow(GiNaC::sin(w), 2) == 1 - GiNaC::pow(GiNaC::cos(w), 2), GiNaC::subs_options::algebraic));
  const GiNaC::ex length = GiNaC::sqrt(squared);
  const Vec2 u = rotate(angle_a, {ends.axis.x / length, ends.axis.y / length});
  return {u, Vec2{-u.y, u.x}};
}

GiNaC::ex dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }

std::vector<GiNaC::ex> rows(const JointEnds& ends) {
  const auto [u, n] = frame(ends, ends.a.angle);
  const Vec2 d = world_point(ends.b, ends.point_b) - world_point(ends.a, ends.point_a);
  return {dot(n, d) - ends.radius, dot(u, d) + ends.radius * (ends.b.angle - ends.a.angle)};
}

std::vector<ForceUnknown> unknowns(const Joint& joint, bool, const std::string& on) {
  return {
      {"normal", spell_indexed("N", 0, joint.name), "N", "rolling contact force on " + on + " along the normal n"},
      {"friction", spell_indexed("f", 0, joint.name), "N", "rolling friction force on " + on + " along the axis u"}};
}

void force(JointSystem& joint, const JointEnds& ends) {
  const auto [u, n] = frame(ends, ends.a.angle);
  const GiNaC::ex normal = joint.unknowns.at(0), friction = joint.unknowns.at(1);
  joint.force = normal * n + friction * u;
  joint.moment = ends.radius * friction;
}

Placement place(const JointEnds& ends, bool child_is_b, const TreeCoordinates& coordinates) {
  const GiNaC::ex& child_angle = coordinates.angle;
  Placement child;
  child.angle = child_angle;
  if (child_is_b) {
    const auto [u, n] = frame(ends, ends.a.angle);
    const Vec2 centre =
        world_point(ends.a, ends.point_a) + ends.radius * n - ends.radius * (child_angle - ends.a.angle) * u;
    child.position = centre - rotate(child_angle, ends.point_b);
  } else {
    const auto [u, n] = frame(ends, child_angle);
    const Vec2 on_line =
        world_point(ends.b, ends.point_b) - ends.radius * n + ends.radius * (ends.b.angle - child_angle) * u;
    child.position = on_line - rotate(child_angle, ends.point_a);
  }
  return child;
}

GiNaC::ex no_coordinate(const JointEnds&) { return 0; }

}  // namespace

extern const JointStages kRollingJoint{
    rows,          unknowns, force, true, place, nullptr, no_coordinate, false, "m", "m/s", JointDrawing::rolling,
    no_coordinate, "",       "",    true};

}  // namespace linkage::sym
