#pragma once
// The joint types, one file each (joint_pin.cpp, joint_slider.cpp), answering the same
// questions: the position constraint rows, the force it carries as unknowns, and where
// it puts the body it reaches in the spanning tree.
#include <string>
#include <vector>

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
  Vec2 point_a, point_b;  // body frames
  Vec2 axis;              // slider: direction in the frame of a (any length)
};

/// The world position of a point of a placed body.
[[nodiscard]] Vec2 world_point(const Placement& body, const Vec2& local);

// --- pin: the two points coincide -------------------------------------------------
[[nodiscard]] std::vector<GiNaC::ex> pin_constraints(const JointEnds& ends);
/// The force b exerts on a: (Fx, Fy), two unknowns.
void pin_force(JointSystem& joint, const SymbolTable& table);
/// The child's placement; `child_angle` is its own theta (its generalized coordinate).
[[nodiscard]] Placement pin_place(const JointEnds& ends, bool child_is_b, const GiNaC::ex& child_angle);

// --- slider: equal angles, b's point on the line through a's point along the axis -----
[[nodiscard]] std::vector<GiNaC::ex> slider_constraints(const JointEnds& ends);
/// The force b exerts on a: N across the axis and a moment M, two unknowns.
void slider_force(JointSystem& joint, const JointEnds& ends, const SymbolTable& table);
/// The child's placement, `s` the slider coordinate along the unit axis.
[[nodiscard]] Placement slider_place(const JointEnds& ends, bool child_is_b, const GiNaC::ex& s);
/// The unit axis in the world.
[[nodiscard]] Vec2 slider_axis(const JointEnds& ends);

}  // namespace linkage::sym
