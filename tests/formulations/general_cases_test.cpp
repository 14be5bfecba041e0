// The three cases derived by the general procedure (symbolic/system, formulations/case_*)
// for the homework, built here in code, against the closed-form solution of
// formulations/formulation.hpp.
#include <gtest/gtest.h>

#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "formulations/formulation.hpp"
#include "support/mechanisms_in_code.hpp"

namespace linkage {
namespace {

using built::homework;

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
