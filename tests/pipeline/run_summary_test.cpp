// A simulated run's summary table: the method in words, the cost and where it ended.
#include "pipeline/run_summary.hpp"

#include <gtest/gtest.h>

#include "core/number_format.hpp"
#include "pipeline/run_support.hpp"

namespace linkage {
namespace {

TEST(RunSummary, MethodInWords) {
  SimulationOptions o;
  EXPECT_EQ(method_text(o), "dop853 (rtol 1e-10, atol 1e-10)");
  o.integrator = IntegratorKind::rk4;
  o.dt = 0.001;
  o.case_id = 1;
  EXPECT_EQ(method_text(o).rfind("rk4 (dt 0.001 s), stabilization ", 0), 0u) << method_text(o);
}

TEST(RunSummary, TheHomeworksEndAndCostUnderItsOwnNames) {
  const linkage::Run run = test::homework_run("a", 1);
  MechanismSimulation sim(*run.built->system, run.built->initial, run.options);
  const Eigen::VectorXd end = sim.state_at(1);
  const ResultTable t = mechanism_summary(run, sim.stats(), end);
  EXPECT_EQ(t.headers, (std::vector<std::string>{"quantity", "value"}));
  ASSERT_GE(t.rows.size(), 12u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"mechanism", "two-blocks"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"case", "3"}));
  EXPECT_EQ(t.rows[3], (std::vector<std::string>{"simulated time", "1 s"}));
  EXPECT_EQ(t.rows[5][1], std::to_string(sim.stats().rhs_evaluations));
  // The coordinates as the homework names them (two-blocks.toml's [aliases]), at the end.
  EXPECT_EQ(t.rows[8], (std::vector<std::string>{"final x of body 1's centre of mass (x1)",
                                                 format_significant(end[0], 6) + " m"}));
  EXPECT_EQ(t.rows[11][0], "final angle of body 2 (theta2)");
  EXPECT_EQ(t.rows.back()[0], "run time");
}

TEST(RunSummary, AMechanismsCoordinatesInWords) {
  const linkage::Run run = test::mechanism_run("crank", "slider-crank", {}, 0.5);
  MechanismSimulation sim(*run.built->system, run.built->initial, run.options);
  const Eigen::VectorXd end = sim.state_at(0.5);
  const ResultTable t = mechanism_summary(run, sim.stats(), end);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"mechanism", "slider-crank"}));
  bool crank = false;
  for (const auto& row : t.rows)
    if (row[0] == "final angle of body 2 (2.theta)") crank = row[1].ends_with(" rad");
  EXPECT_TRUE(crank);
}

}  // namespace
}  // namespace linkage
