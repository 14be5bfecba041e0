#pragma once
// The spanning tree of a mechanism and its generalized coordinates (the contract in
// mechanisms/README.md): grown breadth first from the ground, taking joints in file
// order; a body the ground does not reach starts its own tree as a floating base (x, y,
// theta; a point mass has no theta), the first such body in file order. A body reached through a pin or a rolling joint
// adds its absolute angle theta, one reached through a slider adds the slider's s. A joint whose motion is `loop`
// (a gear's mesh) never carries a body. A joint outside the tree closes a loop.
#include <string>
#include <vector>

#include "model/mechanism.hpp"

namespace linkage {

enum class CoordinateKind { x, y, theta, s };

/// One generalized coordinate: "1.x", "2.theta", "slider.s".
struct Coordinate {
  CoordinateKind kind = CoordinateKind::theta;
  int body = -1;    // the body it moves (index into Mechanism::bodies)
  int joint = -1;   // the slider joint for kind s, else -1
  std::string key;  // "1.theta" (body or joint name, dot, kind)
};

struct TreeBody {
  int parent = -1;        // parent body index, -1 for the ground or none (floating base)
  int joint = -1;         // the joint to the parent, -1 for a floating base
  bool floating = false;  // a base with its own x, y, theta
};

struct SpanningTree {
  std::vector<TreeBody> bodies;         // one per Mechanism::bodies, same order
  std::vector<int> order;               // body indices in the order they were reached
  std::vector<int> tree_joints;         // joint indices in the tree, in the order used
  std::vector<int> loop_joints;         // joint indices that close loops, file order
  std::vector<Coordinate> coordinates;  // generalized coordinates, body file order
};

/// Builds the tree of a mechanism whose names are consistent (every joint names two
/// existing, different bodies or the ground).
[[nodiscard]] SpanningTree spanning_tree(const Mechanism& mechanism);

/// "x", "y", "theta", "s".
[[nodiscard]] const char* coordinate_kind_name(CoordinateKind kind);

/// Whether a body has an angle: every shape but a point mass without an inertia.
[[nodiscard]] bool body_rotates(const Body& body);

/// Degrees of freedom when no constraint is redundant: 3 per body (2 per point mass),
/// minus each joint's rows (its type's `rows`), minus 1 per driver.
[[nodiscard]] int degrees_of_freedom(const Mechanism& mechanism);

}  // namespace linkage
