// The spanning tree and generalized coordinates of the shipped mechanisms (the rule in
// mechanisms/README.md): breadth first from the ground, joints in file order.
#include "model/spanning_tree.hpp"

#include <gtest/gtest.h>

#include "model/mechanism_toml.hpp"

namespace linkage {
namespace {

std::vector<std::string> coordinate_keys(const SpanningTree& tree) {
  std::vector<std::string> keys;
  for (const Coordinate& c : tree.coordinates) keys.push_back(c.key);
  return keys;
}

std::vector<std::string> loop_names(const Mechanism& m, const SpanningTree& tree) {
  std::vector<std::string> names;
  for (int j : tree.loop_joints) names.push_back(m.joints[static_cast<std::size_t>(j)].name);
  return names;
}

TEST(SpanningTree, TheHomeworkHasAFloatingBlockAndNoLoop) {
  const Mechanism m = load_mechanism("two-blocks");
  const SpanningTree tree = spanning_tree(m);
  EXPECT_EQ(coordinate_keys(tree), (std::vector<std::string>{"1.x", "1.y", "1.theta", "2.theta"}));
  EXPECT_TRUE(tree.loop_joints.empty());
  EXPECT_TRUE(tree.bodies[0].floating);
  EXPECT_EQ(tree.bodies[0].joint, -1);
  EXPECT_FALSE(tree.bodies[1].floating);
  EXPECT_EQ(tree.bodies[1].parent, 0);
  EXPECT_EQ(tree.bodies[1].joint, 0);
  EXPECT_EQ(tree.order, (std::vector<int>{0, 1}));
  EXPECT_EQ(degrees_of_freedom(m), 4);
}

TEST(SpanningTree, TheDoublePendulumHangsFromTheGround) {
  const Mechanism m = load_mechanism("double-pendulum");
  const SpanningTree tree = spanning_tree(m);
  EXPECT_EQ(coordinate_keys(tree), (std::vector<std::string>{"1.theta", "2.theta"}));
  EXPECT_TRUE(tree.loop_joints.empty());
  EXPECT_EQ(tree.bodies[0].parent, -1);
  EXPECT_FALSE(tree.bodies[0].floating);
  EXPECT_EQ(tree.bodies[1].parent, 0);
  EXPECT_EQ(tree.tree_joints, (std::vector<int>{0, 1}));
}

TEST(SpanningTree, TheFourBarHasExactlyOneLoopJoint) {
  const Mechanism m = load_mechanism("four-bar");
  const SpanningTree tree = spanning_tree(m);
  EXPECT_EQ(coordinate_keys(tree), (std::vector<std::string>{"2.theta", "3.theta", "4.theta"}));
  EXPECT_EQ(loop_names(m, tree), std::vector<std::string>{"B"});
  // Both ground pins first (breadth first), then the coupler through A.
  EXPECT_EQ(tree.order, (std::vector<int>{0, 2, 1}));
  EXPECT_EQ(degrees_of_freedom(m), 1);
}

TEST(SpanningTree, TheSliderCrankPistonHasTheSliderCoordinate) {
  const Mechanism m = load_mechanism("slider-crank");
  const SpanningTree tree = spanning_tree(m);
  EXPECT_EQ(coordinate_keys(tree), (std::vector<std::string>{"2.theta", "3.theta", "S.s"}));
  ASSERT_EQ(tree.coordinates.size(), 3u);
  EXPECT_EQ(tree.coordinates[2].kind, CoordinateKind::s);
  EXPECT_EQ(tree.coordinates[2].body, 2);
  EXPECT_EQ(tree.coordinates[2].joint, 2);
  EXPECT_EQ(loop_names(m, tree), std::vector<std::string>{"B"});
}

TEST(SpanningTree, TheSpringPendulumIsOneFloatingBody) {
  const SpanningTree tree = spanning_tree(load_mechanism("spring-pendulum"));
  EXPECT_EQ(coordinate_keys(tree), (std::vector<std::string>{"1.x", "1.y", "1.theta"}));
  EXPECT_TRUE(tree.bodies[0].floating);
}

// A body the ground does not reach starts its own tree, the first such in file order,
// and what it carries hangs from it; the ground's tree comes first.
TEST(SpanningTree, AFloatingBodyNotReachedFromTheGround) {
  const std::string text = R"(
[ground]
points = { O = [0, 0] }
[[body]]
name = "free"
shape = "disc"
mass = 1
radius = 0.1
points = { C = [0, 0] }
[[body]]
name = "arm"
shape = "rod"
mass = 1
length = 0.2
points = { A = [-0.1, 0] }
[[body]]
name = "pendulum"
shape = "rod"
mass = 1
length = 0.2
points = { O = [-0.1, 0] }
[[joint]]
name = "J"
type = "pin"
bodies = ["free", "arm"]
points = ["C", "A"]
[[joint]]
name = "O"
type = "pin"
bodies = ["ground", "pendulum"]
points = ["O", "O"]
[initial]
free = { x = 0, y = 1, theta = 0 }
arm = { theta = 0.5 }
pendulum = { theta = -1 }
)";
  const Mechanism m = read_mechanism(text, "free.toml");
  const SpanningTree tree = spanning_tree(m);
  EXPECT_EQ(coordinate_keys(tree),
            (std::vector<std::string>{"free.x", "free.y", "free.theta", "arm.theta", "pendulum.theta"}));
  EXPECT_EQ(tree.order, (std::vector<int>{2, 0, 1}));
  EXPECT_TRUE(tree.bodies[0].floating);
  EXPECT_EQ(tree.bodies[1].parent, 0);
  EXPECT_FALSE(tree.bodies[2].floating);
  EXPECT_TRUE(tree.loop_joints.empty());
  EXPECT_EQ(degrees_of_freedom(m), 5);
}

// A point mass without an inertia has no angle: a floating one keeps x and y only.
TEST(SpanningTree, AFloatingPointMassHasNoAngle) {
  const Mechanism m = read_mechanism(
      "[[body]]\nname = \"p\"\nshape = \"point\"\nmass = 1\n[initial]\np = { x = 0, y = 1 }\n", "p.toml");
  EXPECT_EQ(coordinate_keys(spanning_tree(m)), (std::vector<std::string>{"p.x", "p.y"}));
  EXPECT_EQ(degrees_of_freedom(m), 2);
}

}  // namespace
}  // namespace linkage
