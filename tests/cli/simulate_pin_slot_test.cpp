// Issue 27: the pin-slot joint against closed forms (tests/data/mechanisms/), in every case
// at DOP853 with rtol = atol = 1e-12, projected back onto the constraints after each step:
//  - a Scotch yoke (crank r pinned at O, yoke on the ground slider X along x, the crank's
//    pin in the yoke's vertical slot Q, closing the loop): yoke.x = r cos(crank.theta) and
//    Q.s = r sin(crank.theta) exactly; free, the energy kept; driven at w, the yoke's
//    x'' = -r w^2 cos(w t), the pin's force across the slot Q.normal = M r w^2 cos(w t) (the
//    yoke's only horizontal force) and the motor's torque from the power balance;
//  - a bead in the slot of a bar driven at w (the pin-slot in the tree, a point mass adding
//    Q.s alone): s'' = w^2 s - g sin(w t) in closed form, and the slot's push on it;
//  - the shipped quick-return: the three cases agree, its energy balance holds, and the
//    ram's strokes take the times its geometry gives.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "run_checks.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

Table simulate(const std::string& file, int case_id, const std::string& columns, double duration, double every) {
  return simulate_tight(file, case_id, columns, duration, every,
                        {"--integrator", "dop853", "--stabilize", "projection"});
}

constexpr double kR = 0.1, kCrankMass = 0.3, kYokeMass = 0.6, kG = 9.81;

TEST(SimulatePinSlot, FreeScotchYokeStaysOnItsClosedFormAndKeepsItsEnergy) {
  for (int case_id : {1, 2, 3}) {
    const Table table = simulate(test_mechanism("scotch-yoke.toml"), case_id,
                                 "t,crank.theta,yoke.x,X.s,Q.s,Q.constraint_error,energy_error_relative", 10, 0.25);
    ASSERT_EQ(table.rows.size(), 41U) << "Case " << case_id;
    double turned = 0;
    for (const std::vector<double>& row : table.rows) {
      const std::string at = "Case " + std::to_string(case_id) + " t " + std::to_string(row[0]);
      const double theta = row[1];
      EXPECT_NEAR(row[2], kR * std::cos(theta), 1e-12) << at;
      EXPECT_NEAR(row[3], kR * std::cos(theta), 1e-12) << at;
      EXPECT_NEAR(row[4], kR * std::sin(theta), 1e-12) << at;
      EXPECT_LT(row[5], 1e-12) << at;
      EXPECT_LT(row[6], 1e-9) << at;
      turned = std::max(turned, std::fabs(theta - 0.5));
    }
    EXPECT_GT(turned, 2 * std::numbers::pi) << "the crank goes round";
  }
}

TEST(SimulatePinSlot, DrivenScotchYokeMatchesItsClosedForms) {
  const double w = 5;
  for (int case_id : {1, 2, 3}) {
    const Table table = simulate(test_mechanism("scotch-yoke-driven.toml"), case_id,
                                 "t,crank.theta,yoke.x,yoke.x_ddot,Q.normal,M.torque", 10, 0.25);
    ASSERT_EQ(table.rows.size(), 41U) << "Case " << case_id;
    for (const std::vector<double>& row : table.rows) {
      const std::string at = "Case " + std::to_string(case_id) + " t " + std::to_string(row[0]);
      const double th = w * row[0], c = std::cos(th), s = std::sin(th);
      EXPECT_NEAR(row[1], th, 1e-12) << at;
      EXPECT_NEAR(row[2], kR * c, 1e-12) << at;
      EXPECT_NEAR(row[3], -kR * w * w * c, 1e-9) << at;
      // The crank pushes the yoke along n = k x (0, 1) = (-1, 0): M x'' = -N.
      EXPECT_NEAR(row[4], kYokeMass * kR * w * w * c, 1e-9) << at;
      // tau w = d/dt (T + V): the yoke's (1/2) M (r w sin)^2 and the crank's m g (r/2) sin.
      EXPECT_NEAR(row[5], kYokeMass * kR * kR * w * w * s * c + kCrankMass * kG * kR / 2 * c, 1e-9) << at;
    }
  }
}

