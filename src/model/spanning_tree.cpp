#include "model/spanning_tree.hpp"

#include <deque>
#include <stdexcept>

#include "model/joint_types.hpp"

namespace linkage {

const char* coordinate_kind_name(CoordinateKind kind) {
  switch (kind) {
    case CoordinateKind::x:
      return "x";
    case CoordinateKind::y:
      return "y";
    case CoordinateKind::theta:
      return "theta";
    case CoordinateKind::s:
      return "s";
  }
  return "?";
}

SpanningTree spanning_tree(const Mechanism& mechanism) {
  const auto n = mechanism.bodies.size();
  SpanningTree tree;
  tree.bodies.resize(n);
  std::vector<bool> reached(n, false);
  std::vector<bool> used(mechanism.joints.size(), false);

  // Breadth first from `start` (-1: the ground), joints in file order.
  auto grow = [&](int start) {
    std::deque<int> queue{start};
    while (!queue.empty()) {
      const int at = queue.front();
      queue.pop_front();
      for (std::size_t j = 0; j < mechanism.joints.size(); ++j) {
        if (used[j]) continue;
        const Joint& joint = mechanism.joints[j];
        if (!carries_body(joint_type_info(joint.type).motion)) continue;  // it closes a loop
        const int a = mechanism.body_index(joint.bodies[0]);
        const int b = mechanism.body_index(joint.bodies[1]);
        int other = -2;
        if (a == at) other = b;
        if (b == at) other = a;
        if (other == -2 || other == -1 || reached[static_cast<std::size_t>(other)]) continue;
        used[j] = true;
        reached[static_cast<std::size_t>(other)] = true;
        tree.bodies[static_cast<std::size_t>(other)] = {at, static_cast<int>(j), false};
        tree.order.push_back(other);
        tree.tree_joints.push_back(static_cast<int>(j));
        queue.push_back(other);
      }
    }
  };
  grow(-1);
  for (std::size_t i = 0; i < n; ++i) {
    if (reached[i]) continue;
    reached[i] = true;
    tree.bodies[i] = {-1, -1, true};
    tree.order.push_back(static_cast<int>(i));
    grow(static_cast<int>(i));
  }
  for (std::size_t j = 0; j < mechanism.joints.size(); ++j)
    if (!used[j]) tree.loop_joints.push_back(static_cast<int>(j));

  for (std::size_t i = 0; i < n; ++i) {
    const Body& body = mechanism.bodies[i];
    const TreeBody& node = tree.bodies[i];
    const int index = static_cast<int>(i);
    // A point mass has no angle: it adds no theta.
    const bool rotates = body_rotates(body);
    if (node.floating) {
      for (CoordinateKind kind : {CoordinateKind::x, CoordinateKind::y, CoordinateKind::theta})
        if (kind != CoordinateKind::theta || rotates)
          tree.coordinates.push_back({kind, index, -1, body.name + "." + coordinate_kind_name(kind)});
      continue;
    }
    const Joint& joint = mechanism.joints[static_cast<std::size_t>(node.joint)];
    switch (joint_type_info(joint.type).motion) {
      case JointMotion::revolute:
      case JointMotion::rolling:
        if (rotates) tree.coordinates.push_back({CoordinateKind::theta, index, -1, body.name + ".theta"});
        break;
      case JointMotion::prismatic:
        tree.coordinates.push_back({CoordinateKind::s, index, node.joint, joint.name + ".s"});
        break;
      case JointMotion::fixed:  // placed by its parent: no coordinate
        break;
      case JointMotion::slotted:  // the travel, then the child's own angle
        tree.coordinates.push_back({CoordinateKind::s, index, node.joint, joint.name + ".s"});
        if (rotates) tree.coordinates.push_back({CoordinateKind::theta, index, -1, body.name + ".theta"});
        break;
      case JointMotion::loop:  // never in the tree (carries_body)
        throw std::logic_error("spanning_tree: a loop-only joint carries a body");
    }
  }
  return tree;
}

bool body_rotates(const Body& body) { return body.shape != Shape::point || body.inertia.has_value(); }

int degrees_of_freedom(const Mechanism& mechanism) {
  int dof = 0;
  for (const Body& body : mechanism.bodies) dof += body_rotates(body) ? 3 : 2;
  for (const Joint& joint : mechanism.joints) dof -= joint_type_info(joint.type).rows;
  return dof - static_cast<int>(mechanism.drivers.size());
}

}  // namespace linkage
