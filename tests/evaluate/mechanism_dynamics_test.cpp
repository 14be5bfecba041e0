// The compiled dynamics of any mechanism: the tree's recursion equals the compiled rows,
// the three cases give the same motion of every body, and a projection lands on the
// constraints. (Against the homework's closed form: bench/tests/general_cases_test.cpp.)
#include "evaluate/mechanism_dynamics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "evaluate/tree_dynamics.hpp"
#include "model/mechanism_toml.hpp"
#include "support/long_chain.hpp"
#include "support/mechanisms_in_code.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

/// Case 3 of a tree runs the O(n) recursion (and a Schur complement for loops); Case 2 the
/// compiled rows by LU. Same accelerations at five random states.
void expect_recursion_equals_rows(const built::Named& named, std::mt19937& rng) {
  const sym::System system(named.make());
  eval::MechanismDynamics reduced(system, CaseId::reduced);
  const eval::MechanismDynamics generalized(system, CaseId::generalized);
  reduced.solve_by_structure(false);  // small systems would take the structured solve
  for (int trial = 0; trial < 5; ++trial) {
    const GiNaC::exmap state = built::random_state(system, rng);
    const Eigen::VectorXd y = reduced.initial_state(state);
    Eigen::VectorXd fast, rows;
    ASSERT_TRUE(reduced.derivative(0.3 * trial, y, fast)) << named.name;
    ASSERT_TRUE(generalized.derivative(0.3 * trial, y, rows)) << named.name;
    const double scale = 1 + rows.cwiseAbs().maxCoeff();
    for (Eigen::Index i = 0; i < y.size(); ++i)
      EXPECT_NEAR(fast[i], rows[i], 1e-12 * scale) << named.name << " entry " << i << " trial " << trial;
  }
}

// Every mechanism built in code: pins, sliders, floating bases, springs, dampers, applied
// loads, closed loops.
TEST(MechanismDynamics, RecursionEqualsTheCompiledRows) {
  std::mt19937 rng(13);
  for (const built::Named& named : built::all_mechanisms()) expect_recursion_equals_rows(named, rng);
}

// A rolling joint in the tree turns its child about the moving contact point: the
// recursion takes it as a one-dof joint whose axis is that point (built::rolling_wheel_and_plank,
// above, has a disc on the ground's line and a line's body under a pinned drum).
TEST(MechanismDynamics, RecursionTakesARollingJoint) {
  EXPECT_TRUE(eval::TreeDynamics::applies(sym::System(built::rolling_wheel_and_plank())));
}

