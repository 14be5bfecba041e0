#pragma once
// The joint types: the enum and, beside it, each type's model-level stages as one row of
// data (kJointTypes) that the modules above read: its TOML `type`, the [[joint]] keys it
// takes and the coordinate it adds to the spanning tree. The model cannot see GiNaC, so a
// type's equations, force, columns and drawing are its file symbolic/joint_<type>.cpp,
// registered in symbolic/joints.cpp. docs/joints.md lists the steps to add a type.
#include <array>
#include <cstddef>
#include <string>

namespace linkage {

enum class JointType {
  pin,
  slider,
  weld,
  rolling,
  pin_slot,
  gear,
};

/// How the body a tree joint carries moves relative to its parent: which coordinate the
/// joint adds to the spanning tree, and its joint model in the O(n) recursion.
enum class JointMotion {
  revolute,   // the child's own absolute angle theta (a point mass adds none)
  prismatic,  // the joint's own travel s along its axis; the child keeps its parent's angle
  fixed,      // none: the child is placed rigidly on its parent (a weld)
  rolling,    // the child's own absolute angle theta, turning about the contact point
  slotted,    // the joint's own travel s along its axis, then the child's own angle theta (a point mass: s alone)
  loop,       // none: it never carries a body (the tree does not grow through it), it closes a loop
};

struct JointTypeInfo {
  JointType type = JointType::pin;  // the row's entry: rows are in the enum's order
  const char* name = "";            // the TOML `type`: "pin"
  JointMotion motion = JointMotion::revolute;
  const char* options = "";       // its own [[joint]] keys, for messages: "axis"
  bool torsional_spring = false;  // takes stiffness, damping, rest_angle
  bool axis = false;              // needs axis, a direction in the frame of bodies[0]
  bool keeps_angle = false;       // holds the bodies' relative angle: neither may be a point mass
  // What a [[driver]] on it prescribes, and its column ("torque": NAME.torque); "" when
  // it cannot be driven.
  const char* driven = "";         // "the relative angle th_b - th_a, rad"
  const char* driven_unit = "";    // its unit: "rad"
  const char* driver_column = "";  // "torque"
  int rows = 2;                    // its position rows, for the count of degrees of freedom
  bool angle = false;              // takes `angle`, the relative angle th_b - th_a it holds
  bool radius = false;             // takes radius (a rolling's: default its rolling body's disc radius)
  // Takes carrier, radii and internal, and no points: its points are where its bodies are
  // pinned to the carrier (a gear's mesh).
  bool mesh = false;
};

/// One row per JointType, in the enum's order (checked below; symbolic/joints.cpp checks
/// that no enum entry lacks its row).
inline constexpr std::array kJointTypes{
    JointTypeInfo{JointType::pin, "pin", JointMotion::revolute, "stiffness, damping, rest_angle", true, false, false,
                  "the relative angle th_b - th_a, rad", "rad", "torque"},
    JointTypeInfo{JointType::slider, "slider", JointMotion::prismatic, "axis", false, true, true, "the travel s, m",
                  "m", "force"},
    JointTypeInfo{JointType::weld, "weld", JointMotion::fixed, "angle", false, false, true, "", "", "", 3, true},
    JointTypeInfo{JointType::rolling, "rolling", JointMotion::rolling, "axis, radius", false, true, false, "", "", "",
                  2, false, true},
    JointTypeInfo{JointType::pin_slot, "pin-slot", JointMotion::slotted, "axis", false, true, false, "", "", "", 1},
    JointTypeInfo{JointType::gear, "gear", JointMotion::loop, "carrier, radii, internal", false, false, true, "", "",
                  "", 1, false, false, true},
};

static_assert(
    [] {
      for (std::size_t i = 0; i < kJointTypes.size(); ++i)
        if (kJointTypes[i].type != static_cast<JointType>(i)) return false;
      return true;
    }(),
    "kJointTypes: one row per JointType, in the enum's order");

/// The TOML `type` of each joint type, in the enum's order.
inline constexpr std::array<const char*, kJointTypes.size()> kJointTypeNames = [] {
  std::array<const char*, kJointTypes.size()> names{};
  for (std::size_t i = 0; i < kJointTypes.size(); ++i) names[i] = kJointTypes[i].name;
  return names;
}();

/// A joint type's row.
[[nodiscard]] constexpr const JointTypeInfo& joint_type_info(JointType type) {
  return kJointTypes.at(static_cast<std::size_t>(type));
}

/// "pin", "slider": the TOML `type`.
[[nodiscard]] constexpr const char* joint_type_name(JointType type) { return joint_type_info(type).name; }

/// The types whose row has `takes`, for messages: "pins", "sliders and rolling joints".
[[nodiscard]] std::string joint_types_with(bool JointTypeInfo::*takes);

/// Whether a [[driver]] may drive a joint of this type (its row names a driver column).
[[nodiscard]] constexpr bool drivable(JointType type) { return *joint_type_info(type).driver_column != '\0'; }

/// The drivable types, for messages: "pin or slider".
[[nodiscard]] std::string drivable_joint_types();

/// Whether the motion has a coordinate of the joint's own (keyed "JOINT.s" in [initial]).
[[nodiscard]] bool has_own_coordinate(JointMotion motion);

/// Whether a joint with the motion may carry a body in the spanning tree (all but `loop`).
[[nodiscard]] bool carries_body(JointMotion motion);

}  // namespace linkage
