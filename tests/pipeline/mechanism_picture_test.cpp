// Issue 23, Deliver 2: every picture feature on every mechanism. The draw list holds what
// --show/--hide ask for; gravity, springs and velocities are arrows with the values the
// System gives; the camera is the one asked for (fit and follow by default).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

#include "columns/mechanism_columns.hpp"
#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "scene/mechanism_scene.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

using test::test_mechanism;

using Kind = MechanismDrawList::Arrow::Kind;

// A mechanism file of tests/data/mechanisms/.

MechanismMotion motion_of(const sym::System& system, double duration, double fps, int trail_steps = 1,
                          bool accelerations = false) {
  std::vector<double> times;
  for (long k = 0; k <= std::lround(duration * fps); ++k) times.push_back(static_cast<double>(k) / fps);
  SimulationOptions options;
  options.duration = duration;
  ClipResult result;
  return sample_mechanism_motion(system, sym::checked_initial_state(system).state, options, times, trail_steps, result,
                                 {}, {}, nullptr, {}, accelerations);
}

std::vector<MechanismDrawList::Arrow> arrows_of(const MechanismDrawList& list, Kind kind) {
  std::vector<MechanismDrawList::Arrow> out;
  for (const MechanismDrawList::Arrow& arrow : list.arrows)
    if (arrow.kind == kind) out.push_back(arrow);
  return out;
}

bool has_row(const MechanismDrawList::Legend& legend, Kind kind) {
  for (const MechanismDrawList::Legend::Row& row : legend.rows)
    if (row.kind == kind) return true;
  return false;
}

// The spring-pendulum's disc (m = 0.2 kg, g = 9.81) on k = 20 N/m, l0 = 0.3 m, c = 0.05 N s/m
// from O = (0, 0): m g down at the centre, and k (l - l0) + c l' along the spring, pulling
// the disc towards O, as worked out here by hand from the sample's pose and rates.
TEST(MechanismPicture, GravityAndSpringArrowsCarryTheLoadsValues) {
  const sym::System system(load_mechanism("spring-pendulum"));
  const MechanismMotion motion = motion_of(system, 1.0, 30);
  ElementSet shown = ElementSet::defaults();
  shown.show(Element::velocity);
  const MechanismScene scene(mechanism_geometry(system), motion, {}, 2.0, {}, shown);
  MechanismDrawList list;
  for (const std::size_t k : {0UL, 7UL, 30UL}) {
    SCOPED_TRACE(k);
    scene.frame(k, list);
    const eval::MechanismSample& s = motion.samples[k];
    const Vec2 centre(s.pose[0], s.pose[1]), velocity(s.rates[0], s.rates[1]);
    const auto gravity = arrows_of(list, Kind::gravity);
    ASSERT_EQ(gravity.size(), 1U);
    EXPECT_NEAR(gravity[0].force, 0.2 * 9.81, 1e-12);
    EXPECT_NEAR((gravity[0].tail - centre).norm(), 0, 1e-12);
    EXPECT_NEAR(gravity[0].vector.normalized().y(), -1, 1e-12);
    EXPECT_EQ(gravity[0].label, "mg");
    const auto spring = arrows_of(list, Kind::spring);
    ASSERT_EQ(spring.size(), 1U);  // the ground's end is not drawn
    const double length = centre.norm(), rate = centre.dot(velocity) / length;
    const double tension = 20 * (length - 0.3) + 0.05 * rate;
    EXPECT_NEAR(spring[0].force, std::fabs(tension), 1e-9);
    EXPECT_NEAR((spring[0].vector.normalized() - std::copysign(1.0, tension) * (-centre / length)).norm(), 0, 1e-9);
    EXPECT_EQ(spring[0].label.rfind("k1 on 1", 0), 0U);
    const auto velocities = arrows_of(list, Kind::velocity);
    ASSERT_EQ(velocities.size(), k == 0 ? 0U : 1U);  // it starts at rest
    if (k > 0) {
      EXPECT_NEAR(velocities[0].force, velocity.norm(), 1e-12);
      if (!velocities[0].cut && !velocities[0].stretched) {
        EXPECT_NEAR((velocities[0].vector - scene.scale_of(Kind::velocity) * velocity).norm(), 0, 1e-12);
      }
    }
    for (const MechanismDrawList::Arrow& arrow : list.arrows) {
      if (!arrow.cut && !arrow.stretched) {
        EXPECT_NEAR(arrow.vector.norm(), scene.scale_of(arrow.kind) * arrow.force, 1e-12) << arrow.label;
      }
    }
  }
  EXPECT_TRUE(has_row(list.legend, Kind::gravity));
  EXPECT_TRUE(has_row(list.legend, Kind::spring));
  EXPECT_TRUE(has_row(list.legend, Kind::velocity));
  // By default each kind its own scale; common gives gravity and the spring one.
  EXPECT_NE(scene.scale_of(Kind::gravity), scene.scale_of(Kind::spring));
  ArrowScaleRequest common;
  common.common = true;
  const MechanismScene shared(mechanism_geometry(system), motion, {}, 2.0, common, shown);
  EXPECT_EQ(shared.scale_of(Kind::gravity), shared.scale_of(Kind::spring));
  EXPECT_NE(shared.scale_of(Kind::velocity), shared.scale_of(Kind::gravity));  // not a force
  ArrowScaleRequest fixed;
  fixed.fixed = {{"gravity", 2.0}};  // 1 cm = 2 N
  const MechanismScene two(mechanism_geometry(system), motion, {}, 2.0, fixed, shown);
  EXPECT_NEAR(two.scale_of(Kind::gravity), 0.01 / 2, 1e-15);
}

