#pragma once
// Mechanisms built in code for the tests of the symbolic layer, the cases and the reports:
// the homework, a double pendulum, a Grashof four-bar and a slider-crank.
#include <string>
#include <utility>
#include <vector>

#include "model/mechanism.hpp"

namespace linkage::test {

inline Quantity q(const std::string& text) { return {text, {}}; }

inline Body rod(const std::string& name, const std::string& mass, const std::string& length,
                std::vector<std::pair<std::string, std::string>> points) {
  Body b;
  b.name = name;
  b.shape = Shape::rod;
  b.mass = q(mass);
  b.length = q(length);
  for (auto& [point, x] : points) b.points.push_back({point, {q(x), q("0")}, {}});
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

inline Mechanism double_pendulum() {
  Mechanism m;
  m.gravity = q("g");
  m.parameters = {{"L1", 0.3, {}}, {"L2", 0.25, {}}, {"m1", 0.2, {}}, {"m2", 0.15, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {rod("1", "m1", "L1", {{"O", "-L1/2"}, {"A", "L1/2"}}), rod("2", "m2", "L2", {{"A", "-L2/2"}})};
  m.joints = {pin("O", "ground", "O", "1", "O"), pin("A", "1", "A", "2", "A")};
  m.initial = {{"1.theta", -1.2, {}}, {"2.theta", -0.8, {}}, {"1.theta_dot", 0.5, {}}, {"2.theta_dot", -0.3, {}}};
  return m;
}

inline Mechanism four_bar() {
  Mechanism m;
  m.gravity = q("g");
  m.parameters = {{"a", 0.1, {}}, {"b", 0.35, {}}, {"c", 0.3, {}}, {"d", 0.3, {}}, {"m", 0.1, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O2", {q("0"), q("0")}, {}}, {"O4", {q("d"), q("0")}, {}}};
  m.bodies = {rod("2", "m", "a", {{"O", "-a/2"}, {"A", "a/2"}}), rod("3", "2*m", "b", {{"A", "-b/2"}, {"B", "b/2"}}),
              rod("4", "m", "c", {{"O", "-c/2"}, {"B", "c/2"}})};
  m.joints = {pin("O2", "ground", "O2", "2", "O"), pin("A", "2", "A", "3", "A"), pin("O4", "ground", "O4", "4", "O"),
              pin("B", "3", "B", "4", "B")};
  m.initial = {{"2.theta", 1.0, {}}, {"3.theta", 0.3, {}}, {"4.theta", 1.6, {}}, {"2.theta_dot", 2.0, {}}};
  m.independent = {"2.theta"};
  return m;
}

inline Mechanism slider_crank() {
  Mechanism m;
  m.gravity = q("g");
  m.parameters = {{"r", 0.1, {}}, {"l", 0.35, {}}, {"m", 0.1, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}, {"Q", {q("0"), q("0")}, {}}};
  Body piston;
  piston.name = "4";
  piston.shape = Shape::rectangle;
  piston.mass = q("m");
  piston.length = q("0.08");
  piston.width = q("0.05");
  piston.points = {{"B", {q("0"), q("0")}, {}}};
  m.bodies = {rod("2", "m", "r", {{"O", "-r/2"}, {"A", "r/2"}}), rod("3", "m", "l", {{"A", "-l/2"}, {"B", "l/2"}}),
              piston};
  Joint slider;
  slider.name = "s";
  slider.type = JointType::slider;
  slider.bodies = {"ground", "4"};
  slider.points = {"Q", "B"};
  slider.axis = Vector2Quantity{q("1"), q("0")};
  m.joints = {pin("O", "ground", "O", "2", "O"), slider, pin("A", "2", "A", "3", "A"), pin("B", "3", "B", "4", "B")};
  m.initial = {{"2.theta", 0.8, {}}, {"3.theta", -0.2, {}}, {"s.s", 0.43, {}}, {"2.theta_dot", 3.0, {}}};
  m.independent = {"2.theta"};
  return m;
}

inline Mechanism homework() {
  Mechanism m;
  m.name = "two-blocks";
  m.gravity = q("g");
  m.parameters = {{"L", 0.3, {}}, {"w", 0.1, {}}, {"b", 0.04, {}}, {"m", 0.1, {}}, {"g", 9.81, {}}};
  m.definitions = {{"D", q("L/2 - b"), {}}};
  for (const char* name : {"1", "2"}) {
    Body b;
    b.name = name;
    b.shape = Shape::rectangle;
    b.mass = q("m");
    b.length = q("L");
    b.width = q("w");
    b.points = {{"P", {q(name[0] == '1' ? "D" : "-D"), q("0")}, {}}};
    m.bodies.push_back(b);
  }
  Joint p;
  p.name = "P";
  p.bodies = {"1", "2"};
  p.points = {"P", "P"};
  m.joints.push_back(p);
  m.initial = {{"1.x", 1, {}},        {"1.y", 2, {}},        {"1.theta", 0.1, {}},      {"2.theta", 0.2, {}},
               {"1.x_dot", 0.15, {}}, {"1.y_dot", 0.25, {}}, {"1.theta_dot", 0.35, {}}, {"2.theta_dot", 0.45, {}}};
  return m;
}

}  // namespace linkage::test
