#pragma once
// Mechanisms built in code for the physics checks (energy_test, lagrange_test), with
// every kind of load: springs, linear and torsional dampers, applied forces and torques
// that depend on t; and seeded random states of any of them.
#include <cmath>
#include <functional>
#include <ostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "model/mechanism.hpp"
#include "symbolic/loop_closure.hpp"
#include "symbolic/system.hpp"

namespace linkage::built {

inline Quantity q(const std::string& text) { return {text, {}}; }

inline Body body(const std::string& name, Shape shape, const std::string& mass,
                 std::vector<std::pair<std::string, std::array<std::string, 2>>> points) {
  Body b;
  b.name = name;
  b.shape = shape;
  b.mass = q(mass);
  for (auto& [point, at] : points) b.points.push_back({point, {q(at[0]), q(at[1])}, {}});
  return b;
}

inline Body rod(const std::string& name, const std::string& mass, const std::string& length,
                std::vector<std::pair<std::string, std::array<std::string, 2>>> points) {
  Body b = body(name, Shape::rod, mass, std::move(points));
  b.length = q(length);
  return b;
}

inline Body rectangle(const std::string& name, const std::string& mass, const std::string& length,
                      const std::string& width,
                      std::vector<std::pair<std::string, std::array<std::string, 2>>> points) {
  Body b = body(name, Shape::rectangle, mass, std::move(points));
  b.length = q(length);
  b.width = q(width);
  return b;
}

inline Body disc(const std::string& name, const std::string& mass, const std::string& radius,
                 std::vector<std::pair<std::string, std::array<std::string, 2>>> points) {
  Body b = body(name, Shape::disc, mass, std::move(points));
  b.radius = q(radius);
  return b;
}

inline Joint pin(const std::string& name, const std::string& a, const std::string& pa, const std::string& b,
                 const std::string& pb) {
  Joint j;
  j.name = name;
  j.bodies = {a, b};
  j.points = {pa, pb};
  return j;
}

inline Joint weld(const std::string& name, const std::string& a, const std::string& pa, const std::string& b,
                  const std::string& pb, const std::string& angle) {
  Joint j = pin(name, a, pa, b, pb);
  j.type = JointType::weld;
  j.angle = q(angle);
  return j;
}

inline Spring spring(const std::string& name, const std::string& a, const std::string& b, const std::string& k,
                     const std::string& l0, const std::string& c) {
  auto ref = [](const std::string& text) {
    const auto dot = text.find('.');
    return PointRef{text.substr(0, dot), text.substr(dot + 1), {}};
  };
  return {name, {ref(a), ref(b)}, q(k), q(l0), q(c), {}};
}

/// The homework: two identical blocks joined by the pin P, free under gravity.
inline Mechanism homework() {
  Mechanism m;
  m.name = "two-blocks";
  m.gravity = q("g");
  m.parameters = {{"L", 0.3, {}}, {"w", 0.1, {}}, {"b", 0.04, {}}, {"m", 0.1, {}}, {"g", 9.81, {}}};
  m.definitions = {{"D", q("L/2 - b"), {}}};
  m.bodies = {rectangle("1", "m", "L", "w", {{"P", {"D", "0"}}}), rectangle("2", "m", "L", "w", {{"P", {"-D", "0"}}})};
  m.joints = {pin("P", "1", "P", "2", "P")};
  m.initial = {{"1.x", 1, {}},        {"1.y", 2, {}},        {"1.theta", 0.1, {}},      {"2.theta", 0.2, {}},
               {"1.x_dot", 0.15, {}}, {"1.y_dot", 0.25, {}}, {"1.theta_dot", 0.35, {}}, {"2.theta_dot", 0.45, {}}};
  return m;
}

/// A Grashof crank-rocker: crank 2, coupler 3 (twice as heavy), rocker 4; the pin B closes
/// the loop. The initial angles are only near a closed position.
inline Mechanism four_bar() {
  Mechanism m;
  m.gravity = q("g");
  m.parameters = {{"a", 0.1, {}}, {"b", 0.35, {}}, {"c", 0.3, {}}, {"d", 0.3, {}}, {"m", 0.1, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O2", {q("0"), q("0")}, {}}, {"O4", {q("d"), q("0")}, {}}};
  m.bodies = {rod("2", "m", "a", {{"O", {"-a/2", "0"}}, {"A", {"a/2", "0"}}}),
              rod("3", "2*m", "b", {{"A", {"-b/2", "0"}}, {"B", {"b/2", "0"}}}),
              rod("4", "m", "c", {{"O", {"-c/2", "0"}}, {"B", {"c/2", "0"}}})};
  m.joints = {pin("O2", "ground", "O2", "2", "O"), pin("A", "2", "A", "3", "A"), pin("O4", "ground", "O4", "4", "O"),
              pin("B", "3", "B", "4", "B")};
  m.initial = {{"2.theta", 1.0, {}}, {"3.theta", 0.3, {}}, {"4.theta", 1.6, {}}, {"2.theta_dot", 2.0, {}}};
  m.independent = {"2.theta"};
  return m;
}

/// Crank 2, connecting rod 3, piston 4 on the ground slider s along x; the pin B closes the loop.
inline Mechanism slider_crank() {
  Mechanism m;
  m.gravity = q("g");
  m.parameters = {{"r", 0.1, {}}, {"l", 0.35, {}}, {"m", 0.1, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}, {"Q", {q("0"), q("0")}, {}}};
  Body piston = rectangle("4", "m", "0.08", "0.05", {{"B", {"0", "0"}}});
  m.bodies = {rod("2", "m", "r", {{"O", {"-r/2", "0"}}, {"A", {"r/2", "0"}}}),
              rod("3", "m", "l", {{"A", {"-l/2", "0"}}, {"B", {"l/2", "0"}}}), piston};
  Joint slider = pin("s", "ground", "Q", "4", "B");
  slider.type = JointType::slider;
  slider.axis = Vector2Quantity{q("1"), q("0")};
  m.joints = {pin("O", "ground", "O", "2", "O"), slider, pin("A", "2", "A", "3", "A"), pin("B", "3", "B", "4", "B")};
  m.initial = {{"2.theta", 0.8, {}}, {"3.theta", -0.2, {}}, {"s.s", 0.43, {}}, {"2.theta_dot", 3.0, {}}};
  m.independent = {"2.theta"};
  return m;
}

/// Two rods from a ground pin.
inline Mechanism double_pendulum() {
  Mechanism m;
  m.name = "double-pendulum";
  m.gravity = q("g");
  m.parameters = {{"L1", 0.3, {}}, {"L2", 0.25, {}}, {"m1", 0.2, {}}, {"m2", 0.15, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {rod("1", "m1", "L1", {{"O", {"-L1/2", "0"}}, {"A", {"L1/2", "0"}}}),
              rod("2", "m2", "L2", {{"A", {"-L2/2", "0"}}})};
  m.joints = {pin("O", "ground", "O", "1", "O"), pin("A", "1", "A", "2", "A")};
  return m;
}

/// A rod, a rectangle pinned off its centre line and a disc pinned at its rim.
inline Mechanism triple_pendulum() {
  Mechanism m;
  m.name = "triple-pendulum";
  m.gravity = q("g");
  m.parameters = {{"L1", 0.4, {}}, {"L2", 0.3, {}}, {"w2", 0.08, {}}, {"R", 0.06, {}},
                  {"m1", 0.3, {}}, {"m2", 0.5, {}}, {"m3", 0.2, {}},  {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0.1"), q("0.2")}, {}}};
  m.bodies = {rod("1", "m1", "L1", {{"O", {"-L1/2", "0"}}, {"A", {"L1/2", "0"}}}),
              rectangle("2", "m2", "L2", "w2", {{"A", {"-L2/2", "w2/4"}}, {"B", {"L2/2", "-w2/2"}}}),
              disc("3", "m3", "R", {{"B", {"-R*cos(pi/5)", "R*sin(pi/5)"}}})};
  m.joints = {pin("O", "ground", "O", "1", "O"), pin("A", "1", "A", "2", "A"), pin("B", "2", "B", "3", "B")};
  return m;
}

/// A point mass on a spring-damper from a ground point, under gravity; `driven` adds a
/// horizontal force F0 sin(Omega t).
inline Mechanism spring_pendulum(bool driven) {
  Mechanism m;
  m.name = driven ? "driven-spring-pendulum" : "spring-pendulum";
  m.gravity = q("g");
  m.parameters = {{"m", 0.5, {}},  {"k", 40, {}},   {"l0", 0.3, {}},   {"c", 0.7, {}},
                  {"g", 9.81, {}}, {"F0", 1.5, {}}, {"Omega", 2.3, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {body("1", Shape::point, "m", {{"C", {"0", "0"}}})};
  m.springs = {spring("k1", "ground.O", "1.C", "k", "l0", "c")};
  if (driven) m.forces = {{"1", "C", {q("F0*sin(Omega*t)"), q("0")}, {}}};
  return m;
}

/// The double pendulum with a torsional spring-damper at its middle pin (rest angle not
/// zero), a torque on the second rod that varies with t, and a force at its tip.
inline Mechanism double_pendulum_loaded() {
  Mechanism m = double_pendulum();
  m.name = "double-pendulum-loaded";
  m.parameters.push_back({"kt", 2.5, {}});
  m.parameters.push_back({"ct", 0.4, {}});
  m.parameters.push_back({"tau0", 0.8, {}});
  m.parameters.push_back({"Omega", 1.7, {}});
  m.bodies[1].points.push_back({"T", {q("L2/2"), q("0")}, {}});
  m.joints[1].stiffness = q("kt");
  m.joints[1].damping = q("ct");
  m.joints[1].rest_angle = q("0.3");
  m.torques = {{"2", q("tau0*cos(Omega*t)"), {}}};
  m.forces = {{"2", "T", {q("0.5*t"), q("-0.2")}, {}}};
  return m;
}

/// A cart on a ground slider along (2, 1) with a spring-damper to the ground, a pendulum
/// pinned to it and a force on the cart that varies with t: a slider in the tree.
inline Mechanism cart_pendulum() {
  Mechanism m;
  m.name = "cart-pendulum";
  m.gravity = q("g");
  m.parameters = {{"M", 1.2, {}}, {"m", 0.3, {}}, {"l", 0.5, {}}, {"k", 20, {}}, {"c", 2, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"Q", {q("0"), q("0")}, {}}, {"A", {q("-0.5"), q("-0.25")}, {}}};
  m.bodies = {rectangle("cart", "M", "0.3", "0.1", {{"C", {"0", "0"}}, {"H", {"0.05", "0.05"}}}),
              rod("pole", "m", "l", {{"H", {"-l/2", "0"}}})};
  Joint slider;
  slider.name = "rail";
  slider.type = JointType::slider;
  slider.bodies = {"ground", "cart"};
  slider.points = {"Q", "C"};
  slider.axis = Vector2Quantity{q("2"), q("1")};
  m.joints = {slider, pin("H", "cart", "H", "pole", "H")};
  m.springs = {spring("k1", "ground.A", "cart.C", "k", "0.2", "c")};
  m.forces = {{"cart", "C", {q("3*cos(t)"), q("sin(2*t)")}, {}}};
  return m;
}

/// cart_pendulum with loads that depend on the state (issue 25): the spring stiffens with
/// the travel rail.s, the damper with the pole's angle, the cart's force and the pole's
/// torque read the rates.
inline Mechanism cart_pendulum_state_loads() {
  Mechanism m = cart_pendulum();
  m.name = "cart-pendulum-state-loads";
  m.springs = {spring("k1", "ground.A", "cart.C", "k*(1 + rail.s^2)", "0.2", "c*(1 + pole.theta^2)")};
  m.forces = {{"cart", "C", {q("-0.5*rail.s_dot + 0.3*pole.theta"), q("cart.y_dot")}, {}}};
  m.torques = {{"pole", q("-0.2*rail.s*pole.theta_dot + 0.1*pole.x"), {}}};
  return m;
}

/// double_pendulum_loaded with its pin spring's stiffness, rest angle and damping and its
/// torque in the state (issue 25).
inline Mechanism double_pendulum_state_loads() {
  Mechanism m = double_pendulum_loaded();
  m.name = "double-pendulum-state-loads";
  m.joints[1].stiffness = q("kt*(1 + 1.theta^2)");
  m.joints[1].rest_angle = q("0.3*1.theta_dot");
  m.joints[1].damping = q("ct*(2 + sin(2.theta))");
  m.torques = {{"2", q("tau0*(1 - 2.theta_dot/3)"), {}}};
  return m;
}

/// A rod turning about a ground pin, driven by a torque that varies with t, with a collar
/// sliding along it on a spring-damper from the pivot: a slider whose axis turns.
inline Mechanism arm_collar() {
  Mechanism m;
  m.name = "arm-collar";
  m.gravity = q("g");
  m.parameters = {{"L", 0.8, {}}, {"m", 0.6, {}}, {"mc", 0.25, {}}, {"r", 0.04, {}},
                  {"k", 12, {}},  {"c", 0.3, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {rod("arm", "m", "L", {{"O", {"-L/2", "0"}}}), disc("collar", "mc", "r", {{"C", {"0", "0"}}})};
  Joint slider;
  slider.name = "sleeve";
  slider.type = JointType::slider;
  slider.bodies = {"arm", "collar"};
  slider.points = {"O", "C"};
  slider.axis = Vector2Quantity{q("1"), q("0")};
  m.joints = {pin("O", "ground", "O", "arm", "O"), slider};
  m.springs = {spring("k1", "arm.O", "collar.C", "k", "0.3", "c")};
  m.torques = {{"arm", q("0.5*sin(t)"), {}}};
  return m;
}

/// Every tree joint written child first (bodies = [child, parent]): a cart on a rail along
/// (1, -0.5), a pole pinned to it and a point-mass bob pinned at the pole's tip.
inline Mechanism reversed_joints() {
  Mechanism m;
  m.name = "reversed-joints";
  m.gravity = q("g");
  m.parameters = {{"M", 0.9, {}}, {"m", 0.2, {}}, {"mb", 0.35, {}}, {"l", 0.6, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"Q", {q("0.2"), q("0.1")}, {}}};
  m.bodies = {rectangle("cart", "M", "0.3", "0.1", {{"C", {"0", "-0.05"}}, {"H", {"0.1", "0.05"}}}),
              rod("pole", "m", "l", {{"H", {"-l/2", "0"}}, {"T", {"l/2", "0"}}}),
              body("bob", Shape::point, "mb", {{"B", {"0", "0"}}})};
  Joint slider;
  slider.name = "rail";
  slider.type = JointType::slider;
  slider.bodies = {"cart", "ground"};
  slider.points = {"C", "Q"};
  slider.axis = Vector2Quantity{q("1"), q("-0.5")};
  m.joints = {slider, pin("H", "pole", "H", "cart", "H"), pin("T", "bob", "B", "pole", "T")};
  m.forces = {{"bob", "B", {q("0.4*t"), q("0")}, {}}};
  return m;
}

/// Two bodies joined by a pin with a torsional spring-damper and a linear spring-damper
/// between them, no gravity: nothing external, so p and H_O stay constant.
inline Mechanism floating_pair() {
  Mechanism m;
  m.name = "floating-pair";
  m.parameters = {{"m1", 0.4, {}}, {"m2", 0.7, {}}, {"L", 0.5, {}}, {"w", 0.1, {}}, {"R", 0.12, {}},
                  {"k", 30, {}},   {"c", 0.6, {}},  {"kt", 3, {}},  {"ct", 0.2, {}}};
  m.bodies = {rectangle("1", "m1", "L", "w", {{"P", {"L/2", "0"}}, {"S", {"-L/2", "w/2"}}}),
              disc("2", "m2", "R", {{"P", {"-R", "0"}}, {"S", {"0", "R"}}})};
  m.joints = {pin("P", "1", "P", "2", "P")};
  m.joints[0].stiffness = q("kt");
  m.joints[0].damping = q("ct");
  m.joints[0].rest_angle = q("-0.4");
  m.springs = {spring("k1", "1.S", "2.S", "k", "0.3", "c")};
  return m;
}

/// Two rods welded square into an L at rod 1's tip A, swinging from the ground pin O
/// (mechanisms/welded-pendulum.toml).
inline Mechanism welded_pendulum() {
  Mechanism m;
  m.name = "welded-pendulum";
  m.gravity = q("g");
  m.parameters = {{"l1", 0.3, {}}, {"m1", 0.2, {}}, {"l2", 0.2, {}}, {"m2", 0.15, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {rod("1", "m1", "l1", {{"O", {"-l1/2", "0"}}, {"A", {"l1/2", "0"}}}),
              rod("2", "m2", "l2", {{"A", {"-l2/2", "0"}}})};
  m.joints = {pin("O", "ground", "O", "1", "O"), weld("A", "1", "A", "2", "A", "pi/2")};
  m.initial = {{"1.theta", -0.9, {}}};
  return m;
}

/// A weld inside a chain, written child first: rod 1 from a ground pin, plate 2 welded to
/// its tip at pi/3 (bodies = [2, 1]) off the plate's centre, a disc pinned to the plate's
/// corner; a spring from the ground and a torque on the plate that depends on t.
inline Mechanism welded_chain() {
  Mechanism m;
  m.name = "welded-chain";
  m.gravity = q("g");
  m.parameters = {{"L", 0.4, {}},   {"m1", 0.3, {}}, {"m2", 0.5, {}}, {"a", 0.2, {}}, {"h", 0.1, {}},
                  {"m3", 0.25, {}}, {"R", 0.05, {}}, {"k", 20, {}},   {"c", 0.4, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}, {"S", {q("0.3"), q("0.2")}, {}}};
  m.bodies = {rod("1", "m1", "L", {{"O", {"-L/2", "0"}}, {"A", {"L/2", "0"}}}),
              rectangle("2", "m2", "a", "h", {{"A", {"-a/2", "h/4"}}, {"B", {"a/2", "-h/2"}}}),
              disc("3", "m3", "R", {{"B", {"R", "0"}}})};
  m.joints = {pin("O", "ground", "O", "1", "O"), weld("W", "2", "A", "1", "A", "pi/3"), pin("B", "2", "B", "3", "B")};
  m.springs = {spring("k1", "ground.S", "2.B", "k", "0.2", "c")};
  m.torques = {{"2", q("0.3*cos(2*t)"), {}}};
  m.initial = {{"1.theta", -1.0, {}}, {"3.theta", 0.4, {}}};
  return m;
}

/// A rectangle and a disc welded at -0.7 rad, floating free with a pin-free spring to the
/// ground: a floating root with a welded child.
inline Mechanism welded_floating() {
  Mechanism m;
  m.name = "welded-floating";
  m.gravity = q("g");
  m.parameters = {{"m1", 0.4, {}}, {"m2", 0.7, {}}, {"L", 0.5, {}}, {"w", 0.1, {}},
                  {"R", 0.12, {}}, {"k", 30, {}},   {"c", 0.6, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"S", {q("0"), q("0.5")}, {}}};
  m.bodies = {rectangle("1", "m1", "L", "w", {{"P", {"L/2", "0"}}, {"S", {"-L/2", "w/2"}}}),
              disc("2", "m2", "R", {{"P", {"-R", "0"}}})};
  m.joints = {weld("W", "1", "P", "2", "P", "-0.7")};
  m.springs = {spring("k1", "ground.S", "1.S", "k", "0.3", "c")};
  return m;
}

/// A free rod with a collar sliding along it on a spring-damper, no gravity: a floating
/// base with a slider child.
inline Mechanism floating_collar() {
  Mechanism m = arm_collar();
  m.name = "floating-collar";
  m.gravity.reset();
  m.joints.erase(m.joints.begin());  // the ground pin
  m.torques.clear();
  return m;
}

/// A Grashof four-bar (a closed loop) with a torsional damper at the crank's ground pin, a
/// spring-damper from the ground to the coupler and a torque on the crank that varies with t.
inline Mechanism four_bar_loaded() {
  Mechanism m;
  m.name = "four-bar-loaded";
  m.gravity = q("g");
  m.parameters = {{"a", 0.1, {}}, {"b", 0.35, {}}, {"c", 0.3, {}}, {"d", 0.3, {}},
                  {"m", 0.1, {}}, {"g", 9.81, {}}, {"k", 15, {}},  {"tau0", 0.3, {}}};
  m.ground_points = {{"O2", {q("0"), q("0")}, {}}, {"O4", {q("d"), q("0")}, {}}, {"S", {q("0.1"), q("0.4")}, {}}};
  m.bodies = {rod("2", "m", "a", {{"O", {"-a/2", "0"}}, {"A", {"a/2", "0"}}}),
              rod("3", "2*m", "b", {{"A", {"-b/2", "0"}}, {"B", {"b/2", "0"}}, {"M", {"0", "0"}}}),
              rod("4", "m", "c", {{"O", {"-c/2", "0"}}, {"B", {"c/2", "0"}}})};
  m.joints = {pin("O2", "ground", "O2", "2", "O"), pin("A", "2", "A", "3", "A"), pin("O4", "ground", "O4", "4", "O"),
              pin("B", "3", "B", "4", "B")};
  m.joints[0].damping = q("0.05");
  m.springs = {spring("k1", "ground.S", "3.M", "k", "0.15", "0.2")};
  m.torques = {{"2", q("tau0*sin(3*t)"), {}}};
  m.initial = {{"2.theta", 1.0, {}}, {"3.theta", 0.3, {}}, {"4.theta", 1.6, {}}};
  m.independent = {"2.theta"};
  return m;
}

inline Joint rolling(const std::string& name, const std::string& a, const std::string& pa, const std::string& b,
                     const std::string& pb, std::array<std::string, 2> axis, const std::string& radius) {
  Joint j = pin(name, a, pa, b, pb);
  j.type = JointType::rolling;
  j.axis = Vector2Quantity{q(axis[0]), q(axis[1])};
  j.radius = q(radius);
  return j;
}

/// A wheel rolling down an incline of the ground with a rod hanging from its centre, and a
/// plank rolling on a drum pinned to the ground (the line's body is the tree's child).
inline Mechanism rolling_wheel_and_plank() {
  Mechanism m;
  m.name = "rolling";
  m.gravity = q("g");
  m.parameters = {{"r", 0.2, {}}, {"alpha", 0.3, {}}, {"l", 0.5, {}}, {"m", 0.7, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0.1"), q("-0.2")}, {}}, {"G", {q("1.5"), q("0.3")}, {}}};
  m.bodies = {disc("wheel", "m", "r", {{"C", {"0", "0"}}}), rod("bob", "0.3", "l", {{"A", {"-l/2", "0"}}}),
              disc("drum", "1.2", "0.3", {{"C", {"0", "0"}}}),
              rectangle("plank", "0.5", "1", "0.05", {{"K", {"0.1", "-0.025"}}})};
  m.joints = {rolling("R1", "ground", "O", "wheel", "C", {"cos(alpha)", "-sin(alpha)"}, "r"),
              pin("D", "ground", "G", "drum", "C"), pin("A", "wheel", "C", "bob", "A"),
              rolling("R2", "plank", "K", "drum", "C", {"-1", "0"}, "0.3")};
  m.initial = {{"wheel.theta", 0.3, {}}, {"bob.theta", -1.2, {}}, {"drum.theta", 0.1, {}}, {"plank.theta", 0.05, {}}};
  return m;
}

inline Joint pin_slot(const std::string& name, const std::string& a, const std::string& pa, const std::string& b,
                      const std::string& pb, std::array<std::string, 2> axis) {
  Joint j = pin(name, a, pa, b, pb);
  j.type = JointType::pin_slot;
  j.axis = Vector2Quantity{q(axis[0]), q(axis[1])};
  return j;
}

/// Pin-slots in the tree: a block whose pin P slides in the slot of a bar pinned to the
/// ground (Q adds Q.s and block.theta), a point-mass bead in a slanted slot of the ground
/// (Q2 adds Q2.s alone), and a disc whose slot, off its centre, carries the bar's end B
/// as the tree's child (bar2 reached from the disc: Q3.s and bar2.theta).
inline Mechanism pin_slot_tree() {
  Mechanism m;
  m.name = "pin-slot-tree";
  m.gravity = q("g");
  m.parameters = {{"l", 0.6, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}, {"S", {q("0.5"), q("-0.3")}, {}}, {"D", {q("-0.8"), q("0.2")}, {}}};
  Body bead = body("bead", Shape::point, "0.2", {{"P", {"0", "0"}}});
  m.bodies = {rod("bar", "0.4", "l", {{"O", {"-l/2", "0"}}, {"A", {"0.1", "0.02"}}}),
              rectangle("block", "0.3", "0.1", "0.06", {{"P", {"0.02", "-0.01"}}}), bead,
              disc("wheel", "0.5", "0.2", {{"C", {"0", "0"}}, {"T", {"0.05", "0.03"}}}),
              rod("bar2", "0.25", "0.4", {{"B", {"0.2", "0"}}})};
  m.joints = {pin("O", "ground", "O", "bar", "O"), pin_slot("Q", "bar", "A", "block", "P", {"1", "0"}),
              pin_slot("Q2", "ground", "S", "bead", "P", {"1", "1"}), pin("D", "ground", "D", "wheel", "C"),
              pin_slot("Q3", "wheel", "T", "bar2", "B", {"-0.3", "1"})};
  m.initial = {{"bar.theta", -0.7, {}},  {"Q.s", 0.12, {}},  {"block.theta", 0.4, {}}, {"Q2.s", -0.1, {}},
               {"wheel.theta", 0.3, {}}, {"Q3.s", 0.05, {}}, {"bar2.theta", -1.2, {}}, {"bar.theta_dot", 1.1, {}}};
  return m;
}

/// A Scotch yoke: crank of radius r pinned to the ground at O, the yoke on the ground
/// slider X along x, the crank's pin A in the yoke's vertical slot: Q closes the loop and
/// the yoke's x is r cos(crank.theta).
inline Mechanism scotch_yoke() {
  Mechanism m;
  m.name = "scotch-yoke";
  m.gravity = q("g");
  m.parameters = {{"r", 0.1, {}}, {"m", 0.3, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}, {"R", {q("0"), q("-0.05")}, {}}};
  m.bodies = {rod("crank", "m", "r", {{"O", {"-r/2", "0"}}, {"A", {"r/2", "0"}}}),
              rectangle("yoke", "2*m", "0.05", "0.3", {{"B", {"0", "-0.05"}}, {"S", {"0", "0"}}})};
  Joint along_x = pin("X", "ground", "R", "yoke", "B");
  along_x.type = JointType::slider;
  along_x.axis = Vector2Quantity{q("1"), q("0")};
  m.joints = {pin("O", "ground", "O", "crank", "O"), along_x, pin_slot("Q", "yoke", "S", "crank", "A", {"0", "1"})};
  m.initial = {{"crank.theta", 0.5, {}}, {"X.s", 0.0878, {}}, {"crank.theta_dot", 2.0, {}}};
  m.independent = {"crank.theta"};
  return m;
}

/// A pin-slot in the tree of a loop, its slotted body the child: a crank and a rocker
/// pinned to the ground, a slotted bar reached through Q from the crank's pin (Q.s and
/// yoke.theta), the pin F between the bar and the rocker closing the loop.
inline Mechanism pin_slot_loop() {
  Mechanism m;
  m.name = "pin-slot-loop";
  m.gravity = q("g");
  m.parameters = {{"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}, {"E", {q("0.4"), q("0")}, {}}};
  m.bodies = {rod("crank", "0.2", "0.1", {{"O", {"-0.05", "0"}}, {"A", {"0.05", "0"}}}),
              rod("rocker", "0.3", "0.3", {{"E", {"-0.15", "0"}}, {"F", {"0.15", "0"}}}),
              rod("yoke", "0.4", "0.4", {{"S", {"-0.2", "0"}}, {"F", {"0.2", "0"}}})};
  m.joints = {pin("O", "ground", "O", "crank", "O"), pin("E", "ground", "E", "rocker", "E"),
              pin_slot("Q", "yoke", "S", "crank", "A", {"1", "0"}), pin("F", "yoke", "F", "rocker", "F")};
  m.initial = {{"crank.theta", 1.0, {}}, {"rocker.theta", 1.5, {}},    {"Q.s", -0.0255, {}},
               {"yoke.theta", 0.53, {}}, {"crank.theta_dot", 1.5, {}}, {"rocker.theta_dot", -0.8, {}}};
  m.independent = {"crank.theta", "rocker.theta"};
  return m;
}

/// A gear mesh between a and b pinned to `carrier` at their points `centres` (the reader
/// finds these from the pins; built in code, they are given).
inline Joint gear(const std::string& name, const std::string& a, const std::string& b, const std::string& carrier,
                  std::array<std::string, 2> radii, bool internal, std::array<std::string, 2> centres) {
  Joint j;
  j.name = name;
  j.type = JointType::gear;
  j.bodies = {a, b};
  j.points = std::move(centres);
  j.carrier = carrier;
  j.radii = std::array<Quantity, 2>{q(radii[0]), q(radii[1])};
  j.internal = internal;
  return j;
}

/// Two discs pinned to the ground in external mesh (r1 0.1, r2 0.25), a torque tau on disc
/// 1, under gravity: th1'' = tau / (I1 + I2 (r1/r2)^2), th2'' = -(r1/r2) th1''.
inline Mechanism gear_pair() {
  Mechanism m;
  m.name = "gear-pair";
  m.gravity = q("g");
  m.parameters = {{"r1", 0.1, {}}, {"r2", 0.25, {}}, {"m1", 0.4, {}},
                  {"m2", 1.5, {}}, {"tau", 0.3, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O1", {q("0"), q("0")}, {}}, {"O2", {q("r1 + r2"), q("0")}, {}}};
  m.bodies = {disc("1", "m1", "r1", {{"C", {"0", "0"}}}), disc("2", "m2", "r2", {{"C", {"0", "0"}}})};
  m.joints = {pin("P1", "ground", "O1", "1", "C"), pin("P2", "ground", "O2", "2", "C"),
              gear("G", "1", "2", "ground", {"r1", "r2"}, false, {"C", "C"})};
  m.torques = {{"1", q("tau"), {}}};
  m.initial = {{"1.theta", 0.2, {}}, {"1.theta_dot", 0.5, {}}, {"2.theta", -0.1, {}}, {"2.theta_dot", -0.2, {}}};
  return m;
}

/// A pinion (disc 1, r1 0.1) inside a ring gear (ring 2, r2 0.3), both pinned to the
/// ground, in internal mesh, a torque tau on the pinion: th2'' = (r1/r2) th1''.
inline Mechanism ring_gear() {
  Mechanism m;
  m.name = "ring-gear";
  m.gravity = q("g");
  m.parameters = {{"r1", 0.1, {}}, {"r2", 0.3, {}},  {"m1", 0.3, {}},
                  {"m2", 1.0, {}}, {"tau", 0.2, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}, {"Q", {q("(r2 - r1)*cos(0.4)"), q("(r2 - r1)*sin(0.4)")}, {}}};
  Body ring = body("2", Shape::ring, "m2", {{"C", {"0", "0"}}});
  ring.radius = q("r2");
  m.bodies = {disc("1", "m1", "r1", {{"C", {"0", "0"}}}), ring};
  m.joints = {pin("P1", "ground", "Q", "1", "C"), pin("P2", "ground", "O", "2", "C"),
              gear("G", "1", "2", "ground", {"r1", "r2"}, true, {"C", "C"})};
  m.torques = {{"1", q("tau"), {}}};
  m.initial = {{"1.theta", 0.3, {}}, {"1.theta_dot", 0.9, {}}, {"2.theta", 0.1, {}}};
  return m;
}

/// An epicyclic set: a sun (disc 1) pinned to the ground at O, an arm (rod 3) pinned to the
/// ground at O, a planet (disc 2) pinned to the arm's end, in external mesh with the sun,
/// the arm the carrier; a torque on the arm, a spring-free 2 degrees of freedom.
inline Mechanism planetary_gears() {
  Mechanism m;
  m.name = "planetary";
  m.parameters = {{"rs", 0.12, {}}, {"rp", 0.06, {}}, {"ms", 0.8, {}},  {"mp", 0.2, {}},
                  {"ma", 0.3, {}},  {"L", 0.18, {}},  {"tau", 0.05, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {disc("1", "ms", "rs", {{"C", {"0", "0"}}}), disc("2", "mp", "rp", {{"C", {"0", "0"}}}),
              rod("3", "ma", "L", {{"O", {"-L/2", "0"}}, {"E", {"L/2", "0"}}})};
  m.joints = {pin("S", "ground", "O", "1", "C"), pin("A", "ground", "O", "3", "O"), pin("E", "3", "E", "2", "C"),
              gear("G", "1", "2", "3", {"rs", "rp"}, false, {"C", "C"})};
  m.torques = {{"3", q("tau"), {}}};
  m.initial = {{"1.theta", 0.1, {}}, {"1.theta_dot", -0.4, {}}, {"3.theta", 0.5, {}}, {"3.theta_dot", 0.7, {}}};
  return m;
}

/// A named mechanism for parameterized tests.
struct Named {
  std::string name;
  std::function<Mechanism()> make;
};

/// How GoogleTest prints a Named parameter.
inline void PrintTo(const Named& named, std::ostream* out) { *out << named.name; }

/// Every mechanism built here: pins, sliders, floating bases, springs, dampers, applied
/// loads and closed loops.
inline std::vector<Named> all_mechanisms() {
  return {{"homework", homework},
          {"double_pendulum", double_pendulum},
          {"triple_pendulum", triple_pendulum},
          {"four_bar", four_bar},
          {"slider_crank", slider_crank},
          {"arm_collar", arm_collar},
          {"loaded", double_pendulum_loaded},
          {"cart_pendulum", cart_pendulum},
          {"reversed", reversed_joints},
          {"floating_pair", floating_pair},
          {"floating_collar", floating_collar},
          {"four_bar_loaded", four_bar_loaded},
          {"spring_pendulum", [] { return spring_pendulum(true); }},
          {"welded_pendulum", welded_pendulum},
          {"welded_chain", welded_chain},
          {"welded_floating", welded_floating},
          {"rolling", rolling_wheel_and_plank},
          {"pin_slot_tree", pin_slot_tree},
          {"scotch_yoke", scotch_yoke},
          {"pin_slot_loop", pin_slot_loop},
          {"gear_pair", gear_pair},
          {"ring_gear", ring_gear},
          {"planetary", planetary_gears}};
}

/// A random state of `system`: with no loop, every generalized coordinate and rate drawn
/// (angles in [-pi, pi], x in [0.2, 1], y in [-1, -0.2], s in [0.1, 0.6] m, rates in
/// [-2, 2]); with loops, the independent coordinates moved by up to 0.2 from [initial],
/// every rate drawn, then the loops closed.
inline GiNaC::exmap random_state(const sym::System& system, std::mt19937& rng) {
  auto draw = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const bool loops = !system.tree().loop_joints.empty();
  GiNaC::exmap state = system.initial_state();
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    double value = 0;
    switch (g.coordinate.kind) {
      case CoordinateKind::theta:
        value = draw(-M_PI, M_PI);
        break;
      case CoordinateKind::x:
        value = draw(0.2, 1);
        break;
      case CoordinateKind::y:
        value = draw(-1, -0.2);
        break;
      case CoordinateKind::s:
        value = draw(0.1, 0.6);
        break;
    }
    const double rate = draw(-2, 2);
    if (loops) {
      bool independent = false;
      for (const std::string& key : system.mechanism().independent)
        independent = independent || key == g.coordinate.key;
      if (independent)
        value = sym::to_double(state[g.symbols.q]) + draw(-0.2, 0.2);
      else
        value = sym::to_double(state[g.symbols.q]);
    }
    state[g.symbols.q] = GiNaC::numeric(value);
    state[g.symbols.q_dot] = GiNaC::numeric(rate);
  }
  return loops ? sym::close_loops(system, state).state : state;
}

}  // namespace linkage::built
