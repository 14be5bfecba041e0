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

}  // namespace
}  // namespace linkage
