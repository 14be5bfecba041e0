// Issue 25: `simulate` of driven mechanisms (tests/data/mechanisms/), its columns against
// closed forms: an offset slider-crank's piston at constant crank speed, the drivers'
// torque the same in every case, the energy balance with the drivers' work, and a
// pendulum on a driven cart (one driven, one free coordinate) with every integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "run_checks.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

Table simulate(const std::string& file, int case_id, const std::string& columns, double duration, double every,
               const std::string& integrator = "dop853") {
  const RunResult r =
      run_linkage({"simulate", "--mechanism", test_mechanism(file), "--case", std::to_string(case_id), "--integrator",
                   integrator, "--rtol", "1e-12", "--atol", "1e-12", "--dt", "0.001", "--duration",
                   std::to_string(duration), "--every", std::to_string(every), "--columns", columns});
  EXPECT_EQ(r.exit_code, 0) << file << " Case " << case_id << " " << integrator << ": " << r.err;
  return parse_csv(r.out);
}

// offset-slider-crank.toml: crank r = 0.1 at th = 0.5 + 12 t, rod l = 0.35, rail at e = 0.03.
// With S = r sin th - e and R = sqrt(l^2 - S^2): x = r cos th + R,
//   x' = -r w sin th - S S' / R,   x'' = -r w^2 cos th - (S'^2 + S S'') / R - S^2 S'^2 / R^3,
// S' = r w cos th, S'' = -r w^2 sin th. To 1e-9 at rtol = atol = 1e-12, in every case.
TEST(SimulateDriven, OffsetSliderCrankPistonFollowsItsClosedForm) {
  const double r = 0.1, l = 0.35, e = 0.03, w = 12, th0 = 0.5;
  for (int case_id : {1, 2, 3}) {
    const Table table =
        simulate("offset-slider-crank.toml", case_id, "t,piston.x,piston.x_dot,piston.x_ddot,S.s,S.s_ddot", 1.0, 0.1);
    ASSERT_EQ(table.rows.size(), 11U);
    for (const std::vector<double>& row : table.rows) {
      const double t = row[0], th = th0 + w * t;
      const double S = r * std::sin(th) - e, S1 = r * w * std::cos(th), S2 = -r * w * w * std::sin(th);
      const double R = std::sqrt(l * l - S * S);
      const double x = r * std::cos(th) + R, x1 = -r * w * std::sin(th) - S * S1 / R;
      const double x2 = -r * w * w * std::cos(th) - (S1 * S1 + S * S2) / R - S * S * S1 * S1 / (R * R * R);
      const std::string what = "Case " + std::to_string(case_id) + " t " + std::to_string(t);
      EXPECT_NEAR(row[table.index("piston.x")], x, 1e-9) << what;
      EXPECT_NEAR(row[table.index("S.s")], x, 1e-9) << what;
      EXPECT_NEAR(row[table.index("piston.x_dot")], x1, 1e-9) << what;
      EXPECT_NEAR(row[table.index("piston.x_ddot")], x2, 1e-9) << what;
      EXPECT_NEAR(row[table.index("S.s_ddot")], x2, 1e-9) << what;
    }
  }
}

// The motor's torque is the case's multiplier: Cases 1, 2 and 3 give the same M.torque
// along a run (to 1e-8 N m), and it is not trivially small (gravity and inertia need it).
TEST(SimulateDriven, TheCasesAgreeOnTheDriversTorque) {
  std::vector<Table> tables;
  for (int case_id : {1, 2, 3})
    tables.push_back(simulate("offset-slider-crank.toml", case_id, "t,M.torque", 1.0, 0.05));
  EXPECT_GT(expect_cases_agree(tables, 1e-8), 0.1);
}

// driven-four-bar.toml: the crank driven at 1 + 3 t + 0.5 sin 2t with a damper at A. The
// balance E - E(0) - W stays at the integration error (1e-9 of the energy scale) only
// when W has the motor's work as well as the damper's; the motor's is not small.
TEST(SimulateDriven, TheEnergyBalanceCountsTheDriversWork) {
  for (int case_id : {1, 2, 3}) {
    const Table table = simulate("driven-four-bar.toml", case_id, "t,work,energy_error_relative", 2.0, 0.1);
    ASSERT_EQ(table.rows.size(), 21U);
    expect_balance_with_real_work(table, "Case " + std::to_string(case_id));
  }
}

// driven-cart-pendulum.toml: the cart at s = A sin(w t) (A = 0.1, w = 5), a rod (mr = 0.5,
// l = 0.6) swinging free from its pin. By hand, the rod about the moving pin:
//   (mr l^2 / 3) th'' = -mr g (l/2) cos th + mr (l/2) s'' sin th,
// and along the rail, the cart and the rod's centre (x = s + (l/2) cos th) together:
//   D.force = (mc + mr) s'' - mr (l/2) (sin th th'' + cos th th'^2).
// Both hold at every sample (to 1e-8) whatever the integrator; s'' is the motion's
// -A w^2 sin(w t) exactly (the driver's row at the acceleration level), s the motion's
// within the integrator's error.
TEST(SimulateDriven, APendulumOnADrivenCartRunsWithEveryIntegrator) {
  const double mc = 1.0, mr = 0.5, l = 0.6, g = 9.81, A = 0.1, w = 5;
  for (const std::string integrator : {"euler", "symplectic-euler", "rk4", "dopri5", "dop853", "gauss-legendre"})
    for (int case_id : {1, 2, 3}) {
      const Table table =
          simulate("driven-cart-pendulum.toml", case_id,
                   "t,S.s,S.s_ddot,D.force,rod.theta,rod.theta_dot,rod.theta_ddot", 1.0, 0.1, integrator);
      ASSERT_EQ(table.rows.size(), 11U) << integrator << " Case " << case_id;
      const bool first_order = integrator == "euler" || integrator == "symplectic-euler";
      for (const std::vector<double>& row : table.rows) {
        const double t = row[0], s = row[1], s2 = row[2], force = row[3], th = row[4], th1 = row[5], th2 = row[6];
        const std::string what = integrator + " Case " + std::to_string(case_id) + " t " + std::to_string(t);
        EXPECT_NEAR(s, A * std::sin(w * t), first_order ? 1e-3 : 1e-8) << what;
        EXPECT_NEAR(s2, -A * w * w * std::sin(w * t), 1e-9) << what;
        EXPECT_NEAR(th2, 3 / (2 * l) * (-g * std::cos(th) + s2 * std::sin(th)), 1e-8) << what;
        EXPECT_NEAR(force, (mc + mr) * s2 - mr * l / 2 * (std::sin(th) * th2 + std::cos(th) * th1 * th1), 1e-8) << what;
      }
    }
}

}  // namespace
}  // namespace linkage::test