// Gravity's label as a lecturer writes the weight: the mass's and g's names side by side
// ("mg" on each of the homework's blocks, as its clip wrote them), a mass's digits lowered
// ("m₁g"), a longer name set apart ("ma g"), one arrow per body.
TEST(MechanismPicture, GravityIsLabelledAsTheWeightIsWritten) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> expected{
      {"two-blocks", {"mg", "mg"}}, {"double-pendulum", {"m₁g", "m₂g"}}, {"four-bar", {"ma g", "mb g", "mc g"}}};
  for (const auto& [name, labels] : expected) {
    SCOPED_TRACE(name);
    const sym::System system(load_mechanism(name));
    const MechanismMotion motion = motion_of(system, 0.2, 10);
    const MechanismScene scene(mechanism_geometry(system), motion, {}, 2.0, {}, ElementSet::defaults());
    MechanismDrawList list;
    scene.frame(1, list);
    std::vector<std::string> drawn;
    for (const MechanismDrawList::Arrow& arrow : arrows_of(list, Kind::gravity)) drawn.push_back(arrow.label);
    EXPECT_EQ(drawn, labels);
  }
}

// Under a camera following the centre of mass G, velocities are drawn relative to G (the
// homework's clip did so): each block's is its own minus G's, so the mass-weighted sum of
// the arrows' velocities is zero, and the legend says "relative to G"; otherwise absolute.
TEST(MechanismPicture, VelocitiesAreRelativeToTheFollowedCentreOfMass) {
  const sym::System system(load_mechanism("unequal-blocks"));
  const MechanismMotion motion = motion_of(system, 1.0, 10);
  const MechanismGeometry geometry = mechanism_geometry(system);
  ElementSet shown = ElementSet::defaults();
  shown.show(Element::velocity);
  for (const bool relative : {false, true}) {
    SCOPED_TRACE(relative);
    const MechanismScene scene(geometry, motion, {}, 2.0, {}, shown, false, relative);
    MechanismDrawList list;
    scene.frame(10, list);
    const eval::MechanismSample& s = motion.samples[10];
    const auto velocities = arrows_of(list, Kind::velocity);
    ASSERT_EQ(velocities.size(), 2U);
    const Vec2 com(s.com[2], s.com[3]);
    ASSERT_GT(com.norm(), 5.0);  // falling for a second: G's velocity dwarfs the turning
    Vec2 momentum = Vec2::Zero();
    for (std::size_t i = 0; i < 2; ++i) {
      const Vec2 v = Vec2(s.rates[3 * i], s.rates[3 * i + 1]) - (relative ? com : Vec2::Zero());
      const Vec2 drawn = velocities[i].force * velocities[i].vector.normalized();
      EXPECT_NEAR((drawn - v).norm(), 0, 1e-9 * (1 + v.norm()));
      momentum += geometry.bodies[i].mass * drawn;
    }
    if (relative) {
      EXPECT_NEAR(momentum.norm(), 0, 1e-9);
    }
    EXPECT_EQ(list.legend.relative_velocity, relative);
  }
}

// A trajectory file with only the generalized coordinates (the homework's t, x1, y1,
// theta1, theta2): every body's pose follows from them as the System states it, so block
// 2's centre is the simulation's own, to round-off.
TEST(MechanismPicture, ATrajectoryOfTheCoordinatesGivesEveryPose) {
  const sym::System system(load_mechanism("two-blocks"));
  const MechanismGeometry geometry = mechanism_geometry(system);
  const MechanismMotion motion = motion_of(system, 1.0, 10);
  TrajectoryTable table;
  table.names = mechanism_coordinate_columns(system, &system.mechanism());
  EXPECT_EQ(table.names, (std::vector<std::string>{"t", "x1", "y1", "theta1", "theta2"}));
  table.values.assign(5, {});
  for (std::size_t k = 0; k < motion.times.size(); ++k) {
    const std::vector<double>& pose = motion.samples[k].pose;
    const double row[] = {motion.times[k], pose[0], pose[1], pose[2], pose[5]};
    for (std::size_t c = 0; c < 5; ++c) table.values[c].push_back(row[c]);
  }
  table.t = table.values[0];
  const MechanismMotion read = table_motion(table, geometry, motion.times, &system.mechanism(), &system);
  for (std::size_t k = 0; k < motion.times.size(); ++k)
    for (std::size_t i = 0; i < 6; ++i)
      EXPECT_NEAR(read.samples[k].pose[i], motion.samples[k].pose[i], 1e-12) << "sample " << k << ", " << i;
  EXPECT_GT(std::fabs(motion.samples[10].pose[3] - motion.samples[10].pose[0]), 0.1);  // block 2 is elsewhere
}

