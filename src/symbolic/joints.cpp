#include "symbolic/joints.hpp"

#include "core/error.hpp"
#include "model/joint_types.hpp"

namespace linkage::sym {

Vec2 world_point(const Placement& body, const Vec2& local) { return body.position + rotate(body.angle, local); }

// Each type's stages: its file's one definition.
extern const JointStages kPinJoint;
extern const JointStages kSliderJoint;
extern const JointStages kWeldJoint;
extern const JointStages kRollingJoint;
extern const JointStages kPinSlotJoint;
extern const JointStages kGearJoint;

namespace {

// The registration: one case per joint type. -Wswitch-enum fails the build when a type
// has none; the static_assert below, when a type has no row in kJointTypes.
constexpr const JointStages* registered(JointType type) {
  switch (type) {
    case JointType::pin:
      return &kPinJoint;
    case JointType::slider:
      return &kSliderJoint;
    case JointType::weld:
      return &kWeldJoint;
    case JointType::rolling:
      return &kRollingJoint;
    case JointType::pin_slot:
      return &kPinSlotJoint;
    case JointType::gear:
      return &kGearJoint;
  }
  return nullptr;
}

// Enum entries are numbered 0, 1, ...: the first number past kJointTypes' rows is no
// entry of the enum, unless one lacks its row.
static_assert(registered(static_cast<JointType>(kJointTypes.size())) == nullptr,
              "a JointType has no row in kJointTypes (model/joint_types.hpp)");

}  // namespace

const JointStages& joint_stages(JointType type) {
  const JointStages* stages = registered(type);
  if (stages == nullptr) throw std::logic_error("joint type out of range");
  return *stages;
}

// An axis that is zero whatever the parameters ("r-r") is refused here, before its unit
// vector divides by zero (validate.cpp refuses one that is zero at the values).
Vec2 joint_axis(const System& system, const Joint& joint) {
  if (!joint_type_info(joint.type).axis) return {};
  const Vec2 axis{system.quantity(joint.axis->x, false), system.quantity(joint.axis->y, false)};
  if ((axis.x * axis.x + axis.y * axis.y).is_zero())
    throw Error::input(where(joint.axis->x.pos) + "the axis of " + joint_type_name(joint.type) + " " + joint.name +
                       " (\"" + joint.axis->x.text + "\", \"" + joint.axis->y.text +
                       "\") is zero for any parameter values; valid: a direction of non-zero length");
  return axis;
}

GiNaC::ex joint_angle(const System& system, const Joint& joint) {
  if (!joint_type_info(joint.type).angle || !joint.angle) return 0;
  return system.quantity(*joint.angle, false);
}

std::array<GiNaC::ex, 2> joint_radii(const System& system, const Joint& joint) {
  if (!joint_type_info(joint.type).mesh || !joint.radii) return {};
  return {system.quantity((*joint.radii)[0], false), system.quantity((*joint.radii)[1], false)};
}

GiNaC::ex joint_radius(const System& system, const Joint& joint) {
  if (!joint_type_info(joint.type).radius || !joint.radius) return 0;
  return system.quantity(*joint.radius, false);
}

std::array<Vec2, 2> force_points(const System& system, int joint) {
  const Mechanism& m = system.mechanism();
  const Joint& j = m.joints.at(static_cast<std::size_t>(joint));
  const JointStages& stages = joint_stages(j.type);
  const Vec2 own_a = system.point_position(m.body_index(j.bodies[0]), j.points[0]);
  const Vec2 own_b = system.point_position(m.body_index(j.bodies[1]), j.points[1]);
  const Vec2 at_a = stages.force_at_point_b ? own_b : own_a;
  return {at_a, stages.opposite_at_point_a ? at_a : own_b};
}

JointEnds maximal_ends(const System& system, int joint) {
  const Joint& j = system.mechanism().joints.at(static_cast<std::size_t>(joint));
  auto place = [&](const std::string& name, const std::string& point, Placement& placement, Vec2& local) {
    const int body = system.mechanism().body_index(name);
    if (body < 0) {
      placement = {};
      local = system.point_position(-1, point);
      return;
    }
    const BodySystem& b = system.bodies()[static_cast<std::size_t>(body)];
    placement = {{b.x.q, b.y.q}, b.rotates ? GiNaC::ex(b.theta.q) : GiNaC::ex(0)};
    local = b.points.at(point);
  };
  JointEnds ends;
  place(j.bodies[0], j.points[0], ends.a, ends.point_a);
  place(j.bodies[1], j.points[1], ends.b, ends.point_b);
  ends.axis = joint_axis(system, j);
  ends.angle = joint_angle(system, j);
  ends.radius = joint_radius(system, j);
  ends.radii = joint_radii(system, j);
  ends.mesh = j.internal ? -1 : 1;
  ends.constant = system.joint_constant(joint);
  if (const int carrier = system.mechanism().body_index(j.carrier); carrier >= 0) {
    const BodySystem& c = system.bodies()[static_cast<std::size_t>(carrier)];
    ends.carrier = {{c.x.q, c.y.q}, c.rotates ? GiNaC::ex(c.theta.q) : GiNaC::ex(0)};
  }
  return ends;
}

}  // namespace linkage::sym
