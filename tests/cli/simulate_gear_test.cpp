// Issue 27: the gear joint on the shipped gear-train (a pinion of radius r1 driven by a
// constant torque tau meshes with a gear of radius r2 braked by a constant torque T):
// through the ratio, th1'' = (tau - (r1/r2) T) / (I1 + (r1/r2)^2 I2) and th2'' = -(r1/r2)
// th1''; the tooth force G.force from the gear's moment r2 F = I2 th2'' - T, along the common
// tangent (+y: the centres lie along +x); each pin's force carries the tooth force and the
// weight. Every case, against the closed forms to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "run_checks.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

TEST(SimulateGear, GearTrainMatchesTheReflectedInertiaAndTorque) {
  const double r1 = 0.05, r2 = 0.15, m1 = 0.5, m2 = 4.5, tau = 0.02, T = 0.03, g = 9.81;
  const double I1 = m1 * r1 * r1 / 2, I2 = m2 * r2 * r2 / 2, n = r1 / r2;
  const double a1 = (tau - n * T) / (I1 + n * n * I2), a2 = -n * a1, F = (I2 * a2 - T) / r2;
  const std::string file = source_path("mechanisms/gear-train.toml");
  const char* columns =
      "t,pinion.theta_ddot,gear.theta_ddot,pinion.theta_dot,gear.theta_dot,G.force,G.force_x,G.force_y,O1.force_x,"
      "O1.force_y,O2.force_x,O2.force_y,G.constraint_error,energy_error_relative";
  for (int case_id : {1, 2, 3}) {
    const Table table = simulate_tight(file, case_id, columns, 4, 0.5);
    ASSERT_EQ(table.rows.size(), 9U) << "Case " << case_id;
    for (const std::vector<double>& row : table.rows) {
      const std::string at = "Case " + std::to_string(case_id) + " t " + std::to_string(row[0]);
      EXPECT_NEAR(row[1], a1, 1e-12 * a1) << at;
      EXPECT_NEAR(row[2], a2, 1e-12 * a1) << at;
      EXPECT_NEAR(row[3], a1 * row[0], 1e-10) << at;  // from rest
      EXPECT_NEAR(row[4], -n * row[3], 1e-12) << at;
      EXPECT_NEAR(row[5], F, 1e-12) << at;
      EXPECT_NEAR(row[6], 0, 1e-12) << at;
      EXPECT_NEAR(row[7], F, 1e-12) << at;
      // What each gear exerts on the ground at its pin: the tooth force on it and its weight.
      EXPECT_NEAR(row[8], 0, 1e-12) << at;
      EXPECT_NEAR(row[9], F - m1 * g, 1e-11) << at;
      EXPECT_NEAR(row[10], 0, 1e-12) << at;
      EXPECT_NEAR(row[11], -F - m2 * g, 1e-11) << at;
      EXPECT_LT(row[12], 1e-10) << at;
      EXPECT_LT(row[13], 1e-9) << at;
    }
  }
}

}  // namespace
}  // namespace linkage::test
