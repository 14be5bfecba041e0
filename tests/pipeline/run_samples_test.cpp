// Sampling runs for plots and compare tables: the sample times, the series along a run,
// and the DOP853 reference a final error is measured against.
#include "pipeline/run_samples.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/run_support.hpp"

namespace linkage {
namespace {

TEST(RunSamples, TimesEndExactlyAtTheDuration) {
  EXPECT_EQ(sample_times(1, 0.25), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
  EXPECT_EQ(sample_times(1, 0.3), (std::vector<double>{0, 0.3, 0.6, 0.8999999999999999, 1}));
  // 0.1 does not divide 0.3 in binary, but the last sample is the duration, once.
  const std::vector<double> t = sample_times(0.3, 0.1);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t.back(), 0.3);
}

TEST(RunSamples, AFixedStepRunSamplesOnItsOwnGrid) {
  SimulationOptions o;
  o.integrator = IntegratorKind::rk4;
  o.dt = 0.03;
  o.duration = 0.3;
  // every 0.05 s is not a whole number of 0.03 s steps: the nearest, two (0.06 s).
  const std::vector<double> t = run_sample_times(o, 0.05);
  ASSERT_EQ(t.size(), 6u);
  EXPECT_NEAR(t[1], 0.06, 1e-15);
  EXPECT_EQ(t.back(), 0.3);
  // At least one step, however small `every`.
  EXPECT_EQ(run_sample_times(o, 0.001).size(), 11u);
}

TEST(RunSamples, TheHomeworksColumnsStartAtItsInputs) {
  const linkage::Run run = test::homework_run("a", 0.5);
  const std::vector<MechanismColumn> columns{test::named_column(run, "t"), test::named_column(run, "x1"),
                                             test::named_column(run, "theta2"), test::named_column(run, "x_com")};
  const MechanismSampledRun data = sample_mechanism_run(run, run_sample_times(run.options, 0.1), columns);
  ASSERT_EQ(data.columns.size(), 4u);
  EXPECT_EQ(data.columns[0], (std::vector<double>{0, 0.1, 0.2, 0.30000000000000004, 0.4, 0.5}));
  EXPECT_DOUBLE_EQ(data.columns[1].front(), 1);  // default x1 = 1 m
  EXPECT_DOUBLE_EQ(data.columns[2].front(), 0.2);
  EXPECT_GT(data.stats.steps_accepted, 0);
}

/// A run's final error as a compare table gives it: the largest difference of its final
/// body positions and angles from the reference run's.
double final_error(const linkage::Run& run) {
  const std::vector<MechanismColumn> columns = mechanism_final_columns(*run.built->system);
  const MechanismSampledRun data = sample_mechanism_run(run, run_sample_times(run.options, 0.5), columns);
  const std::vector<double> reference = mechanism_reference_final(run);
  double error = 0;
  for (std::size_t j = 0; j < columns.size(); ++j)
    error = std::max(error, std::fabs(data.columns[j].back() - reference[j]));
  return error;
}

TEST(RunSamples, DOP853AtDefaultTolerancesIsCloseToTheReference) {
  const double error = final_error(test::homework_run("a", 2));
  EXPECT_GT(error, 0);
  EXPECT_LT(error, 1e-8);  // rtol = atol = 1e-10
}

double rk4_final_error(double dt) {
  linkage::Run run = test::homework_run("rk4", 2);
  run.options.integrator = IntegratorKind::rk4;
  run.options.dt = dt;
  return final_error(run);
}

TEST(RunSamples, RK4sFinalErrorFallsSixteenfoldWhenTheStepHalves) {
  const double coarse = rk4_final_error(0.1), fine = rk4_final_error(0.05);
  EXPECT_GT(fine, 0);
  // Fourth order: about 16 times smaller; the reference's own error (~1e-13) is far below
  // (at 0.01 s RK4's error is ~1e-13 too: the ratio then measures round-off).
  EXPECT_GT(coarse / fine, 12) << coarse << " " << fine;
  EXPECT_LT(coarse / fine, 20) << coarse << " " << fine;
}

TEST(RunSamples, AMechanismsFinalColumnsAreItsGeneralizedCoordinates) {
  const linkage::Run run = test::mechanism_run("crank", "slider-crank", {}, 0.5);
  const std::vector<MechanismColumn> columns = mechanism_final_columns(*run.built->system);
  std::vector<std::string> names;
  for (const MechanismColumn& c : columns) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"2.theta", "3.theta", "S.s"}));
  // The homework's: x1, y1, theta1, theta2 (the floating block 1 and the pin's angle).
  const linkage::Run homework = test::homework_run("h", 0.5);
  std::vector<std::string> homework_names;
  for (const MechanismColumn& c : mechanism_final_columns(*homework.built->system))
    homework_names.push_back(homework.built->named(c.name));
  EXPECT_EQ(homework_names, (std::vector<std::string>{"x1", "y1", "theta1", "theta2"}));
  // The reference's end and a default run's end agree to the default tolerances.
  const std::vector<double> reference = mechanism_reference_final(run);
  const MechanismSampledRun data = sample_mechanism_run(run, {0, 0.25, 0.5}, columns);
  ASSERT_EQ(reference.size(), columns.size());
  for (std::size_t j = 0; j < columns.size(); ++j) {
    ASSERT_EQ(data.columns[j].size(), 3u);
    EXPECT_NEAR(data.columns[j].back(), reference[j], 1e-7) << names[j];
  }
  // q and q' only: nothing in the slider-crank does work, so its state carries no W.
  EXPECT_EQ(data.final_state.size(), 2 * static_cast<Eigen::Index>(run.built->system->coordinates().size()));
}

}  // namespace
}  // namespace linkage
