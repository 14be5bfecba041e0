// Issue 25, Deliver 6: columns defined as NAME=EXPRESSION in `simulate --columns` (the
// transmission angle, a driver's power), through the program: their values against the
// columns they name, in degrees with --angles deg, under the homework's names, and a
// panel of a still that plots one.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace linkage::test {
namespace {

// The four-bar's transmission angle gamma = th4 - th3 in degrees is the difference of the
// two angles' degree columns (to round-off: each column is converted on its own).
TEST(SimulateExpressionColumns, AnAngleDifferenceIsWrittenInTheAnglesUnit) {
  const RunResult r = run_linkage({"simulate", "--mechanism", "four-bar", "--duration", "1", "--every", "0.1",
                                   "--angles", "deg", "--columns", "t,gamma=4.theta-3.theta,4.theta,3.theta"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table table = parse_csv(r.out);
  ASSERT_EQ(table.columns, (std::vector<std::string>{"t", "gamma (deg)", "4.theta (deg)", "3.theta (deg)"}));
  ASSERT_EQ(table.rows.size(), 11U);
  for (const auto& row : table.rows) {
    EXPECT_NEAR(row[1], row[2] - row[3], 1e-12 * 360) << "t " << row[0];
    EXPECT_GT(row[1], 10);  // degrees, not radians
  }
}

// The homework speaks its own names (x1, x2): a definition uses them.
TEST(SimulateExpressionColumns, TheHomeworksNamesAreUsable) {
  const RunResult r =
      run_linkage({"simulate", "--duration", "0.5", "--every", "0.1", "--columns", "t,x1,x2,gap=x2-x1,theta1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table table = parse_csv(r.out);
  for (const auto& row : table.rows) EXPECT_EQ(row[table.index("gap")], row[2] - row[1]);
}

// A driver's power M.torque * th2' (W), and its integral against the work column: the
// driven four-bar's work W is the drivers' and the damper's; with the damper's power
// -c (th3' - th2')^2 added, the trapezoid of the two powers follows W to the rule's error.
TEST(SimulateExpressionColumns, ADriversPowerIsInWattsAndIntegratesToItsWork) {
  const RunResult r = run_linkage({"simulate", "--mechanism", test_mechanism("driven-four-bar.toml"), "--duration", "1",
                                   "--every", "0.001", "--rtol", "1e-12", "--atol", "1e-12", "--format", "json",
                                   "--columns", "t,P=M.torque*2.theta_dot,D=-0.05*(3.theta_dot-2.theta_dot)^2,work"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["units"]["P"], "W");
  EXPECT_EQ(j["units"]["D"], "1/s^2");  // the 0.05 is a number here: no unit claimed for it
  const auto& rows = j["rows"];
  double integral = 0, largest = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double dt = rows[i][0].get<double>() - rows[i - 1][0].get<double>();
    const auto power = [&](std::size_t k) { return rows[k][1].get<double>() + rows[k][2].get<double>(); };
    integral += dt * (power(i) + power(i - 1)) / 2;
    largest = std::max(largest, std::abs(rows[i][3].get<double>()));
    EXPECT_NEAR(integral, rows[i][3].get<double>(), 1e-5) << "t " << rows[i][0];
  }
  EXPECT_GT(largest, 1e-2);  // the drivers do work worth checking
}

TEST(SimulateExpressionColumns, APanelPlotsADefinition) {
  TempDir dir;
  const RunResult r =
      run_linkage({"render", "--mechanism", "four-bar", "--out", (dir / "still.png").string(), "--at", "0.5",
                   "--quality", "low", "--panel", "gamma=4.theta-3.theta,F=hypot(B.force_x, B.force_y)"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"still.png"});
}

}  // namespace
}  // namespace linkage::test
