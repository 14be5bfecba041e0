#include "scene/scene_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model/kinematics.hpp"
#include "scene/scene_test_support.hpp"

namespace linkage {
namespace {

const Arrow* find_arrow(const DrawList& list, ArrowKind kind, std::size_t nth = 0) {
  for (const Arrow& a : list.arrows)
    if (a.kind == kind && nth-- == 0) return &a;
  return nullptr;
}

TEST(SceneBuilder, BlocksHaveTheirTrueSizeAndTurn) {
  const Params p;
  const State s;
  const Motion motion = test::still_motion(p, s, true);
  DrawList list;
  build_scene(p, scene_options_for(p, motion, ElementSet::defaults(), false), motion, 0, list);
  ASSERT_EQ(list.blocks.size(), 2u);
  const BodyState b = body_state(p, s);
  for (const BlockShape& block : list.blocks) {
    const double theta = block.index == 1 ? b.theta1 : b.theta2;
    const Vec2 centre = block.index == 1 ? Vec2(b.x1, b.y1) : Vec2(b.x2, b.y2);
    EXPECT_NEAR((block.corners[0] - block.corners[1]).norm(), p.w, 1e-15);
    EXPECT_NEAR((block.corners[1] - block.corners[2]).norm(), p.L, 1e-15);
    const Vec2 along = block.corners[0] - block.corners[3];
    EXPECT_NEAR(std::atan2(along.y(), along.x()), theta, 1e-14);
    EXPECT_NEAR(((block.corners[0] + block.corners[2]) / 2 - centre).norm(), 0, 1e-15);
  }
}

TEST(SceneBuilder, PinAndForcesAtP) {
  const Params p;
  const State s;
  const Motion motion = test::still_motion(p, s, true);
  const SceneOptions options = scene_options_for(p, motion, ElementSet::defaults(), false);
  DrawList list;
  build_scene(p, options, motion, 0, list);
  const Vec2 pin = derive(p, s).pin;
  bool found_pin = false;
  for (const Marker& m : list.markers)
    if (m.kind == MarkerKind::pin) {
      found_pin = true;
      EXPECT_NEAR((m.at - pin).norm(), 0, 1e-15);
      EXPECT_EQ(m.tag, "P");
    }
  EXPECT_TRUE(found_pin);

  // F on block 1 at P; -F on block 2 at P; the spec example's pin force is (1.7575e-3, 2.747e-4) N.
  const Vec2 force = test::pin_force_at(p, s);
  EXPECT_NEAR(force.x(), 0.0017574979797191752, 1e-12);
  const double metres_per_newton = options.arrow_scales[0].metres_per_unit;
  const Arrow* on1 = find_arrow(list, ArrowKind::pin_force, 0);
  const Arrow* on2 = find_arrow(list, ArrowKind::pin_force, 1);
  ASSERT_NE(on1, nullptr);
  ASSERT_NE(on2, nullptr);
  EXPECT_NEAR((on1->tail - pin).norm(), 0, 1e-15);
  EXPECT_NEAR((on2->tail - pin).norm(), 0, 1e-12);
  EXPECT_NEAR((on1->vector - force * metres_per_newton).norm(), 0, 1e-15);
  EXPECT_NEAR((on2->vector + force * metres_per_newton).norm(), 0, 1e-15);
  // The only sample has the largest force, so its arrow is 2/3 .. 1 of the longest.
  EXPECT_LE(on1->vector.norm(), default_longest_arrow(p) * (1 + 1e-12));
  EXPECT_GE(on1->vector.norm(), default_longest_arrow(p) / 1.5);
}

TEST(SceneBuilder, GravityPointsDownFromEachCentreOfMass) {
  const Params p;
  const State s;
  const Motion motion = test::still_motion(p, s, false);
  DrawList list;
  build_scene(p, scene_options_for(p, motion, ElementSet::defaults(), false), motion, 0, list);
  const BodyState b = body_state(p, s);
  const Arrow* g1 = find_arrow(list, ArrowKind::gravity, 0);
  const Arrow* g2 = find_arrow(list, ArrowKind::gravity, 1);
  ASSERT_NE(g1, nullptr);
  ASSERT_NE(g2, nullptr);
  EXPECT_EQ(g1->tail, Vec2(b.x1, b.y1));
  EXPECT_EQ(g2->tail, Vec2(b.x2, b.y2));
  EXPECT_EQ(g1->vector.x(), 0.0);
  EXPECT_LT(g1->vector.y(), 0.0);
  // Without a sampled pin force there are no pin-force arrows.
  EXPECT_EQ(find_arrow(list, ArrowKind::pin_force), nullptr);
}

TEST(SceneBuilder, HiddenElementsAreNotBuilt) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 10, 0.1, true);
  ElementSet shown = ElementSet::none();
  shown.show(Element::blocks);
  DrawList list;
  build_scene(p, scene_options_for(p, motion, shown, false), motion, 9, list);
  EXPECT_EQ(list.blocks.size(), 2u);
  EXPECT_TRUE(list.arrows.empty());
  EXPECT_TRUE(list.markers.empty());
  EXPECT_TRUE(list.trail.empty());
  EXPECT_TRUE(list.labels.empty());
}