TEST(MechanismPicture, ShowAndHideDecideTheDrawList) {
  const sym::System system(load_mechanism("four-bar"));
  const MechanismMotion motion = motion_of(system, 0.5, 30);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const std::vector<BodyPoint> trail{geometry.resolve("3.B", "trail")};
  MechanismDrawList list;
  const auto count = [&](MechanismDrawList::Marker::Kind kind) {
    return std::count_if(list.markers.begin(), list.markers.end(), [&](const auto& m) { return m.kind == kind; });
  };
  const MechanismScene shown(geometry, motion, trail);
  shown.frame(10, list);
  EXPECT_EQ(list.outlines.size(), 3U);
  EXPECT_EQ(list.labels.size(), 3U);
  EXPECT_EQ(count(MechanismDrawList::Marker::Kind::pin), 4);
  EXPECT_EQ(count(MechanismDrawList::Marker::Kind::com), 3);
  EXPECT_EQ(arrows_of(list, Kind::joint).size(), 6U);  // two per joint between bodies, one at each ground pin
  EXPECT_EQ(arrows_of(list, Kind::gravity).size(), 3U);
  EXPECT_TRUE(arrows_of(list, Kind::velocity).empty());  // off by default
  EXPECT_TRUE(std::any_of(list.lines.begin(), list.lines.end(),
                          [](const auto& l) { return l.kind == MechanismDrawList::Line::Kind::trail; }));
  EXPECT_TRUE(list.shown.has(Element::grid));

  ElementSet few = ElementSet::defaults();
  for (const Element e : {Element::blocks, Element::pin, Element::pin_force, Element::labels, Element::trail,
                          Element::com, Element::grid, Element::legend})
    few.hide(e);
  const MechanismScene hidden(geometry, motion, trail, 2.0, {}, few);
  hidden.frame(10, list);
  EXPECT_TRUE(list.outlines.empty());
  EXPECT_TRUE(list.labels.empty());
  EXPECT_EQ(count(MechanismDrawList::Marker::Kind::pin), 0);
  EXPECT_EQ(count(MechanismDrawList::Marker::Kind::com), 0);
  EXPECT_EQ(count(MechanismDrawList::Marker::Kind::ground), 2);  // the ground stays
  EXPECT_TRUE(arrows_of(list, Kind::joint).empty());
  ASSERT_EQ(arrows_of(list, Kind::gravity).size(), 3U);
  for (const MechanismDrawList::Arrow& arrow : list.arrows) EXPECT_EQ(arrow.label, "");  // labels hidden
  EXPECT_FALSE(std::any_of(list.lines.begin(), list.lines.end(),
                           [](const auto& l) { return l.kind == MechanismDrawList::Line::Kind::trail; }));
  EXPECT_FALSE(list.shown.has(Element::grid));  // the painter's part
  EXPECT_FALSE(list.legend.joint);
  EXPECT_TRUE(has_row(list.legend, Kind::gravity));
}

TEST(MechanismPicture, CameraIsFitOrFollowByDefaultAndAsAsked) {
  RenderSettings settings;
  settings.width = 320;
  settings.height = 180;
  const sym::System four_bar(load_mechanism("four-bar")), blocks(load_mechanism("two-blocks"));
  EXPECT_EQ(mechanism_camera_mode(settings, mechanism_geometry(four_bar)), CameraMode::fit);
  EXPECT_EQ(mechanism_camera_mode(settings, mechanism_geometry(blocks)), CameraMode::follow);
  settings.camera_chosen = true;
  settings.camera = CameraMode::follow;
  EXPECT_EQ(mechanism_camera_mode(settings, mechanism_geometry(four_bar)), CameraMode::follow);

  const MechanismMotion motion = motion_of(four_bar, 1.0, 30);
  const MechanismScene scene(mechanism_geometry(four_bar), motion, {});
  // Fit: every outline point and arrow tip of every frame inside the frame.
  const Camera fit = mechanism_camera(scene, settings, CameraMode::fit);
  const View visible = fit.visible();
  EXPECT_LE(visible.xmin, scene.view_bounds().min.x());
  EXPECT_GE(visible.xmax, scene.view_bounds().max.x());
  EXPECT_LE(visible.ymin, scene.view_bounds().min.y());
  EXPECT_GE(visible.ymax, scene.view_bounds().max.y());
  // Follow: centred on the centroid, holding the widest reach.
  const Camera follow = mechanism_camera(scene, settings, CameraMode::follow);
  EXPECT_NEAR((follow.centre() - scene.centroid(0)).norm(), 0, 1e-12);
  EXPECT_NEAR(0.5 * settings.height / follow.scale(), 1.1 * scene.view_reach(), 1e-9);
  // Fixed: exactly the view asked for, widened to the frame's shape.
  settings.view = {-1, -0.5, 1, 0.5};
  const Camera fixed = mechanism_camera(scene, settings, CameraMode::fixed);
  EXPECT_NEAR(fixed.visible().xmin, -1, 1e-12);
  EXPECT_NEAR(fixed.visible().xmax, 1, 1e-12);
  EXPECT_NEAR(fixed.centre().y(), 0, 1e-12);
}

