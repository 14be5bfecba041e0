// A compare step's numbers: final errors against the reference, the table, the CSV and
// the cost plot.
#include "pipeline/run_compare.hpp"

#include <gtest/gtest.h>

#include "pipeline/run_support.hpp"

namespace linkage {
namespace {

Run rk4(const std::string& label, double dt) {
  linkage::Run run = test::homework_run(label, 2);
  run.series = "rk4";
  run.options.integrator = IntegratorKind::rk4;
  run.options.dt = dt;
  return run;
}

const std::vector<CompareColumn> kAll{
    CompareColumn::final_error, CompareColumn::energy_error,    CompareColumn::constraint_error, CompareColumn::steps,
    CompareColumn::rejected,    CompareColumn::rhs_evaluations, CompareColumn::run_time};

TEST(RunCompare, HalvingTheStepCutsTheFinalErrorAndDoublesTheCost) {
  const std::vector<linkage::Run> runs{rk4("dt, 0.1", 0.1), rk4("dt 0.05", 0.05)};
  const Comparison c = compare_runs(runs, kAll, 0.5);
  ASSERT_EQ(c.figures.size(), 2u);
  // Steps large enough that both errors stand far above the reference's own (~1e-13).
  EXPECT_GT(c.figures[0].final_error / c.figures[1].final_error, 12);
  EXPECT_EQ(c.figures[0].steps, 20);
  EXPECT_EQ(c.figures[1].steps, 40);
  EXPECT_EQ(c.figures[1].rhs_evaluations, 4 * 40);  // four stages a step
  EXPECT_TRUE(c.warnings.empty());
  EXPECT_EQ(c.table.headers, (std::vector<std::string>{"run", "final error", "energy error", "constraint error (m)",
                                                       "steps", "rejected", "RHS evaluations", "run time (ms)"}));
  ASSERT_EQ(c.table.rows.size(), 2u);
  EXPECT_EQ(c.table.rows[1][4], "40");
  // The CSV: names, the label quoted for its comma, numbers round-trip.
  const std::string head = "run,final_error,energy_error,constraint_error,steps,rejected,rhs_evaluations,run_time\n";
  ASSERT_EQ(c.csv.substr(0, head.size()), head);
  EXPECT_EQ(c.csv.substr(head.size(), 10), "\"dt, 0.1\",");
  EXPECT_NE(c.csv.find("\ndt 0.05,"), std::string::npos);
}

TEST(RunCompare, ThePlotOfCostGroupsRunsBySeries) {
  std::vector<linkage::Run> runs{rk4("a", 0.02), rk4("b", 0.01), test::homework_run("dop853", 2)};
  const Comparison c = compare_runs(runs, {CompareColumn::final_error}, 0.5);
  const plot::Plot p = cost_plot(runs, c.figures, "Step size");
  EXPECT_EQ(p.title, "Step size: accuracy against cost");
  ASSERT_EQ(p.series.size(), 2u);
  EXPECT_EQ(p.series[0].name, "rk4");
  ASSERT_EQ(p.series[0].points.size(), 2u);
  EXPECT_LT(p.series[0].points[0].x, p.series[0].points[1].x);  // by cost
  EXPECT_GT(p.series[0].points[0].y, p.series[0].points[1].y);
  EXPECT_EQ(cost_plot(runs, c.figures, "").title, "Accuracy against cost");
}

TEST(RunCompare, AMechanismsRunsAgainstItsReference) {
  linkage::Run coarse = test::mechanism_run("rk4 0.01", "slider-crank", {}, 0.5);
  coarse.options.integrator = IntegratorKind::rk4;
  coarse.options.dt = 0.01;
  linkage::Run fine = coarse;
  fine.label = "rk4 0.005";
  fine.options.dt = 0.005;
  const Comparison c = compare_runs({coarse, fine}, {CompareColumn::final_error, CompareColumn::steps}, 0.1);
  ASSERT_EQ(c.figures.size(), 2u);
  EXPECT_GT(c.figures[1].final_error, 0);
  EXPECT_GT(c.figures[0].final_error / c.figures[1].final_error, 8);
  EXPECT_EQ(c.figures[1].steps, 100);
  EXPECT_NE(final_error_note().find("generalized coordinates"), std::string::npos);
  EXPECT_NE(final_error_note().find("rtol = atol = 1e-13"), std::string::npos);
}

TEST(RunCompare, ARunWhoseNumbersMeanNothingIsNamed) {
  linkage::Run bad = test::homework_run("euler", 50);
  bad.options.case_id = 2;
  bad.options.integrator = IntegratorKind::euler;
  bad.options.dt = 0.5;
  const Comparison c = compare_runs({bad}, {CompareColumn::energy_error}, 1);
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0].rfind("run 'euler': the run's numbers do not describe the motion", 0), 0u) << c.warnings[0];
}

}  // namespace
}  // namespace linkage