TEST(SceneBuilder, TrailFadesOverItsWindowAndEndsAtP) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 121, 1.0 / 30, false);
  ElementSet shown = ElementSet::none();
  shown.show(Element::trail);
  SceneOptions options = scene_options_for(p, motion, shown, false);
  options.trail_seconds = 2.0;
  DrawList list;
  build_scene(p, options, motion, 120, list);  // t = 4 s: the last 2 s are 61 samples
  ASSERT_EQ(list.trail.size(), 61u);
  const BodyState& now = motion.samples[120].state;
  EXPECT_NEAR((list.trail.back().at - pin_position(p, now.x1, now.y1, now.theta1)).norm(), 0, 1e-15);
  EXPECT_DOUBLE_EQ(list.trail.back().fade, 1.0);
  EXPECT_NEAR(list.trail.front().fade, 0.0, 1e-12);
  for (std::size_t j = 1; j < list.trail.size(); ++j) EXPECT_GT(list.trail[j].fade, list.trail[j - 1].fade);
}

TEST(SceneBuilder, FollowingGTheTrailStaysInTheWorldAndVelocitiesAreRelative) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 31, 1.0 / 30, false);
  ElementSet shown = ElementSet::none();
  shown.show(Element::trail);
  shown.show(Element::velocity);
  const SceneOptions options = scene_options_for(p, motion, shown, true);
  DrawList list;
  build_scene(p, options, motion, 30, list);
  const BodyState& before = motion.samples[0].state;
  // The oldest point is where P really was then (the grid behind it is fixed too), a
  // whole second of fall above where P is now.
  EXPECT_NEAR((list.trail.front().at - pin_position(p, before.x1, before.y1, before.theta1)).norm(), 0, 1e-14);
  EXPECT_GT(list.trail.front().at.y() - list.trail.back().at.y(), 0.4 * p.g);
  // Relative velocities of the two centres of mass are opposite (G is their midpoint).
  const Arrow* v1 = find_arrow(list, ArrowKind::velocity, 0);
  const Arrow* v2 = find_arrow(list, ArrowKind::velocity, 1);
  ASSERT_NE(v1, nullptr);
  ASSERT_NE(v2, nullptr);
  EXPECT_NEAR((v1->vector + v2->vector).norm(), 0, 1e-15);
}

TEST(SceneBuilder, ArrowMaximaOverTheMotion) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 31, 0.1, true);
  const auto maxima = arrow_maxima(p, motion, false);
  double largest = 0;
  for (const MotionSample& s : motion.samples) largest = std::max(largest, s.pin_force.norm());
  EXPECT_EQ(maxima[static_cast<std::size_t>(ArrowKind::pin_force)], largest);
  EXPECT_DOUBLE_EQ(maxima[static_cast<std::size_t>(ArrowKind::gravity)], p.m * p.g);
  // Falling for 3 s, block 1's speed exceeds 29 m/s.
  EXPECT_GT(maxima[static_cast<std::size_t>(ArrowKind::velocity)], 29.0);
}

}  // namespace
}  // namespace linkage