// The four-bar sampled at 0.5 s and h either side, tightly (rtol = atol = 1e-12), with
// each sample's kinematics when `kinematics`.
MechanismMotion four_bar_about_half_a_second(const sym::System& system, double h, bool kinematics) {
  SimulationOptions options;
  options.duration = 0.6;
  options.rtol = 1e-12;
  options.atol = 1e-12;
  ClipResult result;
  return sample_mechanism_motion(system, sym::checked_initial_state(system).state, options, {0.5 - h, 0.5, 0.5 + h}, 1,
                                 result, {}, {}, nullptr, {}, kinematics);
}

// What the middle sample of `motion` draws of `kind` with `shown` and the point 3.P traced.
struct TracedArrows {
  std::vector<MechanismDrawList::Arrow> arrows;
  double scale = 0;  // of `kind`
  bool row = false;  // the legend's row of `kind`
};
TracedArrows traced_arrows(const sym::System& system, const MechanismMotion& motion, ElementSet shown, Kind kind) {
  const MechanismGeometry geometry = mechanism_geometry(system);
  const MechanismScene scene(geometry, motion, {geometry.resolve("3.P", "trail")}, 2.0, {}, shown);
  MechanismDrawList list;
  scene.frame(1, list);
  return {arrows_of(list, kind), scene.scale_of(kind), has_row(list.legend, kind)};
}

// A traced point's velocity from the System's derivative of its position, checked here
// against a central difference of the point's path (h = 1e-4 s: an error of order h^2
// times the third derivative, far below the tolerance).
TEST(MechanismPicture, TracedPointsVelocityIsTheDerivativeOfItsPath) {
  const sym::System system(load_mechanism("four-bar"));
  const MechanismGeometry geometry = mechanism_geometry(system);
  const BodyPoint p = geometry.resolve("3.P", "trail");
  const MechanismMotion motion = four_bar_about_half_a_second(system, 1e-4, false);
  const std::vector<double>& times = motion.times;
  ElementSet shown = ElementSet::defaults();
  shown.show(Element::velocity);
  const auto velocities = traced_arrows(system, motion, shown, Kind::velocity).arrows;
  ASSERT_EQ(velocities.size(), 4U);  // three centres of mass, then P
  EXPECT_EQ(velocities[3].label.rfind("v of 3.P", 0), 0U);
  const Vec2 expected =
      (world_point(motion.samples[2].pose, p) - world_point(motion.samples[0].pose, p)) / (times[2] - times[0]);
  const Vec2 drawn = velocities[3].force * velocities[3].vector.normalized();
  EXPECT_NEAR((drawn - expected).norm(), 0, 1e-5 * expected.norm());
  EXPECT_NEAR((velocities[3].tail - world_point(motion.samples[1].pose, p)).norm(), 0, 1e-12);
}

// --show acceleration: each centre of mass's acceleration as the sample gives it, and a
// traced point's the second difference of its path; its own legend row and scale.
TEST(MechanismPicture, AccelerationArrowsAreTheSamplesAccelerations) {
  const sym::System system(load_mechanism("four-bar"));
  const MechanismGeometry geometry = mechanism_geometry(system);
  const BodyPoint p = geometry.resolve("3.P", "trail");
  const double h = 1e-3;  // the second difference's error, of order h^2, far below the tolerance
  const MechanismMotion motion = four_bar_about_half_a_second(system, h, true);
  ElementSet shown = ElementSet::defaults();
  EXPECT_FALSE(shown.has(Element::acceleration));  // off by default
  shown.show(Element::acceleration);
  const TracedArrows drawn_arrows = traced_arrows(system, motion, shown, Kind::acceleration);
  const auto& accelerations = drawn_arrows.arrows;
  ASSERT_EQ(accelerations.size(), 4U);  // three centres of mass, then P
  const eval::MechanismSample& s = motion.samples[1];
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec2 a(s.accelerations[3 * i], s.accelerations[3 * i + 1]);
    EXPECT_NEAR(accelerations[i].force, a.norm(), 1e-12);
    EXPECT_NEAR((accelerations[i].tail - Vec2(s.pose[3 * i], s.pose[3 * i + 1])).norm(), 0, 1e-12);
    if (!accelerations[i].cut && !accelerations[i].stretched) {
      EXPECT_NEAR((accelerations[i].vector - drawn_arrows.scale * a).norm(), 0, 1e-12);
    }
  }
  EXPECT_EQ(accelerations[3].label.rfind("a of 3.P", 0), 0U);
  const Vec2 expected =
      (world_point(motion.samples[2].pose, p) - 2 * world_point(s.pose, p) + world_point(motion.samples[0].pose, p)) /
      (h * h);
  const Vec2 drawn = accelerations[3].force * accelerations[3].vector.normalized();
  EXPECT_NEAR((drawn - expected).norm(), 0, 1e-4 * expected.norm());
  EXPECT_NEAR((accelerations[3].tail - world_point(s.pose, p)).norm(), 0, 1e-12);
  EXPECT_TRUE(drawn_arrows.row);
  // Hidden (the default): none, and no row.
  const TracedArrows hidden = traced_arrows(system, motion, ElementSet::defaults(), Kind::acceleration);
  EXPECT_TRUE(hidden.arrows.empty());
  EXPECT_FALSE(hidden.row);
}

