#include "report/worked_solution.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"

namespace linkage {
namespace {

TEST(WorkedSolution, AgreementCoversEveryUnknownAndMarksRecoveredValues) {
  const WorkedSolution w = work_out(Inputs{}, {1, 2, 3});
  ASSERT_EQ(w.agreement.size(), kUnknowns.size());
  const Params p;
  for (const Agreement& a : w.agreement) {
    ASSERT_EQ(a.values.size(), 3u);
    // Case 1 solves for everything; Case 2 recovers x2'', y2''; Case 3 also Fx, Fy.
    EXPECT_FALSE(a.recovered[0]);
    const bool block2 = a.unknown == Unknown::x2_ddot || a.unknown == Unknown::y2_ddot;
    const bool force = a.unknown == Unknown::F_x || a.unknown == Unknown::F_y;
    EXPECT_EQ(a.recovered[1], block2) << info(a.unknown).key;
    EXPECT_EQ(a.recovered[2], block2 || force) << info(a.unknown).key;
    double spread = 0;
    for (double v : a.values) spread = std::max(spread, std::fabs(v - a.values[0]));
    EXPECT_GE(a.max_abs_difference, spread);
    EXPECT_LE(a.max_abs_difference, 2 * spread);
    // Round-off agreement: the accelerations are O(10) m/s^2 at most here.
    EXPECT_LT(a.max_abs_difference, 1e-12) << info(a.unknown).key;
    EXPECT_DOUBLE_EQ(a.values[0], solution_value(w.cases[0], a.unknown, p));
  }
  EXPECT_TRUE(work_out(Inputs{}, {2}).agreement.empty());
}

TEST(WorkedSolution, OverflowingInputsAreABadInputNotInfinity) {
  Inputs inputs;
  inputs.set(*find_input_key("m"), 1e300, "--m");
  inputs.set(*find_input_key("g"), 1e10, "--g");
  try {
    (void)work_out(inputs, {1});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    const std::string message = e.what();
    EXPECT_NE(message.find("overflows"), std::string::npos) << message;
    EXPECT_NE(message.find("m = 1e+300 (--m)"), std::string::npos) << message;
  }
  Inputs spin;
  spin.set(*find_input_key("theta1_dot"), 1e200, "run.toml:3:14");
  try {
    (void)work_out(spin, {3});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("theta1_dot = 1e+200 (run.toml:3:14)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace linkage
