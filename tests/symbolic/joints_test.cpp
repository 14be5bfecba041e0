// The joint types' stages (symbolic/joint_<type>.cpp): each type's against the others
// (the tree placement satisfies the rows, the coordinate inverts the placement, the
// force does no work on the motion the joint allows, the velocity and acceleration rows
// are the rows' time derivatives), then each file's own numbers.
#include "symbolic/joints.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "model/joint_types.hpp"
#include "support/mechanisms_in_code.hpp"

namespace linkage::sym {
namespace {

using GiNaC::ex;
using GiNaC::symbol;

// Exact arithmetic gives 0 up to the round-off of a few operations on numbers of order 1.
constexpr double kExact = 1e-12;

std::vector<JointType> all_types() {
  std::vector<JointType> out;
  for (std::size_t i = 0; i < kJointTypeNames.size(); ++i) out.push_back(static_cast<JointType>(i));
  return out;
}

// The name moved in, not assigned from a literal: GCC 12 at -O3 sees a false
// -Wstringop-overflow in that assignment to a Joint built just before.
Joint joint_of(JointType type) {
  Joint joint;
  joint.name = std::string(1, 'J');
  joint.type = type;
  joint.bodies = {"1", "2"};
  joint.points = {"A", "B"};
  return joint;
}

// Its ends with the points and axis every test uses: not at the centres, not on an axis.
JointEnds ends_of(JointType type, const Placement& a, const Placement& b) {
  JointEnds ends;
  ends.a = a;
  ends.b = b;
  ends.point_a = {ex(0.3), ex(-0.1)};
  ends.point_b = {ex(-0.2), ex(0.15)};
  if (joint_type_info(type).axis) ends.axis = {ex(2), ex(1)};
  if (joint_type_info(type).angle) ends.angle = ex(0.6);
  if (joint_type_info(type).radius) ends.radius = ex(0.4);
  if (joint_type_info(type).mesh) ends.radii = {ex(0.3), ex(0.5)};
  return ends;
}

// `child_is_b`: b placed by the joint from a and the tree's coordinates, else a from b.
JointEnds placed(JointType type, const Placement& parent, bool child_is_b, const TreeCoordinates& coordinates) {
  JointEnds ends = ends_of(type, parent, parent);
  const Placement child = joint_stages(type).place(ends, child_is_b, coordinates);
  (child_is_b ? ends.b : ends.a) = child;
  return ends;
}

// Every mechanism of mechanisms_in_code.hpp, built once.
const std::vector<std::pair<std::string, std::unique_ptr<System>>>& built_systems() {
  static const auto systems = [] {
    std::vector<std::pair<std::string, std::unique_ptr<System>>> out;
    for (const built::Named& named : built::all_mechanisms())
      out.emplace_back(named.name, std::make_unique<System>(named.make()));
    return out;
  }();
  return systems;
}

class JointStagesTest : public ::testing::TestWithParam<JointType> {};

TEST_P(JointStagesTest, RegisteredConsistently) {
  const JointStages& stages = joint_stages(GetParam());
  EXPECT_EQ(stages.own != nullptr, has_own_coordinate(joint_type_info(GetParam()).motion));
  // The scene draws a rail (a rolling surface) along the joint's axis: only a type that
  // takes one has it.
  EXPECT_EQ(stages.drawing == JointDrawing::rail || stages.drawing == JointDrawing::rolling ||
                stages.drawing == JointDrawing::slot,
            joint_type_info(GetParam()).axis);
  const JointEnds ends = ends_of(GetParam(), {}, {});
  // One multiplier per row: the unknowns are the force's components along the rows.
  EXPECT_EQ(stages.unknowns(joint_of(GetParam()), false, "body 1").size(), stages.rows(ends).size());
}

// A type that never carries a body (a gear's mesh) has no tree placement to check.
#define SKIP_IF_LOOP_ONLY()                              \
  if (!carries_body(joint_type_info(GetParam()).motion)) \
  GTEST_SKIP() << joint_type_name(GetParam()) << " closes loops only: it places no body"

TEST_P(JointStagesTest, TreePlacementSatisfiesTheRows) {
  SKIP_IF_LOOP_ONLY();
  const symbol x("x"), y("y"), theta("theta"), c("c"), s("s");
  const Placement parent{{x, y}, theta};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> draw(-2, 2);
  for (const bool child_is_b : {true, false}) {
    const std::vector<ex> rows = joint_stages(GetParam()).rows(placed(GetParam(), parent, child_is_b, {c, s}));
    ASSERT_FALSE(rows.empty());
    for (int k = 0; k < 5; ++k) {
      const GiNaC::exmap at{{x, draw(rng)}, {y, draw(rng)}, {theta, draw(rng)}, {c, draw(rng)}, {s, draw(rng)}};
      for (const ex& row : rows) EXPECT_NEAR(evaluate(row, at), 0, kExact) << row << " child_is_b " << child_is_b;
    }
  }
}

TEST_P(JointStagesTest, CoordinateInvertsThePlacement) {
  SKIP_IF_LOOP_ONLY();
  const JointStages& stages = joint_stages(GetParam());
  const symbol x("x"), y("y"), theta("theta"), c("c"), s("s");
  const Placement parent{{x, y}, theta};
  const GiNaC::exmap at{{x, 0.4}, {y, -0.7}, {theta, 0.9}, {c, 0.35}, {s, -0.45}};
  for (const bool child_is_b : {true, false}) {
    const JointEnds ends = placed(GetParam(), parent, child_is_b, {c, s});
    const Placement& child = child_is_b ? ends.b : ends.a;
    switch (joint_type_info(GetParam()).motion) {
      case JointMotion::prismatic:  // the travel; the child keeps its parent's angle
        EXPECT_NEAR(evaluate(stages.coordinate(ends), at), -0.45, kExact) << "child_is_b " << child_is_b;
        EXPECT_FALSE(child.angle.has(c));
        break;
      case JointMotion::revolute:  // the coordinate is the child's own angle
      case JointMotion::rolling:
        EXPECT_TRUE(stages.coordinate(ends).is_zero());
        EXPECT_NEAR(evaluate(child.angle, at), 0.35, kExact);
        EXPECT_FALSE(child.position.x.has(s) || child.position.y.has(s));
        break;
      case JointMotion::slotted:  // the travel and the child's own angle
        EXPECT_NEAR(evaluate(stages.coordinate(ends), at), -0.45, kExact) << "child_is_b " << child_is_b;
        EXPECT_NEAR(evaluate(child.angle, at), 0.35, kExact);
        break;
      case JointMotion::loop:  // skipped above
        break;
      case JointMotion::fixed:  // none: the child is placed by the parent alone
        EXPECT_TRUE(stages.coordinate(ends).is_zero());
        EXPECT_FALSE(child.position.x.has(c) || child.position.y.has(c) || child.angle.has(c) ||
                     child.position.x.has(s) || child.position.y.has(s));
        EXPECT_NEAR(evaluate(child.angle, at), 0.9 + (child_is_b ? 0.6 : -0.6), kExact) << child_is_b;
        break;
    }
  }
}

// Power of the joint's force and moment on both bodies, for a motion the joint allows
// (the child placed by the tree stage, everything moving with t): zero, as for any
// ideal joint.
TEST_P(JointStagesTest, ForceDoesNoWorkOnTheMotionItAllows) {
  SKIP_IF_LOOP_ONLY() << " (JointGear.ForceDoesTheRowsWorkOnPinnedGears checks a gear's)";
  const JointStages& stages = joint_stages(GetParam());
  const symbol t("t"), f0("f0"), f1("f1"), f2("f2");
  const Placement parent{{0.3 + 0.2 * GiNaC::sin(1.3 * t), -0.4 + 0.1 * GiNaC::cos(0.7 * t)},
                         0.2 + 0.5 * GiNaC::sin(0.9 * t)};
  const TreeCoordinates coordinates{0.25 + 0.3 * GiNaC::sin(1.1 * t), -0.1 + 0.4 * GiNaC::cos(0.8 * t)};
  for (const bool child_is_b : {true, false}) {
    const JointEnds ends = placed(GetParam(), parent, child_is_b, coordinates);
    JointSystem js;
    js.unknowns = {f0, f1, f2};
    js.unknowns.resize(stages.rows(ends).size());
    stages.force(js, ends);
    // The velocity of body p's material point at world point r.
    auto velocity = [&](const Placement& p, const Vec2& r) {
      const ex omega = GiNaC::diff(p.angle, t);
      return Vec2{GiNaC::diff(p.position.x, t) - omega * (r.y - p.position.y),
                  GiNaC::diff(p.position.y, t) + omega * (r.x - p.position.x)};
    };
    const Vec2 at_b = world_point(ends.b, ends.point_b);
    const Vec2 on_a = stages.force_at_point_b ? at_b : world_point(ends.a, ends.point_a);
    const Vec2 va = velocity(ends.a, on_a), vb = velocity(ends.b, at_b);
    const ex power = js.force.x * (va.x - vb.x) + js.force.y * (va.y - vb.y) +
                     js.moment * (GiNaC::diff(ends.a.angle, t) - GiNaC::diff(ends.b.angle, t));
    for (const double time : {0.1, 0.7, 1.9})
      EXPECT_NEAR(evaluate(power, {{t, time}, {f0, 1.7}, {f1, -0.6}, {f2, 0.8}}), 0, kExact)
          << "t " << time << " child_is_b " << child_is_b;
  }
}

// The velocity and acceleration rows (System::time_derivative of the joint's rows, as
// Case 1 and the projections use them) against central differences of the rows along
// q(tau) = q0 + q0' tau + q0'' tau^2 / 2, in every built mechanism with this joint type.
TEST_P(JointStagesTest, VelocityAndAccelerationRowsAreTheRowsDerivatives) {
  int checked = 0;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> draw(-1.5, 1.5);
  for (const auto& [name, built_system] : built_systems()) {
    const System& system = *built_system;
    GiNaC::exmap values = system.parameter_values();
    for (const auto& [constant, value] : system.constants()) values[constant] = value;
    std::vector<std::array<symbol, 3>> maximal;
    for (const BodySystem& b : system.bodies()) {
      maximal.push_back({b.x.q, b.x.q_dot, b.x.q_ddot});
      maximal.push_back({b.y.q, b.y.q_dot, b.y.q_ddot});
      if (b.rotates) maximal.push_back({b.theta.q, b.theta.q_dot, b.theta.q_ddot});
    }
    for (const auto& m : maximal)
      for (const symbol& s : m) values[s] = draw(rng);
    // The rows at tau, the rates and accelerations kept.
    auto at_tau = [&](double tau) {
      GiNaC::exmap v = values;
      for (const auto& m : maximal) {
        const double q = GiNaC::ex_to<GiNaC::numeric>(values[m[0]]).to_double();
        const double rate = GiNaC::ex_to<GiNaC::numeric>(values[m[1]]).to_double();
        const double acceleration = GiNaC::ex_to<GiNaC::numeric>(values[m[2]]).to_double();
        v[m[0]] = q + rate * tau + acceleration * tau * tau / 2;
      }
      return v;
    };
    for (const JointSystem& js : system.joints()) {
      if (system.mechanism().joints[static_cast<std::size_t>(js.index)].type != GetParam()) continue;
      ++checked;
      for (const ex& row : js.constraints) {
        const ex velocity = system.time_derivative(row);
        const ex acceleration = system.time_derivative(velocity);
        const double h1 = 1e-4, h2 = 1e-3;
        const double dv = (evaluate(row, at_tau(h1)) - evaluate(row, at_tau(-h1))) / (2 * h1);
        const double da =
            (evaluate(row, at_tau(h2)) - 2 * evaluate(row, at_tau(0)) + evaluate(row, at_tau(-h2))) / (h2 * h2);
        // Truncation h^2 |Phi'''| / 6 and h^2 |Phi''''| / 12 with derivatives of order 10-100 here.
        EXPECT_NEAR(evaluate(velocity, values), dv, 1e-5) << name << ": " << row;
        EXPECT_NEAR(evaluate(acceleration, values), da, 1e-3) << name << ": " << row;
      }
    }
  }
  EXPECT_GT(checked, 0) << "no built mechanism has a " << joint_type_name(GetParam())
                        << " joint: add one to tests/support/mechanisms_in_code.hpp";
}

INSTANTIATE_TEST_SUITE_P(EveryType, JointStagesTest, ::testing::ValuesIn(all_types()),
                         [](const ::testing::TestParamInfo<JointType>& type) {
                           std::string name = joint_type_name(type.param);  // "pin-slot" as pin_slot
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// --- joint_pin.cpp ------------------------------------------------------------------

TEST(JointPin, DrawnAsAMarker) { EXPECT_EQ(joint_stages(JointType::pin).drawing, JointDrawing::marker); }

TEST(JointPin, RowsAreTheGapBetweenItsPoints) {
  // a at (1, 2) turned a quarter: its point (0.3, -0.1) is at (1.1, 2.3) in the world.
  const JointEnds ends = ends_of(JointType::pin, {{1, 2}, GiNaC::Pi / 2}, {{ex(1.1 + 0.2), ex(2.3 - 0.15 + 0.5)}, 0});
  const std::vector<ex> rows = joint_stages(JointType::pin).rows(ends);
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_NEAR(evaluate(rows[0], {}), 0, kExact);
  EXPECT_NEAR(evaluate(rows[1], {}), -0.5, kExact);
}

TEST(JointPin, ForceIsItsTwoUnknownsAndNoMoment) {
  const JointStages& pin = joint_stages(JointType::pin);
  const std::vector<ForceUnknown> only = pin.unknowns(joint_of(JointType::pin), true, "block 1");
  ASSERT_EQ(only.size(), 2U);
  EXPECT_EQ(only[0].key, "force_x");
  EXPECT_EQ(only[0].spelling.ascii, "Fx");  // the homework's only joint: the spec's name
  EXPECT_EQ(only[1].meaning, "pin force on block 1, y");
  EXPECT_EQ(pin.unknowns(joint_of(JointType::pin), false, "block 1")[1].spelling.latex, "F_{y,J}");
  const symbol fx("fx"), fy("fy");
  JointSystem js;
  js.unknowns = {fx, fy};
  pin.force(js, ends_of(JointType::pin, {}, {}));
  EXPECT_TRUE((js.force.x - fx).is_zero());
  EXPECT_TRUE((js.force.y - fy).is_zero());
  EXPECT_TRUE(js.moment.is_zero());
  EXPECT_FALSE(pin.force_at_point_b);
  EXPECT_FALSE(pin.moment_column);
  EXPECT_STREQ(pin.constraint_unit, "m");
}

// --- joint_slider.cpp ---------------------------------------------------------------

TEST(JointSlider, DrawnAsARail) { EXPECT_EQ(joint_stages(JointType::slider).drawing, JointDrawing::rail); }

TEST(JointSlider, TravelAndRowsAlongTheTurnedAxis) {
  // a turned a quarter: the axis (2, 1) of its frame is u = (-1, 2)/sqrt(5) in the world,
  // the normal k x u = (-2, -1)/sqrt(5).
  const Placement a{{0, 0}, GiNaC::Pi / 2};
  const double k = 1 / std::sqrt(5.0);
  // a's point (0.3, -0.1) is at (0.1, 0.3) in the world; b's point (-0.2, 0.15) on b
  // turned a quarter is (-0.15, -0.2) from b's centre.
  const double travel = 0.7;
  const Placement b{{ex(0.1 - travel * k + 0.15), ex(0.3 + 2 * travel * k + 0.2)}, GiNaC::Pi / 2};
  const JointStages& slider = joint_stages(JointType::slider);
  const JointEnds ends = ends_of(JointType::slider, a, b);
  EXPECT_NEAR(evaluate(slider.coordinate(ends), {}), travel, kExact);
  const std::vector<ex> rows = slider.rows(ends);
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_NEAR(evaluate(rows[0], {}), 0, kExact);
  EXPECT_NEAR(evaluate(rows[1], {}), 0, kExact);
  // Off the line by 0.1 along the normal; turned by 0.2 from a.
  const Placement off{{b.position.x - 0.2 * k, b.position.y - 0.1 * k}, b.angle};
  EXPECT_NEAR(evaluate(slider.rows(ends_of(JointType::slider, a, off))[0], {}), 0.1, kExact);
  const Placement turned{b.position, b.angle + 0.2};
  EXPECT_NEAR(evaluate(slider.rows(ends_of(JointType::slider, a, turned))[1], {}), 0.2, kExact);
}

TEST(JointSlider, ForceAcrossTheAxisAndAMoment) {
  const JointStages& slider = joint_stages(JointType::slider);
  const std::vector<ForceUnknown> unknowns = slider.unknowns(joint_of(JointType::slider), true, "the ground");
  ASSERT_EQ(unknowns.size(), 2U);
  EXPECT_EQ(unknowns[0].key, "normal");
  EXPECT_EQ(unknowns[1].key, "moment");
  EXPECT_EQ(unknowns[1].unit, "N m");
  const symbol n("n"), m("m");
  JointSystem js;
  js.unknowns = {n, m};
  slider.force(js, ends_of(JointType::slider, {}, {}));  // a unturned: normal (-1, 2)/sqrt(5)
  const double k = 1 / std::sqrt(5.0);
  EXPECT_NEAR(evaluate(js.force.x, {{n, 3.0}}), -3 * k, kExact);
  EXPECT_NEAR(evaluate(js.force.y, {{n, 3.0}}), 6 * k, kExact);
  EXPECT_TRUE((js.moment - m).is_zero());
  EXPECT_TRUE(slider.force_at_point_b);
  EXPECT_TRUE(slider.moment_column);
  ASSERT_NE(slider.own, nullptr);
  EXPECT_STREQ(slider.own->base, "s");
}

// --- joint_weld.cpp -----------------------------------------------------------------

TEST(JointWeld, DrawnAsABracket) { EXPECT_EQ(joint_stages(JointType::weld).drawing, JointDrawing::bracket); }

TEST(JointWeld, RowsAreTheGapAndTheAngleItHolds) {
  // a at (1, 2) turned a quarter: its point (0.3, -0.1) is at (1.1, 2.3); b at 0.6 more
  // (the angle it holds): its point (-0.2, 0.15) is R(pi/2 + 0.6) (-0.2, 0.15) from b's centre.
  const double th_b = M_PI / 2 + 0.6;
  const double bx = -0.2 * std::cos(th_b) - 0.15 * std::sin(th_b), by = -0.2 * std::sin(th_b) + 0.15 * std::cos(th_b);
  const Placement a{{1, 2}, GiNaC::Pi / 2};
  const JointEnds ends = ends_of(JointType::weld, a, {{ex(1.1 - bx), ex(2.3 - by)}, GiNaC::Pi / 2 + 0.6});
  const std::vector<ex> rows = joint_stages(JointType::weld).rows(ends);
  ASSERT_EQ(rows.size(), 3U);
  for (const ex& row : rows) EXPECT_NEAR(evaluate(row, {}), 0, kExact) << row;
  // b turned 0.2 further: the angle row reads 0.2; b moved up by 0.5: the y row -0.5.
  const JointEnds moved = ends_of(JointType::weld, a, {{ex(1.1 - bx), ex(2.3 - by + 0.5)}, GiNaC::Pi / 2 + 0.8});
  EXPECT_NEAR(evaluate(joint_stages(JointType::weld).rows(moved)[2], {}), 0.2, kExact);
  const JointEnds shifted = ends_of(JointType::weld, a, {{ex(1.1 - bx), ex(2.3 - by + 0.5)}, GiNaC::Pi / 2 + 0.6});
  EXPECT_NEAR(evaluate(joint_stages(JointType::weld).rows(shifted)[1], {}), -0.5, kExact);
}

TEST(JointWeld, ForceAndMomentAreItsThreeUnknowns) {
  const JointStages& weld = joint_stages(JointType::weld);
  const std::vector<ForceUnknown> unknowns = weld.unknowns(joint_of(JointType::weld), true, "body 1");
  ASSERT_EQ(unknowns.size(), 3U);
  EXPECT_EQ(unknowns[0].key, "force_x");
  EXPECT_EQ(unknowns[1].key, "force_y");
  EXPECT_EQ(unknowns[2].key, "moment");
  EXPECT_EQ(unknowns[2].unit, "N m");
  EXPECT_EQ(unknowns[0].meaning, "weld force on body 1, x");
  const symbol fx("fx"), fy("fy"), m("m");
  JointSystem js;
  js.unknowns = {fx, fy, m};
  weld.force(js, ends_of(JointType::weld, {}, {}));
  EXPECT_TRUE((js.force.x - fx).is_zero());
  EXPECT_TRUE((js.force.y - fy).is_zero());
  EXPECT_TRUE((js.moment - m).is_zero());
  EXPECT_FALSE(weld.force_at_point_b);
  EXPECT_TRUE(weld.moment_column);
  EXPECT_EQ(weld.own, nullptr);
  EXPECT_EQ(weld.driven, nullptr);
  EXPECT_FALSE(drivable(JointType::weld));
  EXPECT_EQ(joint_type_info(JointType::weld).rows, 3);
}

// --- joint_rolling.cpp ----------------------------------------------------------------

TEST(JointRolling, DrawnAsASurface) { EXPECT_EQ(joint_stages(JointType::rolling).drawing, JointDrawing::rolling); }

// On the ground's line along x through the origin, radius R: the centre at height R and at
// -R th_b along the line (rolling without slip, counter-clockwise rolls to -x).
TEST(JointRolling, RowsAreTheHeightAndTheRolledDistance) {
  const symbol x("x"), y("y"), th("th");
  JointEnds ends;
  ends.b = {{x, y}, th};
  ends.axis = {ex(3), ex(0)};
  ends.radius = ex(0.4);
  const std::vector<ex> rows = joint_stages(JointType::rolling).rows(ends);
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_TRUE((rows[0] - (y - 0.4)).expand().is_zero()) << rows[0];
  EXPECT_TRUE((rows[1] - (x + 0.4 * th)).expand().is_zero()) << rows[1];
}

// F = N n + f u on bodies[0], as if at C with the moment R f (the force at the contact point).
TEST(JointRolling, ForceIsNormalAndFrictionAtTheContactPoint) {
  const JointStages& rolling = joint_stages(JointType::rolling);
  const std::vector<ForceUnknown> unknowns = rolling.unknowns(joint_of(JointType::rolling), false, "body 1");
  ASSERT_EQ(unknowns.size(), 2U);
  EXPECT_EQ(unknowns[0].key, "normal");
  EXPECT_EQ(unknowns[1].key, "friction");
  const symbol n("N"), f("f"), th("th");
  JointEnds ends;
  ends.a.angle = th;
  ends.axis = {ex(0), ex(2)};  // u = (0, 1) turned by th, n = (-1, 0) turned by th
  ends.radius = ex(0.4);
  JointSystem js;
  js.unknowns = {n, f};
  rolling.force(js, ends);
  EXPECT_TRUE((js.force.x - (-n * GiNaC::cos(th) - f * GiNaC::sin(th))).expand().is_zero()) << js.force.x;
  EXPECT_TRUE((js.force.y - (-n * GiNaC::sin(th) + f * GiNaC::cos(th))).expand().is_zero()) << js.force.y;
  EXPECT_TRUE((js.moment - 0.4 * f).expand().is_zero()) << js.moment;
  EXPECT_TRUE(rolling.force_at_point_b);
  EXPECT_FALSE(rolling.moment_column);
  EXPECT_TRUE(rolling.unknown_columns);
  EXPECT_EQ(joint_type_info(JointType::rolling).rows, 2);
}

// --- joint_pin_slot.cpp ---------------------------------------------------------------

TEST(JointPinSlot, DrawnAsASlot) { EXPECT_EQ(joint_stages(JointType::pin_slot).drawing, JointDrawing::slot); }

// The slot of a (at (1, 2), turned pi/2: its axis [2, 0] points along +y in the world,
// n along -x) through its point A at (0.3, 0) of a's frame, so at (1, 2.3) in the world:
// the row is n . (P - A) = -(P.x - 1), the travel u . (P - A) = P.y - 2.3, whatever b's angle.
TEST(JointPinSlot, RowIsTheDistanceAcrossTheSlotAndTheTravelAlongIt) {
  const symbol x("x"), y("y"), th("th");
  JointEnds ends;
  ends.a = {{ex(1), ex(2)}, GiNaC::Pi / 2};
  ends.b = {{x, y}, th};
  ends.point_a = {ex(0.3), ex(0)};
  ends.axis = {ex(2), ex(0)};
  const JointStages& slot = joint_stages(JointType::pin_slot);
  const std::vector<ex> rows = slot.rows(ends);
  ASSERT_EQ(rows.size(), 1U);
  EXPECT_TRUE((rows[0] + (x - 1)).expand().is_zero()) << rows[0];
  for (const double at : {-0.4, 0.9})  // 2.3 in binary: compared as numbers
    EXPECT_NEAR(evaluate(slot.coordinate(ends), {{x, 0.2}, {y, at}, {th, 0.7}}), at - 2.3, kExact);
  EXPECT_EQ(joint_type_info(JointType::pin_slot).rows, 1);
}

// N n on bodies[0] at the pin, no moment; written as JOINT.normal; not drivable; in the
// tree the travel s and the child's own angle.
TEST(JointPinSlot, ForceIsAcrossTheSlotAtThePin) {
  const JointStages& slot = joint_stages(JointType::pin_slot);
  const std::vector<ForceUnknown> unknowns = slot.unknowns(joint_of(JointType::pin_slot), false, "body 1");
  ASSERT_EQ(unknowns.size(), 1U);
  EXPECT_EQ(unknowns[0].key, "normal");
  const symbol n("N"), th("th");
  JointEnds ends;
  ends.a.angle = th;
  ends.axis = {ex(3), ex(0)};  // u = (cos th, sin th), n = (-sin th, cos th)
  JointSystem js;
  js.unknowns = {n};
  slot.force(js, ends);
  EXPECT_TRUE((js.force.x + n * GiNaC::sin(th)).expand().is_zero()) << js.force.x;
  EXPECT_TRUE((js.force.y - n * GiNaC::cos(th)).expand().is_zero()) << js.force.y;
  EXPECT_TRUE(js.moment.is_zero());
  EXPECT_TRUE(slot.force_at_point_b);
  EXPECT_FALSE(slot.moment_column);
  EXPECT_TRUE(slot.unknown_columns);
  EXPECT_FALSE(drivable(JointType::pin_slot));
  EXPECT_EQ(slot.driven, nullptr);
  EXPECT_EQ(joint_type_info(JointType::pin_slot).motion, JointMotion::slotted);
  EXPECT_FALSE(joint_type_info(JointType::pin_slot).keeps_angle);
}

// In the tree it adds its travel, then the child's angle (a point mass: the travel alone);
// closing a loop it is one row.
TEST(JointPinSlot, TreeCoordinatesAndLoopRows) {
  const auto keys = [](const System& system) {
    std::vector<std::string> out;
    for (const GeneralizedCoordinate& g : system.coordinates()) out.push_back(g.coordinate.key);
    return out;
  };
  const System tree(built::pin_slot_tree());
  EXPECT_EQ(keys(tree),
            (std::vector<std::string>{"bar.theta", "Q.s", "block.theta", "Q2.s", "wheel.theta", "Q3.s", "bar2.theta"}));
  EXPECT_TRUE(tree.tree().loop_joints.empty());
  const System loop(built::scotch_yoke());
  EXPECT_EQ(keys(loop), (std::vector<std::string>{"crank.theta", "X.s"}));
  ASSERT_EQ(loop.tree().loop_joints, std::vector<int>{2});
  EXPECT_EQ(loop.joints()[2].constraints.size(), 1U);
  EXPECT_EQ(degrees_of_freedom(loop.mechanism()), 1);
  // The slotted bar as the child (bodies[0] of Q), the pin F closing the loop.
  const System child_slotted(built::pin_slot_loop());
  EXPECT_EQ(keys(child_slotted), (std::vector<std::string>{"crank.theta", "rocker.theta", "Q.s", "yoke.theta"}));
  EXPECT_EQ(child_slotted.tree().loop_joints, std::vector<int>{3});
  EXPECT_EQ(degrees_of_freedom(child_slotted.mechanism()), 2);
}

// --- joint_gear.cpp -----------------------------------------------------------------

TEST(JointGear, DrawnAsPitchCirclesAndOnlyClosesLoops) {
  EXPECT_EQ(joint_stages(JointType::gear).drawing, JointDrawing::gear);
  EXPECT_FALSE(carries_body(joint_type_info(JointType::gear).motion));
  EXPECT_EQ(joint_type_info(JointType::gear).rows, 1);
  EXPECT_FALSE(drivable(JointType::gear));
  EXPECT_TRUE(joint_type_info(JointType::gear).keeps_angle);  // neither gear a point mass
}

// r1 (th_a - th_c) + s r2 (th_b - th_c) - c_G, s = -1 for an internal mesh.
TEST(JointGear, RowIsTheRolledArcsLessTheConstant) {
  const symbol a("a"), b("b"), c("c"), k("k");
  JointEnds ends = ends_of(JointType::gear, {{0, 0}, a}, {{0, 0}, b});
  ends.carrier.angle = c;
  ends.constant = k;
  for (const int s : {1, -1}) {
    ends.mesh = s;
    const std::vector<ex> rows = joint_stages(JointType::gear).rows(ends);
    ASSERT_EQ(rows.size(), 1U);
    EXPECT_TRUE((rows[0] - (0.3 * (a - c) + s * 0.5 * (b - c) - k)).expand().is_zero()) << rows[0];
  }
}

// Gears a and b pinned to a carrier that moves (its centres C_a, C_b r1 + s r2 apart, fixed
// in it), each turning at its own rate: the tooth force's wrench (on a at C_a, the opposite
// on b at C_a too) works at F times the rate of the row, as the row's multiplier would:
// the rest of it is a pair of forces at the pins, which the pins take.
TEST(JointGear, ForceDoesTheRowsWorkOnPinnedGears) {
  const JointStages& gear = joint_stages(JointType::gear);
  const symbol t("t"), F("F");
  for (const int s : {1, -1}) {
    const Placement carrier{{0.3 + 0.2 * GiNaC::sin(1.3 * t), -0.4 + 0.1 * GiNaC::cos(0.7 * t)},
                            0.2 + 0.5 * GiNaC::sin(0.9 * t)};
    const ex apart = 0.3 + s * ex(0.5);
    const Vec2 ca = world_point(carrier, {ex(0.1), ex(0.2)});
    const Vec2 cb = world_point(carrier, {0.1 + apart * std::cos(0.8), 0.2 + apart * std::sin(0.8)});
    JointEnds ends = ends_of(JointType::gear, {}, {});
    ends.mesh = s;
    ends.carrier = carrier;
    ends.a.angle = 0.4 + 1.1 * GiNaC::sin(1.7 * t);
    ends.b.angle = -0.3 + 0.6 * GiNaC::cos(1.2 * t);
    ends.a.position = ca - rotate(ends.a.angle, ends.point_a);
    ends.b.position = cb - rotate(ends.b.angle, ends.point_b);
    JointSystem js;
    js.unknowns = {F};
    gear.force(js, ends);
    ASSERT_TRUE(gear.opposite_at_point_a);
    auto velocity = [&](const Placement& p, const Vec2& r) {
      const ex omega = GiNaC::diff(p.angle, t);
      return Vec2{GiNaC::diff(p.position.x, t) - omega * (r.y - p.position.y),
                  GiNaC::diff(p.position.y, t) + omega * (r.x - p.position.x)};
    };
    const Vec2 va = velocity(ends.a, ca), vb = velocity(ends.b, ca);
    const ex power = js.force.x * (va.x - vb.x) + js.force.y * (va.y - vb.y) +
                     js.moment * (GiNaC::diff(ends.a.angle, t) - GiNaC::diff(ends.b.angle, t));
    const ex row_rate = GiNaC::diff(gear.rows(ends).at(0), t);
    for (const double time : {0.1, 0.7, 1.9})
      EXPECT_NEAR(evaluate(power - F * row_rate, {{t, time}, {F, 1.7}}), 0, kExact) << "s " << s << " t " << time;
    // The tooth force lies along the common tangent: across the line of centres.
    const ex along = js.force.x * (cb.x - ca.x) + js.force.y * (cb.y - ca.y);
    EXPECT_NEAR(evaluate(along, {{t, 0.4}, {F, 1.7}}), 0, kExact);
    EXPECT_TRUE((js.moment - 0.3 * F).expand().is_zero()) << js.moment;
  }
}

}  // namespace
}  // namespace linkage::sym