// The homework's look as general features: a row per trail ("path of P, last 2 s"), the HUD's energy balance (the
// energy_error column's value) and, only when the case keeps a constraint, the joints' largest constraint error; the
// centre of mass the bodies' centres weighted by their masses.
TEST(MechanismPicture, LegendRowsHudAndCentreOfMassOfTheTwoBlocks) {
  const sym::System system(load_mechanism("unequal-blocks"));
  const MechanismGeometry geometry = mechanism_geometry(system);
  const std::vector<double> times{0, 0.1, 0.2};
  for (const int case_id : {1, 3}) {
    SCOPED_TRACE(case_id);
    SimulationOptions options;
    options.duration = 0.2;
    options.case_id = case_id;
    ClipResult result;
    const MechanismMotion motion =
        sample_mechanism_motion(system, sym::checked_initial_state(system).state, options, times, 1, result);
    ASSERT_EQ(motion.energy_error.size(), 3U);
    EXPECT_EQ(motion.constraints_kept, case_id == 1);
    const BodyPoint p = geometry.resolve(
        system.mechanism().bodies[0].name + "." + system.mechanism().bodies[0].points.front().name, "trail");
    const MechanismScene scene(geometry, motion, {p}, 2.0, {}, ElementSet::defaults());
    MechanismDrawList list;
    scene.frame(2, list);
    ASSERT_EQ(list.legend.trails.size(), 1U);
    EXPECT_EQ(list.legend.trails[0], "path of " + system.mechanism().bodies[0].points.front().name);
    EXPECT_EQ(list.legend.trail_seconds, 2.0);
    EXPECT_EQ(list.hud.energy_error, motion.energy_error[2]);
    EXPECT_LT(std::fabs(list.hud.energy_error), 1e-6);
    EXPECT_EQ(list.hud.constraint, case_id == 1);
    double largest = 0;
    for (const double c : motion.samples[2].constraint) largest = std::max(largest, c);
    EXPECT_EQ(list.hud.constraint_error, largest);
    const std::vector<double>& pose = motion.samples[2].pose;
    Vec2 weighted = Vec2::Zero();
    double mass = 0;
    for (std::size_t i = 0; i < geometry.bodies.size(); ++i) {
      weighted += geometry.bodies[i].mass * Vec2(pose[3 * i], pose[3 * i + 1]);
      mass += geometry.bodies[i].mass;
    }
    EXPECT_NEAR((list.centre_of_mass - weighted / mass).norm(), 0, 1e-12);
    EXPECT_NE(geometry.bodies[0].mass, geometry.bodies[1].mass);  // unequal: not the mean of the centres
  }
  ElementSet bare = ElementSet::defaults();
  bare.hide(Element::trail);
  bare.hide(Element::com);
  SimulationOptions options;
  options.duration = 0.2;
  ClipResult result;
  const MechanismMotion motion =
      sample_mechanism_motion(system, sym::checked_initial_state(system).state, options, times, 1, result);
  const MechanismScene scene(geometry, motion, {}, 2.0, {}, bare);
  MechanismDrawList list;
  scene.frame(1, list);
  EXPECT_TRUE(list.legend.trails.empty());
}

