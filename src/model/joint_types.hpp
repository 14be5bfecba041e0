#pragma once
// The model-level stages of each joint type, as data the modules above read: the
// [[joint]] keys it takes and the coordinate it adds to the spanning tree. A joint type's
// equations, force, columns and drawing data are its file symbolic/joint_<type>.cpp;
// docs/joints.md lists the steps to add a type.
#include "model/mechanism.hpp"

namespace linkage {

/// How the body a tree joint carries moves relative to its parent: which coordinate the
/// joint adds to the spanning tree, and its joint model in the O(n) recursion.
enum class JointMotion {
  revolute,   // the child's own absolute angle theta (a point mass adds none)
  prismatic,  // the joint's own travel s along its axis; the child keeps its parent's angle
};

struct JointTypeInfo {
  JointMotion motion = JointMotion::revolute;
  const char* options = "";       // its own [[joint]] keys, for messages: "axis"
  bool torsional_spring = false;  // takes stiffness, damping, rest_angle
  bool axis = false;              // needs axis, a direction in the frame of bodies[0]
  bool keeps_angle = false;       // holds both angles equal: neither body may be a point mass
};

/// The registration of the joint types' model-level data: one exhaustive switch.
[[nodiscard]] const JointTypeInfo& joint_type_info(JointType type);

/// "pin", "slider": the TOML `type`.
[[nodiscard]] const char* joint_type_name(JointType type);

/// Whether the motion has a coordinate of the joint's own (keyed "JOINT.s" in [initial]).
[[nodiscard]] bool has_own_coordinate(JointMotion motion);

}  // namespace linkage