// s(t) = s0 cosh(w t) + D sinh(w t) + g / (2 w^2) sin(w t), D = (v0 - g / (2 w)) / w; the
// bar pushes the bead across the slot with m (2 w s' + g cos(w t)), so Q.normal (the bead
// on the bar) is its opposite.
TEST(SimulatePinSlot, BeadInADrivenSlotFollowsItsClosedForm) {
  const double w = 1.5, m = 0.2, s0 = 0.3, v0 = 0.2, a = kG / (2 * w * w), d = (v0 - kG / (2 * w)) / w;
  for (int case_id : {1, 2, 3}) {
    const Table table = simulate(test_mechanism("slotted-bar-bead.toml"), case_id,
                                 "t,bar.theta,Q.s,bead.x_dot,bead.y_dot,Q.normal,bead.x,bead.y", 2, 0.1);
    ASSERT_EQ(table.rows.size(), 21U) << "Case " << case_id;
    for (const std::vector<double>& row : table.rows) {
      const std::string at = "Case " + std::to_string(case_id) + " t " + std::to_string(row[0]);
      const double th = w * row[0];
      const double s = s0 * std::cosh(th) + d * std::sinh(th) + a * std::sin(th);
      const double v = w * (s0 * std::sinh(th) + d * std::cosh(th) + a * std::cos(th));
      // s grows to 17 m in 2 s (cosh(3) = 10): relative tolerances.
      const double scale = 1 + std::fabs(s);
      EXPECT_NEAR(row[1], th, 1e-12) << at;
      EXPECT_NEAR(row[2], s, 1e-10 * scale) << at;
      // The bead's velocity along the slot, u = (cos, sin): s'.
      EXPECT_NEAR(row[3] * std::cos(th) + row[4] * std::sin(th), v, 1e-10 * scale) << at;
      EXPECT_NEAR(row[5], -m * (2 * w * v + kG * std::cos(th)), 1e-9 * scale) << at;
      EXPECT_NEAR(row[6], s * std::cos(th), 1e-10 * scale) << at;
      EXPECT_NEAR(row[7], s * std::sin(th), 1e-10 * scale) << at;
    }
  }
}

const std::string kQuickReturn = source_path("mechanisms/quick-return.toml");

TEST(SimulatePinSlot, QuickReturnCasesAgree) {
  std::vector<Table> tables;
  for (int case_id : {1, 2, 3})
    tables.push_back(simulate(kQuickReturn, case_id, "t,M.torque,Q.normal,Q.s,X.s,ram.x_dot,lever.theta", 2, 0.05));
  EXPECT_GT(expect_cases_agree(tables, 1e-10), 0.1);
}

TEST(SimulatePinSlot, QuickReturnKeepsItsEnergyBalance) {
  for (int case_id : {1, 2, 3}) {
    const Table table = simulate(kQuickReturn, case_id, "t,work,energy_error_relative", 10, 0.1);
    ASSERT_EQ(table.rows.size(), 101U);
    expect_balance_with_real_work(table, "Case " + std::to_string(case_id));
  }
}

// The lever's limits are where the crank stands square to it: the crank turns through
// 2 arccos(r/d) = 120 degrees between them below C and 240 above, so at one turn a second
// the ram's stroke to the left takes 2/3 s and its return 1/3 s. The turns of ram.x_dot's
// sign, sampled every 0.5 ms and interpolated, fall 1/3 s and 2/3 s apart.
TEST(SimulatePinSlot, QuickReturnStrokesTakeTwoThirdsAndOneThirdOfATurn) {
  const Table table = simulate(kQuickReturn, 3, "t,ram.x_dot", 2, 0.0005);
  std::vector<double> turns;
  for (std::size_t i = 1; i < table.rows.size(); ++i) {
    const double v0 = table.rows[i - 1][1], v1 = table.rows[i][1];
    if ((v0 < 0) != (v1 < 0))
      turns.push_back(table.rows[i - 1][0] + (table.rows[i][0] - table.rows[i - 1][0]) * v0 / (v0 - v1));
  }
  ASSERT_GE(turns.size(), 3U);
  for (std::size_t k = 1; k < turns.size(); ++k) {
    const double stroke = turns[k] - turns[k - 1];
    // From a leftward start the first full stroke is rightward (quick), then leftward (slow).
    const bool rightward = (table.rows[0][1] < 0) == (k % 2 == 1);
    EXPECT_NEAR(stroke, rightward ? 1.0 / 3 : 2.0 / 3, 1e-5) << "stroke " << k;
  }
}

}  // namespace
}  // namespace linkage::test