// The free-body view: every body pulled away from the others, carrying every force on it
// (joint forces as equal and opposite pairs, one on each body, gravity at its centre), and
// each body its half of each pin between bodies.
TEST(MechanismPicture, FreeBodyViewPullsEachBodyApartWithItsForces) {
  for (const char* name : {"four-bar", "slider-crank", "triple-pendulum", "two-blocks"}) {
    SCOPED_TRACE(name);
    const sym::System system(load_mechanism(name));
    const MechanismMotion motion = motion_of(system, 0.5, 30);
    const MechanismGeometry geometry = mechanism_geometry(system);
    const MechanismScene together(geometry, motion, {});
    const MechanismScene apart(geometry, motion, {}, 2.0, {}, ElementSet::defaults(), true);
    MechanismDrawList joined, pulled;
    const std::size_t k = 9;
    together.frame(k, joined);
    apart.frame(k, pulled);
    ASSERT_EQ(joined.outlines.size(), pulled.outlines.size());
    ASSERT_EQ(joined.arrows.size(), pulled.arrows.size());
    const std::vector<double>& pose = motion.samples[k].pose;
    const Vec2 c = together.centroid(k);
    std::vector<Vec2> shift;
    for (std::size_t i = 0; i < geometry.bodies.size(); ++i) {
      shift.push_back(0.5 * (Vec2(pose[3 * i], pose[3 * i + 1]) - c));
      // The whole outline moves by its body's shift, unturned.
      for (std::size_t p = 0; p < joined.outlines[i].points.size(); ++p)
        EXPECT_NEAR((pulled.outlines[i].points[p] - joined.outlines[i].points[p] - shift[i]).norm(), 0, 1e-12);
    }
    // Every arrow moves with the body it acts on, its value and direction unchanged.
    for (std::size_t a = 0; a < pulled.arrows.size(); ++a) {
      const MechanismDrawList::Arrow& arrow = pulled.arrows[a];
      ASSERT_GE(arrow.body, 0) << arrow.label;
      EXPECT_EQ(arrow.label, joined.arrows[a].label);
      EXPECT_NEAR((arrow.vector - joined.arrows[a].vector).norm(), 0, 1e-12);
      EXPECT_NEAR((arrow.tail - joined.arrows[a].tail - shift[static_cast<std::size_t>(arrow.body)]).norm(), 0, 1e-12)
          << arrow.label;
    }
    // A joint between two bodies: its pair of arrows equal and opposite, on different
    // bodies, now apart; and its pin drawn on each.
    std::size_t pairs = 0;
    for (std::size_t a = 0; a + 1 < pulled.arrows.size(); ++a) {
      const MechanismDrawList::Arrow &one = pulled.arrows[a], &other = pulled.arrows[a + 1];
      if (one.kind != Kind::joint || other.kind != Kind::joint || one.body == other.body) continue;
      // One force's two arrows: "B on 3" and "B on 4", or by its alias "F on 1" and "−F on 2".
      const auto force = [](const std::string& label) {
        std::string by = label.substr(0, label.find(" on "));
        return by.starts_with("\u2212") ? by.substr(std::string("\u2212").size()) : by;
      };
      if (force(one.label) != force(other.label)) continue;
      ++pairs;
      EXPECT_NEAR((one.vector + other.vector).norm(), 0, 1e-12) << one.label;
      EXPECT_GT((one.tail - other.tail).norm(), 1e-3) << one.label;
      ++a;
    }
    std::size_t between = 0;
    for (const MechanismGeometry::JointShape& joint : geometry.joints)
      if (joint.points[0].body >= 0 && joint.points[1].body >= 0) ++between;
    EXPECT_EQ(pairs, between);
    const auto pins = [](const MechanismDrawList& list) {
      return std::count_if(list.markers.begin(), list.markers.end(),
                           [](const auto& m) { return m.kind == MechanismDrawList::Marker::Kind::pin; });
    };
    // A pin on every body it joins (the ground's side stays a support), one per joint when joined.
    std::size_t pin_joints = 0, pin_sides = 0;
    for (const MechanismGeometry::JointShape& joint : geometry.joints) {
      if (joint.type != JointType::pin) continue;
      ++pin_joints;
      pin_sides += (joint.points[0].body >= 0 ? 1U : 0U) + (joint.points[1].body >= 0 ? 1U : 0U);
    }
    EXPECT_EQ(static_cast<std::size_t>(pins(joined)), pin_joints);
    EXPECT_EQ(static_cast<std::size_t>(pins(pulled)), pin_sides);
    // The camera's view holds the pulled-apart bodies.
    for (const MechanismDrawList::Outline& outline : pulled.outlines)
      for (const Vec2& p : outline.points) {
        EXPECT_GE(p.x(), apart.view_bounds().min.x() - 1e-12);
        EXPECT_LE(p.y(), apart.view_bounds().max.y() + 1e-12);
      }
  }
}

