// Issue 25, Deliver 5: loads that depend on the state (tests/data/mechanisms/). A drag
// torque written in the rate gives the pin damper's run, a motor's torque-speed line spins
// a disc up as its closed form says, the energy balance holds with state-dependent
// springs, dampers, forces and torques, `solve` prints the loads as they are written, and
// a value that leaves its range during a run stops it with one line.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "run_checks.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

RunResult simulate_run(const std::string& file, int case_id, const std::string& columns, double duration,
                       double every) {
  return run_linkage({"simulate", "--mechanism", test_mechanism(file), "--case", std::to_string(case_id), "--rtol",
                      "1e-12", "--atol", "1e-12", "--duration", std::to_string(duration), "--every",
                      std::to_string(every), "--columns", columns});
}

Table simulate(const std::string& file, int case_id, const std::string& columns, double duration, double every) {
  const RunResult r = simulate_run(file, case_id, columns, duration, every);
  EXPECT_EQ(r.exit_code, 0) << file << " Case " << case_id << ": " << r.err;
  return parse_csv(r.out);
}

// damped-pendulum-torque.toml's [[torque]] -c*pend.theta_dot is the pin damper of
// damped-pendulum-pin.toml: every column of `all` the same to 1e-12, in every case, but
// the shaking moment: the damper's reaction c theta' acts on the ground, the applied
// torque's does not (the pin is at the origin, so the joint force has no moment there).
TEST(SimulateStateLoads, ADragTorqueInTheRateIsThePinDamper) {
  for (int case_id : {1, 2, 3}) {
    const Table pin = simulate("damped-pendulum-pin.toml", case_id, "all", 3.0, 0.25);
    const Table torque = simulate("damped-pendulum-torque.toml", case_id, "all", 3.0, 0.25);
    ASSERT_EQ(pin.columns, torque.columns) << "Case " << case_id;
    ASSERT_EQ(pin.rows.size(), 13U) << "Case " << case_id;
    ASSERT_EQ(torque.rows.size(), pin.rows.size()) << "Case " << case_id;
    double work = 0;
    for (std::size_t i = 0; i < pin.rows.size(); ++i) {
      work = std::max(work, std::fabs(pin.rows[i][pin.index("work")]));
      for (std::size_t c = 0; c < pin.columns.size(); ++c) {
        if (pin.columns[c] == "shaking_moment") continue;
        EXPECT_NEAR(torque.rows[i][c], pin.rows[i][c], 1e-12)
            << "Case " << case_id << " " << pin.columns[c] << " t " << pin.rows[i][0];
      }
      const double damping = 0.08, rate = pin.rows[i][pin.index("pend.theta_dot")];
      EXPECT_NEAR(pin.rows[i][pin.index("shaking_moment")], damping * rate, 1e-12) << "Case " << case_id;
      EXPECT_NEAR(torque.rows[i][torque.index("shaking_moment")], 0, 1e-12) << "Case " << case_id;
    }
    EXPECT_GT(work, 0.1) << "Case " << case_id << ": the damper must dissipate";
  }
}

// motor-disc.toml: I theta'' = T0 (1 - theta'/w0) from rest, I = m R^2 / 2, so
// theta'(t) = w0 (1 - exp(-T0 t / (I w0))) and theta(t) = w0 t - w0 tau (1 - exp(-t/tau)),
// tau = I w0 / T0: to 1e-9 at rtol = atol = 1e-12, in every case.
TEST(SimulateStateLoads, AMotorsTorqueSpeedLineReachesItsNoLoadSpeedExponentially) {
  const double m = 2, R = 0.15, T0 = 0.9, w0 = 12, I = m * R * R / 2, tau = I * w0 / T0;
  for (int case_id : {1, 2, 3}) {
    const Table table = simulate("motor-disc.toml", case_id, "t,disc.theta,disc.theta_dot,disc.theta_ddot", 2.0, 0.1);
    ASSERT_EQ(table.rows.size(), 21U);
    for (const std::vector<double>& row : table.rows) {
      const double t = row[0], decay = std::exp(-t / tau);
      const std::string what = "Case " + std::to_string(case_id) + " t " + std::to_string(t);
      EXPECT_NEAR(row[1], w0 * t - w0 * tau * (1 - decay), 1e-9) << what;
      EXPECT_NEAR(row[2], w0 * (1 - decay), 1e-9) << what;
      EXPECT_NEAR(row[3], T0 / I * decay, 1e-9) << what;
    }
    EXPECT_GT(table.rows.back()[2], 0.99 * w0);
  }
}

// state-loads-cart.toml: a spring stiffening with S.s, a pin damper growing with the
// angle, a drag, a force and a torque in the rates. W integrates their power: E - E(0) - W
// stays at the integration error (1e-9 of the energy scale) in every case, while W itself
// is not small. Counting the spring's k(S.s) (l - l0)^2 / 2 as a potential would not.
TEST(SimulateStateLoads, TheEnergyBalanceHoldsWithLoadsThatDependOnTheState) {
  for (int case_id : {1, 2, 3}) {
    const Table table = simulate("state-loads-cart.toml", case_id, "t,work,energy_error_relative", 3.0, 0.1);
    ASSERT_EQ(table.rows.size(), 31U);
    expect_balance_with_real_work(table, "Case " + std::to_string(case_id));
  }
}

