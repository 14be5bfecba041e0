// Hairer's step size controller: the next step from Solving ODEs I, II.4, with and
// without the PI term, its clamps, and what follows a rejection.
#include "integrate/step_control.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace linkage::ode {
namespace {

// DOP853's: q = 7, no PI term, err^(1/8) by three square roots.
StepController<double> dop853() { return {7, 0.0, 0.333, 6.0}; }
// Dopri5's: q = 4, beta = 0.04, exponent 1/5 - 0.75 beta = 0.17.
StepController<double> dopri5() { return {4, 0.04, 0.2, 10.0}; }

TEST(StepControl, AcceptedStepFollowsTheFormulaWithoutAPiTerm) {
  StepController<double> c = dop853();
  double h_next = 0;
  ASSERT_TRUE(c.decide(0.5, 0.01, h_next));
  EXPECT_NEAR(h_next, 0.01 * 0.9 / std::pow(0.5, 1.0 / 8), 1e-15);
  ASSERT_TRUE(c.decide(1e-30, 0.01, h_next));  // at most 6 times larger
  EXPECT_NEAR(h_next, 0.06, 1e-15);
  ASSERT_TRUE(c.decide(0.0, 0.01, h_next));
  EXPECT_NEAR(h_next, 0.06, 1e-15);
}

TEST(StepControl, AcceptedStepFollowsTheFormulaWithAPiTerm) {
  StepController<double> c = dopri5();
  double h_next = 0;
  // The first accepted step's err_prev is the floor, 1e-4.
  ASSERT_TRUE(c.decide(0.5, 0.01, h_next));
  EXPECT_NEAR(h_next, 0.01 * 0.9 * std::pow(1e-4, 0.04) / std::pow(0.5, 0.17), 1e-15);
  // The next one divides by the last accepted err^beta.
  ASSERT_TRUE(c.decide(0.1, 0.02, h_next));
  EXPECT_NEAR(h_next, 0.02 * 0.9 * std::pow(0.5, 0.04) / std::pow(0.1, 0.17), 1e-15);
  // Clamped to fac_max = 10 and fac_min = 0.2 of h.
  ASSERT_TRUE(c.decide(1e-40, 0.02, h_next));
  EXPECT_NEAR(h_next, 0.2, 1e-15);
  ASSERT_TRUE(c.decide(0.0, 0.02, h_next));
  EXPECT_NEAR(h_next, 0.2, 1e-15);
}

TEST(StepControl, ARejectedStepShrinksAndTheNextAcceptedOneDoesNotGrow) {
  for (StepController<double> c : {dop853(), dopri5()}) {
    double h_next = 0;
    ASSERT_FALSE(c.decide(4.0, 0.01, h_next));
    EXPECT_LT(h_next, 0.01);
    EXPECT_GT(h_next, 0.0);
    ASSERT_TRUE(c.decide(1e-6, h_next, h_next));  // would grow, but follows a rejection
    EXPECT_LE(h_next, 0.01);
  }
  StepController<double> c = dopri5();
  double h_next = 0;
  ASSERT_FALSE(c.decide(4.0, 0.01, h_next));
  EXPECT_NEAR(h_next, 0.01 * 0.9 / std::pow(4.0, 0.17), 1e-15);
}

TEST(StepControl, ANonFiniteErrorIsARejectionByTheSmallestFactor) {
  for (StepController<double> c : {dop853(), dopri5()}) {
    double h_next = 0;
    EXPECT_FALSE(c.decide(std::numeric_limits<double>::quiet_NaN(), 0.01, h_next));
    EXPECT_FALSE(c.decide(std::numeric_limits<double>::infinity(), 0.01, h_next));
    EXPECT_GT(h_next, 0.0);
    EXPECT_LE(h_next, 0.01 * 0.334);
  }
}

}  // namespace
}  // namespace linkage::ode
