#pragma once
// The joint types, one file each (joint_pin.cpp, joint_slider.cpp, joint_pin_slot.cpp, ...), every one filling the
// same stages (JointStages), registered in joints.cpp (a declaration and a case each):
//   rows     its position constraint rows Phi = 0 in its bodies' placements; the velocity
//            and acceleration rows are their time derivatives (System::time_derivative),
//            never typed by hand;
//   force    the unknowns naming the force bodies[1] exerts on bodies[0], that force and
//            its moment in them, and the point of bodies[0] it acts at;
//   tree     where it puts the body it carries, from that body's angle (revolute) or its
//            own coordinate (prismatic: the symbol, units and value of that coordinate);
//   columns  what `simulate` writes for it besides force_x and force_y;
//   drawing  how the scene draws it;
//   driver   what a [[driver]] on it prescribes.
// The model-level stages (its [[joint]] keys, the coordinate it adds to the tree, which
// the O(n) recursion reads) are its row in model/joint_types.hpp, beside its enum entry.
// docs/joints.md: how to add a joint type.
#include <array>
#include <string>
#include <vector>

#include "symbolic/spelling.hpp"
#include "symbolic/system.hpp"

namespace linkage::sym {

/// A body's placement: centre of mass and angle (0 for a point mass... as its parent's).
struct Placement {
  Vec2 position;
  GiNaC::ex angle = 0;
};

/// What a joint sees of its two bodies: their placements (maximal symbols, or expressions
/// in generalized coordinates) and its points in each body's frame.
struct JointEnds {
  Placement a, b;
  Vec2 point_a, point_b;             // body frames
  Vec2 axis;                         // slider, rolling: direction in the frame of a (any length)
  GiNaC::ex radius = 0;              // rolling: the rolling radius
  GiNaC::ex angle = 0;               // weld: the relative angle th_b - th_a it holds
  Placement carrier;                 // gear: the body both gears are pinned to (zero: the ground)
  std::array<GiNaC::ex, 2> radii{};  // gear: the pitch radii of bodies[0] and bodies[1]
  GiNaC::ex mesh = 1;                // gear: +1 an external mesh, -1 an internal one
  GiNaC::ex constant = 0;            // the constant its row holds, set by the initial state (a gear's c_G)
};

/// What the spanning tree gives a tree joint to place the body it carries with: the
/// child's own angle (revolute, rolling, slotted; 0 for a point mass) and the joint's own
/// travel (prismatic, slotted: its `own` coordinate; 0 without one).
struct TreeCoordinates {
  GiNaC::ex angle = 0;
  GiNaC::ex travel = 0;
};

/// The world position of a point of a placed body.
[[nodiscard]] Vec2 world_point(const Placement& body, const Vec2& local);

/// A force unknown: its key after "JOINT." ("force_x"), spelling, unit and meaning.
struct ForceUnknown {
  std::string key;
  Spelling spelling;
  std::string unit;
  std::string meaning;
};

/// A joint's own generalized coordinate (a slider's s): its base letter and, for q, q'
/// and q'', the unit and the meaning (followed by the joint's name).
struct OwnCoordinate {
  const char* base = "s";
  std::array<const char*, 3> units{};
  std::array<const char*, 3> meanings{};
};

/// How the scene draws a joint of the type (scene/mechanism_scene.cpp switches on it).
enum class JointDrawing {
  marker,   // a pin's circle at its point on bodies[0]
  rolling,  // the line as a hatched surface of bodies[0], the contact point on bodies[1]'s circle
  rail,     // a rail along the axis through bodies[0]'s point over the travel, a guide at bodies[1]'s
  bracket,  // an L-shaped plate over the point, a leg along each body
  slot,     // a channel of bodies[0] along the axis over the travel, the pin at bodies[1]'s point
  gear,     // each body's pitch circle about its point, with teeth marks that turn with it
};

struct JointStages {
  /// rows: Phi(ends) = 0.
  std::vector<GiNaC::ex> (*rows)(const JointEnds& ends);
  /// force: its unknowns, in the order of JointSystem::unknowns; `single` when it is the
  /// mechanism's only joint (the homework's Fx, Fy), `on` names bodies[0].
  std::vector<ForceUnknown> (*unknowns)(const Joint& joint, bool single, const std::string& on);
  /// force: JointSystem::force and moment from its unknowns.
  void (*force)(JointSystem& joint, const JointEnds& ends);
  /// force: whether the force on bodies[0] acts at bodies[1]'s point (else at its own).
  bool force_at_point_b;
  /// tree: the placement of the child (bodies[1] when `child_is_b`) from its parent's and
  /// the tree's coordinates: the child's own angle (revolute) or the joint's travel (prismatic).
  Placement (*place)(const JointEnds& ends, bool child_is_b, const TreeCoordinates& coordinates);
  /// tree: the joint's own coordinate, null when it adds none
  /// (model/joint_types.hpp: has_own_coordinate).
  const OwnCoordinate* own;
  /// tree: the value of that coordinate in the ends' placements (0 without one).
  GiNaC::ex (*coordinate)(const JointEnds& ends);
  /// columns: whether `JOINT.moment` is written; the units of `JOINT.constraint_error` and
  /// of `JOINT.constraint_velocity_error`.
  bool moment_column;
  const char* constraint_unit;
  const char* constraint_rate_unit;
  /// drawing: how the scene draws it.
  JointDrawing drawing;
  /// driver: what a [[driver]] on it prescribes, in the ends' placements (a pin: the
  /// relative angle th_b - th_a; a slider: its travel, the `coordinate` above); null
  /// when the type is not drivable (its row names no driver column).
  GiNaC::ex (*driven)(const JointEnds& ends);
  /// driver: its multiplier's letter and unit ("tau", "N m"); the column is the row's
  /// `driver_column` (model/joint_types.hpp).
  const char* driver_letter;
  const char* driver_unit;
  /// columns: whether each force unknown is written as `JOINT.<key>` too (a rolling
  /// joint's normal and friction).
  bool unknown_columns = false;
  /// force: whether the opposite force and moment on bodies[1] act at the point where they
  /// act on bodies[0] (a gear's mesh: one wrench at gear 1's centre), not at its own point.
  bool opposite_at_point_a = false;
  /// rows: the letter of the constant its row holds ("c": c_JOINT, in `constant_unit`),
  /// whose value is the rest of its row at the initial state (a gear's mesh keeps its
  /// initial phase); null when it holds none. JointEnds::constant is its symbol.
  const char* constant_letter = nullptr;
  const char* constant_unit = "";
};

/// Every joint type's stages, from the registration in joints.cpp.
[[nodiscard]] const JointStages& joint_stages(JointType type);

/// Where the joint's force and moment act, world frame, maximal coordinates: [0] on
/// bodies[0] (`force_at_point_b`), [1] the opposite on bodies[1] (`opposite_at_point_a`).
/// Newton-Euler, Lagrange's generalized forces and the ground reaction all read these.
[[nodiscard]] std::array<Vec2, 2> force_points(const System& system, int joint);

/// The joint's ends in maximal coordinates (the ground's placement is zero), its axis
/// checked: one that is zero whatever the parameters is an input error.
[[nodiscard]] JointEnds maximal_ends(const System& system, int joint);

/// The joint's axis in the frame of bodies[0] as parsed (zero when its type takes none).
[[nodiscard]] Vec2 joint_axis(const System& system, const Joint& joint);

/// The relative angle a weld holds, as parsed (0 when absent or its type takes none).
[[nodiscard]] GiNaC::ex joint_angle(const System& system, const Joint& joint);

/// A mesh's pitch radii as parsed (zero when its type takes none).
[[nodiscard]] std::array<GiNaC::ex, 2> joint_radii(const System& system, const Joint& joint);

/// The joint's radius as parsed (zero when its type takes none).
[[nodiscard]] GiNaC::ex joint_radius(const System& system, const Joint& joint);

}  // namespace linkage::sym