// The cases agree at the start of a run with such loads (solve --case all's table).
TEST(SimulateStateLoads, TheCasesAgreeOnAStateLoadedRun) {
  std::vector<Table> tables;
  for (int case_id : {1, 2, 3})
    tables.push_back(simulate("state-loads-cart.toml", case_id, "t,S.s,rod.theta,rod.theta_dot,P.force_x", 1.0, 0.1));
  EXPECT_GT(expect_cases_agree(tables, 1e-8), 0.01);  // S.s moves
}

// The derivation shows the torque as written, its rate spelled like every other rate.
TEST(SimulateStateLoads, SolvePrintsTheLoadAsWrittenInEveryFormat) {
  const std::string file = test_mechanism("motor-disc.toml");
  const RunResult text = run_linkage({"solve", "--mechanism", file, "--case", "3", "--unicode"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("I θ̈_disc = T₀ (1 - θ̇_disc/w₀)"), std::string::npos) << text.out;
  const RunResult ascii = run_linkage({"solve", "--mechanism", file, "--case", "3", "--ascii"});
  ASSERT_EQ(ascii.exit_code, 0) << ascii.err;
  EXPECT_NE(ascii.out.find("moment T0 (1 - th_disc'/w0): torque 1"), std::string::npos) << ascii.out;
  const std::string tex = "T_0 \\left(1 - \\frac{\\dot{\\theta}_{\\mathrm{disc}}}{w_0}\\right)";
  for (const char* format : {"latex", "markdown"}) {
    const RunResult r = run_linkage({"solve", "--mechanism", file, "--case", "3", "--format", format});
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.err;
    EXPECT_NE(r.out.find("\\ddot{\\theta}_{\\mathrm{disc}} &= " + tex), std::string::npos) << format << "\n" << r.out;
  }
}

// A state-dependent value that leaves its range later in a run stops it with one line:
// FILE:LINE:COLUMN, the value as written, its value and the time; exit 2; every row
// before finite. softening-spring-cart.toml's stiffness turns negative at the closed
// form's t* = 0.2072126 s: DOP853 bisects its dense output there (to its tolerance,
// 1e-6 s), RK4 stops at the end of the step that crosses it (dt = 1 ms).
TEST(SimulateStateLoads, AStiffnessThatTurnsNegativeInTheRunStopsIt) {
  const double crossing = 0.2072126;
  for (const std::string integrator : {"dop853", "rk4"})
    for (const std::string case_id : {"1", "3"}) {
      const RunResult r = run_linkage({"simulate", "--mechanism", test_mechanism("softening-spring-cart.toml"),
                                       "--quiet", "--integrator", integrator, "--case", case_id, "--duration", "1",
                                       "--every", "0.05", "--columns", "t,S.s,energy"});
      EXPECT_EQ(r.exit_code, 2) << integrator << " Case " << case_id;
      std::smatch m;
      ASSERT_TRUE(std::regex_search(r.err, m,
                                    std::regex("^linkage: error: [^\n]*softening-spring-cart\\.toml:32:13: "
                                               "stiffness of spring k1 \"k\\*\\(1 - S\\.s/a\\)\" is "
                                               "-[0-9.e+-]+ at t = ([0-9.]+) s; valid: >= 0 [^\n]*\n$")))
          << r.err;
      const double t = std::stod(m[1].str());
      if (integrator == "dop853")
        EXPECT_NEAR(t, crossing, 1e-6) << "Case " << case_id;
      else
        EXPECT_TRUE(t >= crossing && t <= crossing + 0.001) << "Case " << case_id << " t " << t;
      const Table table = parse_csv(r.out);
      ASSERT_GE(table.rows.size(), 4U) << integrator << " Case " << case_id;
      for (const std::vector<double>& row : table.rows) {
        for (double v : row) EXPECT_TRUE(std::isfinite(v)) << integrator << " t " << row[0];
        EXPECT_LT(row[1], 0.2) << integrator << " t " << row[0];  // no row past the range
      }
    }
}

// root-force-cart.toml's force -sqrt(0.25 - S.s) has no value past S.s = 0.25, reached
// at t* = 0.3188163 s: the first state met past it is a stage of the step that crosses
// it, within 2 ms of t* (RK4's step is 1 ms; DOP853's there is shorter).
TEST(SimulateStateLoads, ALoadThatTurnsNonFiniteInTheRunStopsIt) {
  const double crossing = 0.3188163;
  for (const std::string integrator : {"dop853", "rk4"})
    for (const std::string case_id : {"1", "3"}) {
      const RunResult r = run_linkage({"simulate", "--mechanism", test_mechanism("root-force-cart.toml"), "--quiet",
                                       "--integrator", integrator, "--case", case_id, "--duration", "1", "--every",
                                       "0.05", "--columns", "t,S.s,energy,work"});
      EXPECT_EQ(r.exit_code, 2) << integrator << " Case " << case_id;
      std::smatch m;
      ASSERT_TRUE(std::regex_search(r.err, m,
                                    std::regex("^linkage: error: [^\n]*root-force-cart\\.toml:37:10: force on cart "
                                               "x \"-sqrt\\(0\\.25 - S\\.s\\)\" is nan at t = ([0-9.]+) s "
                                               "\\([^)]*\\); valid: a finite number [^\n]*\n$")))
          << r.err;
      EXPECT_NEAR(std::stod(m[1].str()), crossing, 0.002) << integrator << " Case " << case_id;
      EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
      const Table table = parse_csv(r.out);
      ASSERT_GE(table.rows.size(), 6U) << integrator << " Case " << case_id;
      for (const std::vector<double>& row : table.rows)
        for (double v : row) EXPECT_TRUE(std::isfinite(v)) << integrator << " t " << row[0];
    }
}

}  // namespace
}  // namespace linkage::test
