// The compiled cases give the numbers of the cases' own GiNaC expressions: every entry of
// A and B of every case of every mechanism built in code, at random states, to 1e-13.
#include "evaluate/case_evaluator.hpp"

#include <gtest/gtest.h>

#include <random>

#include "formulations/case_numbers.hpp"
#include "support/mechanisms_in_code.hpp"

namespace linkage {
namespace {

TEST(CaseEvaluator, MatchesTheExpressionsAtRandomStates) {
  const std::vector<built::Named> mechanisms = {{"homework", built::homework},
                                                {"double_pendulum", built::double_pendulum},
                                                {"triple_pendulum", built::triple_pendulum},
                                                {"four_bar", built::four_bar},
                                                {"slider_crank", built::slider_crank},
                                                {"arm_collar", built::arm_collar},
                                                {"loaded", built::double_pendulum_loaded}};
  std::mt19937 rng(7);
  for (const built::Named& named : mechanisms) {
    const sym::System system(named.make());
    for (CaseId id : kAllCases) {
      const CaseSystem c = derive_case(system, id);
      const eval::CaseEvaluator evaluator(system, c);
      for (int trial = 0; trial < 3; ++trial) {
        const GiNaC::exmap values = state_values(system, built::random_state(system, rng), 0.3 * trial);
        Eigen::MatrixXd A;
        Eigen::VectorXd B;
        evaluator.evaluate(evaluator.inputs(values), A, B);
        for (std::size_t i = 0; i < c.A.size(); ++i) {
          for (std::size_t j = 0; j < c.unknowns.size(); ++j) {
            const double exact = value_at(c.A[i][j], values);
            EXPECT_NEAR(A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)), exact,
                        1e-13 * (1 + std::abs(exact)))
                << named.name << " Case " << case_number(id) << " A(" << i << "," << j << ")";
          }
          const double exact = value_at(c.B[i], values);
          EXPECT_NEAR(B(static_cast<Eigen::Index>(i)), exact, 1e-13 * (1 + std::abs(exact)))
              << named.name << " Case " << case_number(id) << " B(" << i << ")";
        }
      }
    }
  }
}

// solve() returns A's unknowns: the residual of A u = B is at rounding level, and every
// case of the homework gives the same accelerations.
TEST(CaseEvaluator, SolveGivesTheUnknownsOfEachCase) {
  const sym::System system(built::homework());
  std::mt19937 rng(11);
  const GiNaC::exmap values = state_values(system, built::random_state(system, rng), 0.0);
  std::vector<Eigen::VectorXd> solutions;
  for (CaseId id : kAllCases) {
    const CaseSystem c = derive_case(system, id);
    const eval::CaseEvaluator evaluator(system, c);
    const std::vector<double> inputs = evaluator.inputs(values);
    Eigen::VectorXd u;
    EXPECT_GT(evaluator.solve(inputs, u), 1e-8) << "Case " << case_number(id);
    Eigen::MatrixXd A;
    Eigen::VectorXd B;
    evaluator.evaluate(inputs, A, B);
    EXPECT_LT((A * u - B).norm(), 1e-12 * (1 + B.norm())) << "Case " << case_number(id);
    solutions.push_back(u);
  }
  // Case 1's unknowns start x1'', y1'', theta1'', x2'', y2'', theta2''; Case 3's are
  // x1'', y1'', theta1'', theta2'' (the generalized coordinates' order).
  for (int k : {0, 1, 2}) EXPECT_NEAR(solutions[0](k), solutions[2](k), 1e-10 * (1 + std::abs(solutions[0](k))));
  EXPECT_NEAR(solutions[0](5), solutions[2](3), 1e-10 * (1 + std::abs(solutions[0](5))));
}

}  // namespace
}  // namespace linkage