/// A disc rolling on a plank that swings on a pin (the line turns and its point moves), a
/// rod hanging from the disc, and a second disc under which a plank rolls, pinned to the
/// first plank's end: each of the recursion's rolling cases on a moving parent.
Mechanism rolling_on_moving_lines() {
  using namespace built;
  Mechanism m;
  m.name = "rolling_on_moving_lines";
  m.gravity = q("g");
  m.parameters = {{"g", 9.81, {}}, {"r", 0.15, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {
      rectangle("plank", "2", "1.2", "0.05", {{"P", {"-0.4", "0"}}, {"T", {"0.1", "0.025"}}, {"E", {"0.6", "0"}}}),
      disc("wheel", "0.7", "r", {{"C", {"0", "0"}}}), rod("bob", "0.3", "0.4", {{"A", {"-0.2", "0"}}}),
      disc("drum", "0.9", "0.2", {{"C", {"0", "0"}}}),
      rectangle("board", "0.4", "0.8", "0.04", {{"K", {"0.2", "-0.02"}}})};
  m.joints = {pin("P", "ground", "O", "plank", "P"), rolling("R1", "plank", "T", "wheel", "C", {"1", "0.2"}, "r"),
              pin("A", "wheel", "C", "bob", "A"), pin("E", "plank", "E", "drum", "C"),
              rolling("R2", "board", "K", "drum", "C", {"-1", "0"}, "0.2")};
  m.initial = {{"plank.theta", 0.2, {}},
               {"wheel.theta", 0.5, {}},
               {"bob.theta", -1.0, {}},
               {"drum.theta", 0.1, {}},
               {"board.theta", -0.3, {}}};
  return m;
}

TEST(MechanismDynamics, RecursionEqualsTheCompiledRowsRollingOnMovingLines) {
  std::mt19937 rng(29);
  ASSERT_TRUE(eval::TreeDynamics::applies(sym::System(rolling_on_moving_lines())));
  expect_recursion_equals_rows({"rolling_on_moving_lines", rolling_on_moving_lines}, rng);
}

// A pin-slot in the tree adds two coordinates, which the recursion takes as two nodes (a
// massless slider then a pin for the pin's body, a pin then a turned slider for the slot's):
// pin_slot_tree without its bead (a point mass, which no recursion node can carry through a
// pin) carries pin bodies; pin_slot_loop, closed by a pin, a slotted body.
Mechanism pin_slot_tree_of_rigid_bodies() {
  Mechanism m = built::pin_slot_tree();
  std::erase_if(m.bodies, [](const Body& b) { return b.name == "bead"; });
  std::erase_if(m.joints, [](const Joint& j) { return j.name == "Q2"; });
  std::erase_if(m.initial, [](const auto& entry) { return entry.key == "Q2.s"; });
  return m;
}

TEST(MechanismDynamics, RecursionEqualsTheCompiledRowsWithPinSlotsInTheTree) {
  EXPECT_FALSE(eval::TreeDynamics::applies(sym::System(built::pin_slot_tree())));  // the bead
  std::mt19937 rng(31);
  for (const built::Named& named : {built::Named{"pin_slot_tree_of_rigid_bodies", pin_slot_tree_of_rigid_bodies},
                                    built::Named{"pin_slot_loop", built::pin_slot_loop}}) {
    ASSERT_TRUE(eval::TreeDynamics::applies(sym::System(named.make()))) << named.name;
    expect_recursion_equals_rows(named, rng);
  }
}

/// A tree whose bodies have several children: an arm pinned to the ground off its centre,
/// a rod and a plate pinned at its ends, a collar sliding along it on a spring-damper, a
/// disc pinned to the rod's tip; a damped pin, a torque and a force that vary with t.
Mechanism branched() {
  Mechanism m;
  m.name = "branched";
  m.gravity = built::q("g");
  m.parameters = {{"L", 0.8, {}}, {"l", 0.4, {}}, {"m", 0.6, {}}, {"R", 0.05, {}},
                  {"k", 12, {}},  {"c", 0.3, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {built::q("0.1"), built::q("-0.2")}, {}}};
  m.bodies = {built::rod("arm", "m", "L", {{"O", {"-L/4", "0"}}, {"A", {"-L/2", "0"}}, {"B", {"L/2", "0"}}}),
              built::rod("left", "0.3", "l", {{"A", {"-l/2", "0"}}, {"T", {"l/2", "0"}}}),
              built::rectangle("right", "0.4", "l", "0.1", {{"B", {"-l/2", "0.05"}}, {"F", {"l/2", "0"}}}),
              built::disc("collar", "0.2", "R", {{"C", {"0", "0"}}}),
              built::disc("tip", "0.1", "R", {{"T", {"R", "0"}}})};
  Joint slider;
  slider.name = "sleeve";
  slider.type = JointType::slider;
  slider.bodies = {"arm", "collar"};
  slider.points = {"O", "C"};
  slider.axis = Vector2Quantity{built::q("1"), built::q("0")};
  m.joints = {built::pin("O", "ground", "O", "arm", "O"), built::pin("A", "arm", "A", "left", "A"),
              built::pin("B", "arm", "B", "right", "B"), slider, built::pin("T", "left", "T", "tip", "T")};
  m.joints[2].damping = built::q("0.05");
  m.springs = {built::spring("k1", "arm.O", "collar.C", "k", "0.2", "c")};
  m.torques = {{"tip", built::q("0.2*sin(t)"), {}}};
  m.forces = {{"right", "F", {built::q("0.3*cos(2*t)"), built::q("0")}, {}}};
  return m;
}

/// The same tree floating free, no gravity: a rotating base with four children.
Mechanism floating_branched() {
  Mechanism m = branched();
  m.name = "floating-branched";
  m.gravity.reset();
  m.joints.erase(m.joints.begin());
  return m;
}

// Bodies with several children (the siblings' articulated inertias summed in the parent),
// under the ground and on a floating base.
TEST(MechanismDynamics, RecursionEqualsTheCompiledRowsOnBranchedTrees) {
  std::mt19937 rng(31);
  for (const built::Named& named : {built::Named{"branched", branched}, built::Named{"floating", floating_branched}})
    expect_recursion_equals_rows(named, rng);
}

// A chain of eight rods of different lengths and masses: every step of the recursion takes
// its parent from the one before.
TEST(MechanismDynamics, RecursionEqualsTheCompiledRowsOnAChain) {
  std::vector<test::Rod> rods = test::leaning_rods(8);
  for (std::size_t i = 0; i < rods.size(); ++i) {
    rods[i].length = 0.1 + 0.02 * static_cast<double>(i);
    rods[i].mass = 0.3 - 0.025 * static_cast<double>(i);
  }
  std::mt19937 rng(47);
  expect_recursion_equals_rows({"chain", [&] { return read_mechanism(test::chain_toml(rods), "chain.toml"); }}, rng);
}

// Two rods welded square (welded_pendulum: rod 1 of l1, m1 from the pin O; rod 2 of l2, m2
// welded at rod 1's tip at +pi/2) swing as one rigid L about O: I_O th'' = -g sum m x_c,
// I_O = m1 l1^2/3 + m2 l2^2/12 + m2 (l1^2 + l2^2/4), x_c of rod 2 = l1 cos th - (l2/2) sin th.
// Every case's sample (a dense solve) at any rate; Case 3's derivative by the structured
// solve and by the O(n) recursion.
TEST(JointWeld, LPendulumSwingsAsOneRigidBody) {
  const sym::System system(built::welded_pendulum());
  const double l1 = 0.3, m1 = 0.2, l2 = 0.2, m2 = 0.15, g = 9.81;
  const double inertia = m1 * l1 * l1 / 3 + m2 * l2 * l2 / 12 + m2 * (l1 * l1 + l2 * l2 / 4);
  for (const double theta : {-0.9, 0.4, 2.5})
    for (CaseId id : kAllCases)
      for (const bool structured : {true, false}) {
        eval::MechanismDynamics dynamics(system, id);
        dynamics.solve_by_structure(structured);
        GiNaC::exmap state = system.initial_state();
        for (auto& [symbol, value] : state) {
          const std::string name = GiNaC::ex_to<GiNaC::symbol>(symbol).get_name();
          if (name == "1.theta") value = theta;
          if (name == "1.theta_dot") value = 1.7;
        }
        const Eigen::VectorXd y = dynamics.initial_state(state);
        eval::MechanismSample s;
        dynamics.sample(0, y, s, true);
        const double expected =
            -g * (m1 * l1 / 2 * std::cos(theta) + m2 * (l1 * std::cos(theta) - l2 / 2 * std::sin(theta))) / inertia;
        EXPECT_NEAR(s.accelerations[2], expected, 1e-12) << "Case " << static_cast<int>(id) + 1 << " th " << theta;
        EXPECT_NEAR(s.accelerations[5], expected, 1e-12) << "rod 2 turns with rod 1";
        EXPECT_NEAR(s.pose[5] - s.pose[2], M_PI / 2, 1e-12);
        if (id == CaseId::reduced) {  // y = (th1, th1'): the O(n) recursion unstructured
          Eigen::VectorXd dydt;
          ASSERT_TRUE(dynamics.derivative(0, y, dydt));
          EXPECT_NEAR(dydt[1], expected, 1e-12) << "structured " << structured;
        }
        EXPECT_NEAR(s.rates[5], 1.7, 1e-12);
        // The weld's force and moment on rod 1 (what rod 2 exerts): rod 2's Newton-Euler
        // rows with its centre r2 = l1 e(th) + (l2/2) e(th + pi/2).
        const double c = std::cos(theta), sn = std::sin(theta), w2 = 1.7 * 1.7;
        const double r2x = l1 * c - l2 / 2 * sn, r2y = l1 * sn + l2 / 2 * c;
        const double a2x = -expected * r2y - w2 * r2x, a2y = expected * r2x - w2 * r2y;
        const double fx = -m2 * a2x, fy = -m2 * (a2y + g);
        const double dx = l2 / 2 * sn, dy = -l2 / 2 * c;  // the corner A from rod 2's centre
        const double moment = -m2 * l2 * l2 / 12 * expected - (dx * fy - dy * fx);
        EXPECT_NEAR(s.force[3], fx, 1e-11);
        EXPECT_NEAR(s.force[4], fy, 1e-11);
        EXPECT_NEAR(s.force[5], moment, 1e-11);
      }
}

// Each case's sample reports the same bodies' motion and joint forces at the same state.
TEST(MechanismDynamics, CasesAgreeOnEveryBodyAndJoint) {
  const std::vector<built::Named> mechanisms = built::all_mechanisms();
  std::mt19937 rng(5);
  for (const built::Named& named : mechanisms) {
    const sym::System system(named.make());
    const GiNaC::exmap state = built::random_state(system, rng);
    std::vector<eval::MechanismSample> samples;
    for (CaseId id : kAllCases) {
      const eval::MechanismDynamics dynamics(system, id);
      const Eigen::VectorXd y = dynamics.initial_state(state);
      eval::MechanismSample s;
      dynamics.sample(0.2, y, s);
      samples.push_back(s);
    }
    for (std::size_t k = 1; k < samples.size(); ++k) {
      for (std::size_t i = 0; i < samples[0].pose.size(); ++i) {
        EXPECT_NEAR(samples[k].pose[i], samples[0].pose[i], 1e-13) << named.name << " pose " << i;
        EXPECT_NEAR(samples[k].rates[i], samples[0].rates[i], 1e-12) << named.name << " rate " << i;
      }
      for (std::size_t i = 0; i < samples[0].force.size(); ++i)
        EXPECT_NEAR(samples[k].force[i], samples[0].force[i], 1e-11 * (1 + std::abs(samples[0].force[i])))
            << named.name << " Case " << k + 1 << " force " << i;
      EXPECT_NEAR(samples[k].kinetic, samples[0].kinetic, 1e-13) << named.name;
      EXPECT_NEAR(samples[k].potential, samples[0].potential, 1e-13) << named.name;
    }
  }
}

// The state carries W only where something does work: the two blocks have (q, q'), the
// spring-damper pendulum (q, q', W). A 2 n + 1 state still runs where W is not carried (W'
// = 0) and gives the same q' and q''; a damper's power is W' only where W is carried.
TEST(MechanismDynamics, StateCarriesWorkOnlyWhereSomethingDoesWork) {
  const sym::System blocks(load_mechanism("two-blocks"));
  const sym::System damped(load_mechanism("spring-pendulum"));
  for (CaseId id : kAllCases) {
    const eval::MechanismDynamics free(blocks, id);
    EXPECT_FALSE(free.carries_work());
    const Eigen::VectorXd y = free.initial_state(sym::checked_initial_state(blocks).state);
    ASSERT_EQ(y.size(), 2 * free.coordinates());
    Eigen::Vector<double, Eigen::Dynamic> with_w(y.size() + 1);
    with_w << y, 0.25;
    Eigen::VectorXd dy, dy_w;
    ASSERT_TRUE(free.derivative(0.1, y, dy));
    ASSERT_TRUE(free.derivative(0.1, with_w, dy_w));
    ASSERT_EQ(dy.size(), y.size());
    ASSERT_EQ(dy_w.size(), with_w.size());
    EXPECT_EQ(dy_w.head(y.size()), dy);
    EXPECT_EQ(dy_w[y.size()], 0);
    EXPECT_EQ(eval::work_of(y), 0);
    EXPECT_EQ(eval::work_of(with_w), 0.25);

    const eval::MechanismDynamics spring(damped, id);
    EXPECT_TRUE(spring.carries_work());
    Eigen::VectorXd z = spring.initial_state(sym::checked_initial_state(damped).state);
    ASSERT_EQ(z.size(), 2 * spring.coordinates() + 1);
    z.segment(spring.coordinates(), spring.coordinates()).setConstant(0.3);  // moving: the damper takes power
    Eigen::VectorXd dz;
    ASSERT_TRUE(spring.derivative(0.1, z, dz));
    eval::MechanismSample s;
    spring.sample(0.1, z, s);
    EXPECT_LT(s.power, 0);
    EXPECT_NEAR(dz[z.size() - 1], s.power, 1e-12 * (1 + std::fabs(s.power)));
  }
}

// Case 1 integrates every body's x, y, theta; its angular accelerations equal those of
// Case 3, which integrates the angles alone.
TEST(MechanismDynamics, MaximalAccelerationsAreTheGeneralizedOnes) {
  const sym::System system(built::double_pendulum());
  std::mt19937 rng(9);
  const GiNaC::exmap state = built::random_state(system, rng);
  const eval::MechanismDynamics maximal(system, CaseId::maximal), reduced(system, CaseId::reduced);
  const Eigen::VectorXd ym = maximal.initial_state(state), yr = reduced.initial_state(state);
  Eigen::VectorXd dm, dr;
  ASSERT_TRUE(maximal.derivative(0, ym, dm));
  ASSERT_TRUE(reduced.derivative(0, yr, dr));
  auto acceleration = [](const eval::MechanismDynamics& d, const Eigen::VectorXd& dydt, const std::string& name) {
    const auto& names = d.coordinate_names();
    const auto at = std::find(names.begin(), names.end(), name) - names.begin();
    return dydt[d.coordinates() + at];
  };
  for (const std::string name : {"1.theta", "2.theta"})
    EXPECT_NEAR(acceleration(maximal, dm, name), acceleration(reduced, dr, name), 1e-12) << name;
}

// A projection moves a perturbed four-bar back onto its loop, to round-off, and its rates
// onto the loop's velocity constraint.
TEST(MechanismDynamics, ProjectionClosesTheLoop) {
  const sym::System system(built::four_bar());
  const sym::ClosedState closed = sym::checked_initial_state(system);
  for (CaseId id : kAllCases) {
    const eval::MechanismDynamics dynamics(system, id);
    ASSERT_GT(dynamics.constraint_rows(), 0);
    Eigen::VectorXd y = dynamics.initial_state(closed.state);
    EXPECT_LT(dynamics.constraint_violation(0, y), 1e-9);
    y.head(dynamics.coordinates()).array() += 1e-3;
    y.segment(dynamics.coordinates(), dynamics.coordinates()).array() += 0.1;
    EXPECT_GT(dynamics.constraint_violation(0, y), 1e-4);
    EXPECT_LT(dynamics.project(0, y), 1e-14) << "Case " << case_number(id);
    EXPECT_LT(dynamics.constraint_violation(0, y), 1e-14);
  }
}

}  // namespace
}  // namespace linkage
