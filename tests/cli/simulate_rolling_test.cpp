// Issue 27: the rolling joint against the closed forms on an incline of angle alpha
// (mechanisms/rolling-disc.toml: a uniform disc on R1 down the right side of a roof, a hoop
// on R2 down the left, mass m, radius r): down the slope a = g sin(alpha) / (1 + I / (m r^2)),
// (2/3) g sin(alpha) for the disc and g sin(alpha) / 2 for the hoop; the friction the ground
// feels along its axis u, +-(m g sin(alpha) - m a) (R1's u points down the slope, R2's up);
// the normal component -m g cos(alpha); the energy balance, in every case.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "run_checks.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

TEST(SimulateRolling, DiscAndHoopOnAnInclineMatchTheClosedForms) {
  const double m = 1, g = 9.81, alpha = 0.03;
  const std::string file = source_path("mechanisms/rolling-disc.toml");
  const char* columns =
      "t,disc.x_ddot,disc.y_ddot,hoop.x_ddot,hoop.y_ddot,R1.normal,R1.friction,R2.normal,R2.friction,"
      "R1.constraint_error,energy_error_relative";
  for (int case_id : {1, 2, 3}) {
    const Table table = simulate_tight(file, case_id, columns, 4, 0.5);
    ASSERT_EQ(table.rows.size(), 9U) << "Case " << case_id;
    for (const std::vector<double>& row : table.rows) {
      // The centres' accelerations down the slope: (cos alpha, -sin alpha) on the right,
      // (-cos alpha, -sin alpha) on the left.
      const double disc = row[1] * std::cos(alpha) - row[2] * std::sin(alpha);
      const double hoop = -row[3] * std::cos(alpha) - row[4] * std::sin(alpha);
      const std::string at = "Case " + std::to_string(case_id) + " t " + std::to_string(row[0]);
      EXPECT_NEAR(disc, 2.0 / 3.0 * g * std::sin(alpha), 1e-12) << at;
      EXPECT_NEAR(hoop, 0.5 * g * std::sin(alpha), 1e-12) << at;
      // Across the slope the centres do not accelerate.
      EXPECT_NEAR(row[1] * std::sin(alpha) + row[2] * std::cos(alpha), 0, 1e-12) << at;
      EXPECT_NEAR(-row[3] * std::sin(alpha) + row[4] * std::cos(alpha), 0, 1e-12) << at;
      EXPECT_NEAR(row[5], -m * g * std::cos(alpha), 1e-12) << at;
      EXPECT_NEAR(row[6], m * g * std::sin(alpha) / 3, 1e-12) << at;
      EXPECT_NEAR(row[7], -m * g * std::cos(alpha), 1e-12) << at;
      EXPECT_NEAR(row[8], -m * g * std::sin(alpha) / 2, 1e-12) << at;
      EXPECT_LT(row[9], 1e-10) << at;
      EXPECT_LT(row[10], 1e-9) << at;
    }
  }
}

}  // namespace
}  // namespace linkage::test
