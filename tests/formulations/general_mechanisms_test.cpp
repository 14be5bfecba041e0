// The three cases of mechanisms beyond the homework, built in code: every case gives the
// same accelerations and joint forces (directly or recovered) to 1e-12 relative.
#include <gtest/gtest.h>

#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

Quantity q(const std::string& text) { return {text, {}}; }

Body rod(const std::string& name, const std::string& mass, const std::string& length,
         std::vector<std::pair<std::string, std::string>> points) {
  Body b;
  b.name = name;
  b.shape = Shape::rod;
  b.mass = q(mass);
  b.length = q(length);
  for (auto& [point, x] : points) b.points.push_back({point, {q(x), q("0")}, {}});
  return b;
}

Joint pin(const std::string& name, const std::string& a, const std::string& pa, const std::string& b,
          const std::string& pb) {
  Joint j;
  j.name = name;
  j.bodies = {a, b};
  j.points = {pa, pb};
  return j;
}

Mechanism double_pendulum() {
  Mechanism m;
  m.gravity = q("g");
  m.parameters = {{"L1", 0.3, {}}, {"L2", 0.25, {}}, {"m1", 0.2, {}}, {"m2", 0.15, {}}, {"g", 9.81, {}}};
  m.ground_points = {{"O", {q("0"), q("0")}, {}}};
  m.bodies = {rod("1", "m1", "L1", {{"O", "-L1/2"}, {"A", "L1/2"}}), rod("2", "m2", "L2", {{"A", "-L2/2"}})};
  m.joints = {pin("O", "ground", "O", "1", "O"), pin("A", "1", "A", "2", "A")};
  m.initial = {{"1.theta", -1.2, {}}, {"2.theta", -0.8, {}}, {"1.theta_dot", 0.5, {}}, {"2.theta_dot", -0.3, {}}};
  return m;
}

Mechanism four_bar() {
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

Mechanism slider_crank() {
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

void expect_cases_agree(const Mechanism& mechanism) {
  const sym::System system(mechanism);
  const sym::ClosedState closed = sym::close_loops(system, system.initial_state());
  const GiNaC::exmap values = state_values(system, closed.state, 0);
  std::vector<CaseSystem> cases;
  std::vector<CaseNumbers> numbers;
  for (CaseId id : kAllCases) {
    cases.push_back(derive_case(system, id));
    numbers.push_back(solve_numbers(cases.back(), values));
    EXPECT_LT(numbers.back().residual, 1e-10 * (1 + numbers.back().B.norm())) << case_number(id);
  }
  // Every Case 1 unknown, from every case.
  for (std::size_t j = 0; j < cases[0].unknowns.size(); ++j) {
    const GiNaC::symbol& u = cases[0].unknowns[j];
    const double reference = numbers[0].solution(static_cast<Eigen::Index>(j));
    for (std::size_t k = 1; k < cases.size(); ++k) {
      const auto value = case_value(cases[k], numbers[k], values, u);
      ASSERT_TRUE(value.has_value()) << u << " missing from Case " << k + 1;
      EXPECT_NEAR(*value, reference, 1e-12 * (1 + std::abs(reference))) << u << " in Case " << k + 1;
    }
  }
}

TEST(GeneralMechanisms, DoublePendulumCasesAgree) { expect_cases_agree(double_pendulum()); }
TEST(GeneralMechanisms, FourBarCasesAgree) { expect_cases_agree(four_bar()); }
TEST(GeneralMechanisms, SliderCrankCasesAgree) { expect_cases_agree(slider_crank()); }

TEST(GeneralMechanisms, FourBarLoopCloses) {
  const Mechanism m = four_bar();
  const sym::System system(m);
  const sym::ClosedState closed = sym::close_loops(system, system.initial_state());
  EXPECT_TRUE(closed.changed);
  const GiNaC::exmap values = state_values(system, closed.state, 0);
  for (int j : system.tree().loop_joints)
    for (const GiNaC::ex& phi : system.joints()[static_cast<std::size_t>(j)].constraints) {
      EXPECT_NEAR(value_at(phi.subs(system.to_generalized()), values), 0, 1e-13);
      const GiNaC::ex rate = system.time_derivative(phi.subs(system.to_generalized()));
      EXPECT_NEAR(value_at(rate, values), 0, 1e-12);
    }
  // The crank keeps its angle.
  EXPECT_DOUBLE_EQ(value_at(system.coordinates()[0].symbols.q, values), 1.0);
}

TEST(GeneralMechanisms, FourBarKeepsOnlyTheLoopForce) {
  const sym::System system(four_bar());
  const CaseSystem c3 = reduced_case(system);
  EXPECT_EQ(c3.unknowns.size(), 3u + 2u);  // three angles, the loop pin's two components
  EXPECT_EQ(c3.A.size(), 5u);
}

}  // namespace
}  // namespace linkage