// Issue 25, Deliver 8: a driver drawn as a motor at its joint. driven-four-bar.toml's M
// drives O2 (ground, crank "2"): the motor at O2's point, its torque on the crank an arc
// about O2 turning counter-clockwise for M.torque > 0 with the column's value in its label;
// shown by default, hidden by --hide motor, absent from a file with no driver.
TEST(MechanismPicture, ADriverIsAMotorAtItsJointWithItsTorque) {
  const sym::System system(load_mechanism(test_mechanism("driven-four-bar.toml")));
  const MechanismMotion motion = motion_of(system, 2.0, 30);
  const MechanismScene scene(mechanism_geometry(system), motion, {});
  const std::vector<MechanismColumn> columns = mechanism_columns(system);
  const MechanismColumn torque = find_mechanism_column(columns, "M.torque", "test");
  MechanismDrawList list;
  int positive = 0, negative = 0;
  for (std::size_t k = 0; k < motion.samples.size(); ++k) {
    SCOPED_TRACE(k);
    scene.frame(k, list);
    const eval::MechanismSample& s = motion.samples[k];
    const double value = column_value(torque, motion.times[k], Eigen::VectorXd::Zero(1), s, {});
    ASSERT_TRUE(std::isfinite(value));
    ASSERT_EQ(list.motors.size(), 1U);
    EXPECT_NEAR(list.motors[0].at.norm(), 0, 1e-12);  // O2 = (0, 0)
    EXPECT_FALSE(list.motors[0].slider);
    ASSERT_EQ(list.torques.size(), 1U);  // the file has no applied torque
    const MechanismDrawList::Torque& arc = list.torques[0];
    EXPECT_TRUE(arc.driver);
    EXPECT_NEAR(arc.centre.norm(), 0, 1e-12);
    EXPECT_EQ(arc.sweep > 0, value > 0);  // counter-clockwise positive, on the crank
    (value > 0 ? positive : negative)++;
    ASSERT_EQ(arc.label.rfind("M: ", 0), 0U) << arc.label;
    EXPECT_EQ(arc.label.substr(arc.label.size() - 4), " N m");
    // The printed value is the column's, to its three significant digits.
    const double printed = std::stod(arc.label.substr(3));
    EXPECT_NEAR(printed, value, 5e-3 * std::fabs(value)) << arc.label;
    EXPECT_EQ(arc.label, "M: " + format_quantity(value, "N m"));
    const bool row = std::any_of(list.legend.rows.begin(), list.legend.rows.end(),
                                 [](const auto& r) { return r.kind == Kind::driver && r.sweep > 0; });
    EXPECT_TRUE(row);
  }
  EXPECT_GT(positive, 0);
  // Its sweep is its size: twice the torque, twice the arc (below the longest drawn).
  scene.frame(5, list);
  const double a = list.torques[0].sweep / motion.samples[5].drivers[0];
  scene.frame(15, list);
  EXPECT_NEAR(list.torques[0].sweep / motion.samples[15].drivers[0], a, 1e-12 * std::fabs(a));

  ElementSet hidden = ElementSet::defaults();
  EXPECT_TRUE(hidden.has(Element::motor));
  hidden.hide(Element::motor);
  const MechanismScene without(mechanism_geometry(system), motion, {}, 2.0, {}, hidden);
  without.frame(5, list);
  EXPECT_TRUE(list.motors.empty());
  EXPECT_TRUE(list.torques.empty());
  for (const auto& r : list.legend.rows) EXPECT_NE(r.kind, Kind::driver);

  const sym::System undriven(load_mechanism("four-bar"));
  const MechanismMotion still = motion_of(undriven, 0.2, 10);
  const MechanismScene plain(mechanism_geometry(undriven), still, {});
  plain.frame(1, list);
  EXPECT_TRUE(list.motors.empty());
  EXPECT_TRUE(list.torques.empty());
}

// A slider's driver: driven-cart-pendulum.toml's D moves the cart along slider S: the
// motor at the guide along the rail, its force an arrow along the axis with D.force's value.
TEST(MechanismPicture, ASliderDriverIsAMotorAlongItsAxisWithItsForce) {
  const sym::System system(load_mechanism(test_mechanism("driven-cart-pendulum.toml")));
  const MechanismMotion motion = motion_of(system, 1.0, 10);
  const MechanismScene scene(mechanism_geometry(system), motion, {});
  MechanismDrawList list;
  for (std::size_t k = 1; k < motion.samples.size(); ++k) {
    SCOPED_TRACE(k);
    scene.frame(k, list);
    const double force = motion.samples[k].drivers.at(0);
    ASSERT_EQ(list.motors.size(), 1U);
    EXPECT_TRUE(list.motors[0].slider);
    const auto drawn = arrows_of(list, Kind::driver);
    ASSERT_EQ(drawn.size(), force == 0 ? 0U : 1U);
    if (force == 0) continue;
    EXPECT_NEAR(drawn[0].force, std::fabs(force), 1e-12);
    EXPECT_NEAR((drawn[0].tail - list.motors[0].at).norm(), 0, 1e-12);
    // Along the axis, pointing the way the force on bodies[1] does.
    EXPECT_NEAR(drawn[0].vector.normalized().dot(list.motors[0].axis), force > 0 ? 1 : -1, 1e-12);
    EXPECT_EQ(drawn[0].label, "D: " + format_quantity(force, "N"));
  }
}

