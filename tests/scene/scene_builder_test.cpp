#include "scene/scene_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

TEST(SceneBuilder, CommonScaleDrawsGravityAndThePinForceToOneScale) {
  // At the spec's example the pin force is hundreds of times smaller than m g: at one
  // scale their arrows' lengths keep that ratio, unless the pin force's is stretched.
  const Params p;
  const Motion motion = test::still_motion(p, State{}, true);
  ArrowScaleRequest request;
  request.common = true;
  SceneOptions options = scene_options_for(p, motion, ElementSet::defaults(), false, request);
  const ArrowScale& pin = options.arrow_scales[static_cast<std::size_t>(ArrowKind::pin_force)];
  const ArrowScale& gravity = options.arrow_scales[static_cast<std::size_t>(ArrowKind::gravity)];
  EXPECT_TRUE(options.common_force_scale);
  EXPECT_EQ(pin.units_per_cm(), gravity.units_per_cm());
  DrawList list;
  build_scene(p, options, motion, 0, list);
  const Arrow* f = find_arrow(list, ArrowKind::pin_force);
  const Arrow* mg = find_arrow(list, ArrowKind::gravity);
  ASSERT_NE(f, nullptr);
  ASSERT_NE(mg, nullptr);
  const double ratio = p.m * p.g / motion.samples[0].pin_force.norm();
  EXPECT_GT(ratio, 300);
  EXPECT_NEAR(mg->vector.norm() / f->vector.norm(), ratio, 1e-9 * ratio);
  EXPECT_FALSE(f->stretched);
  EXPECT_TRUE(f->valued);  // at one scale, the labels give the values
  EXPECT_TRUE(mg->valued);
  EXPECT_NEAR(mg->magnitude, p.m * p.g, 1e-15);
  EXPECT_NEAR(f->magnitude, motion.samples[0].pin_force.norm(), 1e-15);
  EXPECT_LE(mg->vector.norm(), default_longest_arrow(p) * (1 + 1e-12));

  // Too short to see at 2 cm: stretched to 2 cm, its direction kept; gravity is not.
  options.shortest_arrow = 0.02;
  EXPECT_TRUE(any_stretched(p, options, motion));
  build_scene(p, options, motion, 0, list);
  f = find_arrow(list, ArrowKind::pin_force);
  mg = find_arrow(list, ArrowKind::gravity);
  EXPECT_TRUE(f->stretched);
  EXPECT_NEAR(f->vector.norm(), 0.02, 1e-15);
  EXPECT_NEAR(f->vector.normalized().dot(motion.samples[0].pin_force.normalized()), 1, 1e-12);
  EXPECT_FALSE(mg->stretched);

  // Each its own scale (the default): neither is short, and nothing is stretched.
  SceneOptions own = scene_options_for(p, motion, ElementSet::defaults(), false);
  EXPECT_FALSE(own.common_force_scale);
  own.shortest_arrow = 0.02;
  EXPECT_FALSE(any_stretched(p, own, motion));
  build_scene(p, own, motion, 0, list);
  for (const Arrow& arrow : list.arrows) EXPECT_FALSE(arrow.valued);
}

TEST(SceneBuilder, FixedScalesAreKeptPerKind) {
  const Params p;
  const Motion motion = test::still_motion(p, State{}, true);
  ArrowScaleRequest request;
  request.fixed = {{"pin", 0.001}, {"gravity", 2.0}};
  const SceneOptions options = scene_options_for(p, motion, ElementSet::defaults(), false, request);
  DrawList list;
  build_scene(p, options, motion, 0, list);
  EXPECT_NEAR(find_arrow(list, ArrowKind::gravity)->vector.norm(), p.m * p.g / 2.0 * 0.01, 1e-12);
  EXPECT_NEAR(find_arrow(list, ArrowKind::pin_force)->vector.norm(), motion.samples[0].pin_force.norm() / 0.001 * 0.01,
              1e-12);
}

TEST(SceneBuilder, FreeBodyViewDrawsTheBlocksApartEachWithItsPinPointAndLoads) {
  const Params p;
  const Motion motion = test::still_motion(p, State{}, true);
  SceneOptions options = scene_options_for(p, motion, ElementSet::defaults(), false);
  options.explode = 0.4;
  DrawList list;
  build_scene(p, options, motion, 0, list);
  const BodyState& s = motion.samples[0].state;
  const Vec2 c1(s.x1, s.y1), c2(s.x2, s.y2), apart = (c2 - c1).normalized();
  ASSERT_EQ(list.blocks.size(), 2U);
  EXPECT_NEAR((list.blocks[0].centre - (c1 - 0.2 * apart)).norm(), 0, 1e-15);
  EXPECT_NEAR((list.blocks[1].centre - (c2 + 0.2 * apart)).norm(), 0, 1e-15);
  EXPECT_TRUE(list.trail.empty());
  // Two halves of the pin 0.4 m apart, no system centre of mass.
  std::vector<Vec2> pins;
  for (const Marker& m : list.markers) {
    EXPECT_NE(m.kind, MarkerKind::com_system);
    if (m.kind == MarkerKind::pin) pins.push_back(m.at);
  }
  ASSERT_EQ(pins.size(), 2U);
  EXPECT_NEAR((pins[1] - pins[0]).norm(), 0.4, 1e-12);
  // Each pin force starts at its block's own half of the pin; F on 1 and -F on 2 still opposite.
  const Arrow* f1 = find_arrow(list, ArrowKind::pin_force, 0);
  const Arrow* f2 = find_arrow(list, ArrowKind::pin_force, 1);
  ASSERT_NE(f1, nullptr);
  ASSERT_NE(f2, nullptr);
  EXPECT_NEAR((f1->tail - pins[0]).norm(), 0, 1e-15);
  EXPECT_NEAR((f2->tail - pins[1]).norm(), 0, 1e-15);
  EXPECT_NEAR((f1->vector + f2->vector).norm(), 0, 1e-15);
  EXPECT_NEAR((find_arrow(list, ArrowKind::gravity, 1)->tail - list.blocks[1].centre).norm(), 0, 1e-15);
}

TEST(SceneBuilder, DriftedCase1MarksEachBlocksOwnPinPoint) {
  const Params p;
  Motion motion = test::still_motion(p, State{}, true);
  const SceneOptions options = scene_options_for(p, motion, ElementSet::defaults(), false);
  const auto pins_of = [&](double shift) {
    Motion drifted = motion;
    drifted.samples[0].state.x2 += shift;  // block 2 off the pin by `shift` along x
    DrawList list;
    build_scene(p, options, drifted, 0, list);
    std::vector<Marker> pins;
    for (const Marker& m : list.markers)
      if (m.kind == MarkerKind::pin) pins.push_back(m);
    return pins;
  };
  // Half a millimetre (under a hundredth of w = 0.1 m): one pin, P.
  const std::vector<Marker> close = pins_of(0.0005);
  ASSERT_EQ(close.size(), 1U);
  EXPECT_EQ(close[0].tag, "P");
  // A centimetre: block 1's pin point and block 2's, a centimetre apart, each named.
  const std::vector<Marker> apart = pins_of(0.01);
  ASSERT_EQ(apart.size(), 2U);
  EXPECT_EQ(apart[0].tag, "P of 1");
  EXPECT_EQ(apart[1].tag, "P of 2");
  EXPECT_NEAR((apart[1].at - apart[0].at - Vec2(0.01, 0)).norm(), 0, 1e-12);
}

}  // namespace
}  // namespace linkage
