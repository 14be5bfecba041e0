// The three cases derived by the general procedure (symbolic/system, formulations/case_*)
// for the homework, built here in code, against the closed-form solution of
// formulations/formulation.hpp.
#include <gtest/gtest.h>

#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "formulations/formulation.hpp"

namespace linkage {
namespace {

Quantity q(const std::string& text) { return {text, {}}; }

Mechanism homework() {
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

TEST(GeneralCases, HomeworkMatchesTheClosedForm) {
  const sym::System system(homework());
  const GiNaC::exmap values = state_values(system, system.initial_state(), 0);
  Params p;
  State s;
  s.theta1 = 0.1;
  s.theta2 = 0.2;
  s.x1 = 1;
  s.y1 = 2;
  s.x1_dot = 0.15;
  s.y1_dot = 0.25;
  s.theta1_dot = 0.35;
  s.theta2_dot = 0.45;
  for (CaseId id : kAllCases) {
    const CaseSystem c = derive_case(system, id);
    const CaseNumbers n = solve_numbers(c, values);
    const CaseSolution closed = solve_case(case_number(id), p, s);
    ASSERT_EQ(n.A.rows(), closed.A.rows()) << case_number(id);
    EXPECT_LT((n.A - closed.A).norm(), 1e-14) << "Case " << case_number(id) << "\n" << n.A << "\n\n" << closed.A;
    EXPECT_LT((n.B - closed.B).norm(), 1e-14) << "Case " << case_number(id) << "\n" << n.B << "\n\n" << closed.B;
    EXPECT_LT((n.solution - closed.solution).norm(), 1e-12) << case_number(id);
  }
}

}  // namespace
}  // namespace linkage
