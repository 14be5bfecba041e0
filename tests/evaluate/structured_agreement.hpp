#pragma once
// The structured solve (MechanismDynamics::solve_by_structure) held to the general LU, the
// reference it must agree with: the native library's and the drivers' tests share it.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "evaluate/mechanism_dynamics.hpp"
#include "support/mechanisms_in_code.hpp"

namespace linkage::test {

/// y' of `structured` (solve_by_structure(true), native code attached or not) against the
/// general LU's at four random states of `system`, at t = 0, 0.2, 0.4, 0.6, the last with
/// Baumgarte's terms: every value to 1e-12 of 1 + the largest.
inline void expect_structured_agrees(const sym::System& system, eval::MechanismDynamics& structured, std::mt19937& rng,
                                     const std::string& what) {
  eval::MechanismDynamics general(system, structured.case_id());
  structured.solve_by_structure(true);
  general.solve_by_structure(false);
  for (int trial = 0; trial < 4; ++trial) {
    const Eigen::VectorXd y = general.initial_state(built::random_state(system, rng));
    if (trial == 3) {
      structured.set_baumgarte(5.0, 7.0);
      general.set_baumgarte(5.0, 7.0);
    }
    Eigen::VectorXd ds, dg;
    ASSERT_TRUE(general.derivative(0.2 * trial, y, dg)) << what;
    ASSERT_TRUE(structured.derivative(0.2 * trial, y, ds)) << what;
    const double scale = 1 + dg.cwiseAbs().maxCoeff();
    for (Eigen::Index k = 0; k < dg.size(); ++k)
      EXPECT_NEAR(ds[k], dg[k], 1e-12 * scale) << what << " value " << k << " trial " << trial;
  }
}

}  // namespace linkage::test