// Issue 25, Deliver 8: --trail-length cycle is one period of the driver's motion, and the
// trail over it closes. offset-slider-crank.toml turns its crank at w = 12 rad/s: 2 pi/12 =
// 0.5236 s. The trail's samples are 1/120 s apart (30 fps, 4 per frame), so its start,
// between two of them, is placed between their points: off the true path by at most
// r w^2 dt^2/8 = 0.1 x 144/120^2/8 = 1.25e-4 m for A at r = 0.1 m (without it, up to
// r w dt = 1 cm), far below a pixel of the picture (0.7 m over 1280 px).
TEST(MechanismPicture, ATrailOverADriversCycleCloses) {
  const sym::System system(load_mechanism(test_mechanism("offset-slider-crank.toml")));
  const double period = driver_cycle_seconds(system);
  EXPECT_NEAR(period, 2 * std::numbers::pi / 12, 1e-12);
  EXPECT_NEAR(trail_seconds_of(system, "cycle"), period, 0);
  EXPECT_EQ(trail_seconds_of(system, ""), 2.0);
  EXPECT_EQ(trail_seconds_of(system, "2.5"), 2.5);
  const MechanismMotion motion = motion_of(system, 1.0, 30, 4);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const BodyPoint a = geometry.resolve("rod.A", "trail");
  MechanismScene scene(geometry, motion, {a}, period);
  scene.set_trail_fades(false);  // --trail-length cycle: the closed curve drawn end to end
  MechanismDrawList list;
  int closed = 0;
  for (std::size_t k = 16; k <= 30; ++k) {  // from t = 0.533 s, a whole cycle back
    SCOPED_TRACE(k);
    scene.frame(k, list);
    const auto trail = std::find_if(list.lines.begin(), list.lines.end(), [](const MechanismDrawList::Line& l) {
      return l.kind == MechanismDrawList::Line::Kind::trail;
    });
    ASSERT_NE(trail, list.lines.end());
    EXPECT_NEAR((trail->points.front() - trail->points.back()).norm(), 0, 2e-4);
    EXPECT_NEAR((trail->points.back() - world_point(motion.samples[k].pose, a)).norm(), 0, 1e-12);
    EXPECT_EQ(*std::min_element(trail->fade.begin(), trail->fade.end()), 1.0);  // not faded out
    ++closed;
  }
  EXPECT_EQ(closed, 15);
  // No cycle to close: no driver, a varying rate, a slider's travel.
  const auto refusal = [](const std::string& file) {
    try {
      (void)driver_cycle_seconds(sym::System(load_mechanism(file)));
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(refusal("four-bar").find("cycle needs a [[driver]], and four-bar has none"), std::string::npos);
  EXPECT_NE(refusal(test_mechanism("driven-four-bar.toml")).find("does not turn at a constant rate"),
            std::string::npos);
  EXPECT_NE(refusal(test_mechanism("driven-cart-pendulum.toml")).find("moves slider S"), std::string::npos);
}

// Issue 25, Deliver 8: --show velocity,acceleration --points 3.P,4.B: at each named point
// its velocity and acceleration (world frame), each kind its own scale, labelled with its
// magnitude; the values are the sample's kinematics of those points (MechanismSample::points,
// the 3.P.x_dot ... columns), independent of the scene's own derivative of the position.
TEST(MechanismPicture, NamedPointsCarryTheirVelocityAndAcceleration) {
  const sym::System system(load_mechanism(test_mechanism("driven-four-bar.toml")));
  const MechanismMotion motion = motion_of(system, 1.0, 30, 1, true);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const std::vector<BodyPoint> points{geometry.resolve("3.P", "points"), geometry.resolve("4.B", "points")};
  // Their places in the sample's named points: bodies in order, each body's points by name.
  const std::vector<eval::NamedPoint> named = eval::named_points(system);
  const auto index_of = [&](std::size_t body, const std::string& name) {
    for (std::size_t i = 0; i < named.size(); ++i)
      if (named[i].body == body && named[i].name == name) return i;
    return named.size();
  };
  const std::array<std::size_t, 2> index{index_of(1, "P"), index_of(2, "B")};
  const std::array<std::string, 2> names{"3.P", "4.B"};
  ElementSet shown = ElementSet::defaults();
  shown.show(Element::velocity);
  shown.show(Element::acceleration);
  const MechanismScene scene(geometry, motion, {}, 2.0, {}, shown, false, false, points);
  EXPECT_NE(scene.scale_of(Kind::velocity), scene.scale_of(Kind::acceleration));
  MechanismDrawList list;
  for (const std::size_t k : {3UL, 10UL}) {
    SCOPED_TRACE(k);
    scene.frame(k, list);
    const eval::MechanismSample& s = motion.samples[k];
    for (std::size_t i = 0; i < 2; ++i) {
      SCOPED_TRACE(names[i]);
      const std::size_t p = index[i];
      ASSERT_LT(6 * p + 5, s.points.size());
      const Vec2 at(s.points[6 * p], s.points[6 * p + 1]), v(s.points[6 * p + 2], s.points[6 * p + 3]),
          a(s.points[6 * p + 4], s.points[6 * p + 5]);
      for (const auto& [kind, value, symbol, unit] :
           {std::tuple{Kind::velocity, v, "v", "m/s"}, std::tuple{Kind::acceleration, a, "a", "m/s²"}}) {
        const auto arrows = arrows_of(list, kind);
        const auto drawn = std::find_if(arrows.begin(), arrows.end(), [&](const auto& arrow) {
          return arrow.label.rfind(std::string(symbol) + " of " + names[i], 0) == 0;
        });
        ASSERT_NE(drawn, arrows.end());
        EXPECT_NEAR((drawn->tail - at).norm(), 0, 1e-12);
        EXPECT_NEAR(drawn->force, value.norm(), 1e-9 * value.norm());
        EXPECT_NEAR(drawn->vector.normalized().dot(value.normalized()), 1, 1e-9);
        if (!drawn->cut && !drawn->stretched) {
          EXPECT_NEAR(drawn->vector.norm(), scene.scale_of(kind) * value.norm(), 1e-9 * drawn->vector.norm());
        }
        EXPECT_EQ(drawn->label, std::string(symbol) + " of " + names[i] + ": " + format_quantity(drawn->force, unit));
      }
    }
  }
  // Without velocity and acceleration shown (the default), none.
  const MechanismScene plain(geometry, motion, {}, 2.0, {}, ElementSet::defaults(), false, false, points);
  plain.frame(3, list);
  EXPECT_TRUE(arrows_of(list, Kind::velocity).empty());
  EXPECT_TRUE(arrows_of(list, Kind::acceleration).empty());
}

}  // namespace
}  // namespace linkage
