// Pieces of the study's arithmetic: the median, time-to-error interpolation, and the
// integrators' overhead (what it copies, how the row reads; bench/overhead.hpp).
#include "bench/targets.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "bench/overhead.hpp"
#include "bench/timing.hpp"
#include "core/error.hpp"

namespace linkage::bench {
namespace {

AccuracyPoint point(double seconds, double error, std::int64_t evaluations = 1000) {
  AccuracyPoint p;
  p.method = std::string("x");
  p.library = std::string("linkage");
  p.timing.median_seconds = seconds;
  p.error = error;
  p.outcome.rhs_evaluations = evaluations;
  return p;
}

TEST(Timing, MedianOfOddAndEvenCounts) {
  std::vector<double> odd{5, 1, 3};
  EXPECT_EQ(median(odd), 3);
  std::vector<double> even{4, 1, 3, 2};
  EXPECT_EQ(median(even), 2.5);
  std::vector<double> none;
  EXPECT_EQ(median(none), 0);
}

TEST(Timing, RepeatsUntilTheMinimumTotal) {
  int calls = 0;
  const Timing t = time_repeated([&] { ++calls; }, 0.0);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(t.repeats, 1);
  calls = 0;
  const Timing many = time_repeated([&] { ++calls; }, 1.0, 5);
  EXPECT_EQ(calls, 5);  // capped
  EXPECT_LE(many.min_seconds, many.median_seconds);
}

TEST(TimeToError, InterpolatesLogLogBetweenTheBracketingSettings) {
  ScenarioResult r;
  r.points = {point(1e-3, 1e-6), point(1e-2, 1e-10)};
  const std::vector<Curve> c = curves(r);
  ASSERT_EQ(c.size(), 1u);
  // error falls 4 decades while time rises 1: 1e-8 is halfway, at sqrt(1e-3 * 1e-2)
  EXPECT_NEAR(*time_to_error(c[0], 1e-8), std::sqrt(1e-5), 1e-12);
  EXPECT_NEAR(*time_to_error(c[0], 1e-6), 1e-3, 1e-15);  // reached by the first setting
  EXPECT_NEAR(*time_to_error(c[0], 1e-3), 1e-3, 1e-15);  // the first setting already beats it
  EXPECT_FALSE(time_to_error(c[0], 1e-12).has_value());  // never reached
}

TEST(TimeToError, SkipsFailedRuns) {
  ScenarioResult r;
  r.points = {point(1e-3, std::nan("")), point(2e-3, 1e-9)};
  EXPECT_NEAR(*time_to_error(curves(r)[0], 1e-8), 2e-3, 1e-15);
}

TEST(Curves, SplitByMethodCaseAndRightHandSide) {
  ScenarioResult r;
  r.points = {point(1, 1), point(1, 1), point(1, 1)};
  r.points[1].case_id = 2;
  r.points[2].rhs = RhsKind::definition;
  EXPECT_EQ(curves(r).size(), 3u);
}

// Under load the old figure (run time / evaluations - the RHS timed apart) printed
// RK4's overhead as -7.26 ns: a run faster per evaluation than its RHS alone.
TEST(Overhead, TheRowIsTheTimeOnTheCheapRightHandSideAndNeverNegative) {
  ScenarioResult r;
  r.points = {point(1e-3, 1e-9, 100000)};  // 10 ns per evaluation on Case 3
  r.points[0].label = "RK4";
  RhsTimings rhs;
  rhs.case3_fast = {40.0, 40.0};  // more than a whole evaluation's share of the run
  rhs.oscillators = {1.5, 1.5};
  OverheadTiming o;
  o.method = "x";
  o.label = "RK4";
  o.adaptive = false;
  o.knob = 25000;
  o.homework_error = 1e-9;
  o.evaluations = 100000;
  o.per_evaluation = {12.5, 12.0};
  r.overhead = {o};
  int rows = 0;
  for (const TargetRow& row : evaluate_targets(r, rhs, Clock::wall, {})) {
    if (row.target.rfind("integrator overhead", 0) != 0) continue;
    ++rows;
    EXPECT_EQ(row.measured, "12.5 ns") << row.note;
    EXPECT_EQ(row.met, std::optional<bool>(true));
    EXPECT_NE(row.note.find("that RHS alone 1.5 ns, included), 100000 evaluations at 25000 steps"), std::string::npos)
        << row.note;
  }
  EXPECT_EQ(rows, 1);
}

/// A study of one DOP853 run whose overhead was timed on fixed- and dynamic-size states.
ScenarioResult dop853_with_dynamic_row() {
  ScenarioResult r;
  r.points = {point(1e-3, 1e-9, 100000)};
  OverheadTiming o;
  o.method = "dop853";
  o.label = "DOP853";
  o.knob = 1e-10;
  o.evaluations = 100000;
  o.per_evaluation = {10.0, 10.0};
  o.dynamic_per_evaluation = PerCall{16.0, 15.5};
  r.overhead = {o};
  return r;
}

// DOP853 and Dopri5 have a second row: the same run on a dynamic-size state.
TEST(Overhead, TheAdaptiveMethodsHaveADynamicSizeRow) {
  const ScenarioResult r = dop853_with_dynamic_row();
  RhsTimings rhs;
  rhs.case3_fast = {40.0, 40.0};
  std::vector<TargetRow> rows;
  for (TargetRow& row : evaluate_targets(r, rhs, Clock::wall, {}))
    if (row.target.rfind("integrator overhead", 0) == 0) rows.push_back(std::move(row));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].measured, "10 ns");
  EXPECT_EQ(rows[0].met, std::optional<bool>(true));
  EXPECT_NE(rows[1].target.find("DOP853, dynamic-size state"), std::string::npos) << rows[1].target;
  EXPECT_EQ(rows[1].measured, "16 ns");
  EXPECT_EQ(rows[1].met, std::optional<bool>(false));  // goal < 15 ns
}

// The dynamic-size row says what the state costs a real right-hand side, when timed.
TEST(Overhead, TheDynamicSizeRowComparesTheClosedFormRuns) {
  ScenarioResult r = dop853_with_dynamic_row();
  r.overhead[0].closed_form_fixed = PerCall{50.0, 50.0};
  r.overhead[0].closed_form_dynamic = PerCall{53.0, 53.0};
  RhsTimings rhs;
  rhs.case3_fast = {40.0, 40.0};
  int found = 0;
  for (const TargetRow& row : evaluate_targets(r, rhs, Clock::wall, {}))
    if (row.target.find("dynamic-size state") != std::string::npos) {
      ++found;
      EXPECT_NE(row.note.find("takes 53 ns an evaluation against 50 ns fixed-size and inline (1.06x)"),
                std::string::npos)
          << row.note;
    }
  EXPECT_EQ(found, 1);
}

// Both closed-form runs integrate the same scenario at the same tolerance: the same steps.
TEST(Overhead, TheClosedFormRunsTakeTheSameSteps) {
  const Scenario& s = find_scenario("fast", "test");
  for (const std::string method : {"dopri5", "dop853", "vern7"}) {
    std::int64_t fixed = 0, dynamic = 0;
    (void)time_on_closed_form(method, s, 1e-8, 0.0, false, fixed);
    (void)time_on_closed_form(method, s, 1e-8, 0.0, true, dynamic);
    EXPECT_GT(fixed, 1000) << method;
    EXPECT_EQ(dynamic, fixed) << method;
  }
  std::int64_t made = 0;
  EXPECT_THROW((void)time_on_closed_form("rk4", s, 1e-8, 0.0, false, made), Error);
}

TEST(Overhead, TheDynamicSizeRunsMakeTheSameEvaluations) {
  double sink = 0;
  for (const std::string method : {"dop853", "dopri5", "vern7"}) {
    ASSERT_TRUE(has_dynamic_run(method));
    EXPECT_EQ(run_on_oscillators(method, 1e-10, 10.0, 20000, sink, true),
              run_on_oscillators(method, 1e-10, 10.0, 20000, sink, false))
        << method;
  }
  EXPECT_FALSE(has_dynamic_run("rk4"));
  EXPECT_THROW((void)run_on_oscillators("rk4", 100, 1, 1, sink, true), Error);
}

TEST(Overhead, CopiesTheFirstRunReachingTheErrorElseTheLastThatFinished) {
  ScenarioResult r;
  r.points = {point(1e-4, 1e-6), point(2e-4, 1e-9), point(3e-4, 1e-11), point(4e-4, std::nan(""))};
  r.points[3].outcome.failure = "the step size underflowed";
  const Curve c = curves(r)[0];
  EXPECT_EQ(overhead_point(c, 1e-8), c.points[1]);
  EXPECT_EQ(overhead_point(c, 1e-13), c.points[2]);  // never reached: the most accurate
  EXPECT_EQ(overhead_point(c, 1e-5), c.points[0]);
}

TEST(Overhead, TheOscillatorRunsMakeTheHomeworksEvaluations) {
  double sink = 0;
  // fixed step: the same steps, 4 evaluations each for RK4
  EXPECT_EQ(run_on_oscillators("rk4", 1000, 10.0, 0, sink), 4000);
  EXPECT_EQ(run_on_oscillators("symplectic-euler", 1000, 10.0, 0, sink), 1000);
  // adaptive: at least as many, by at most the last step's few attempts (12, 6 evaluations each)
  const std::int64_t dop853 = run_on_oscillators("dop853", 1e-10, 10.0, 20000, sink);
  EXPECT_GE(dop853, 20000);
  EXPECT_LT(dop853, 20000 + 3 * 12);
  const std::int64_t dopri5 = run_on_oscillators("dopri5", 1e-10, 10.0, 20000, sink);
  EXPECT_GE(dopri5, 20000);
  EXPECT_LT(dopri5, 20000 + 3 * 6);
  EXPECT_TRUE(std::isfinite(sink));
  EXPECT_THROW((void)run_on_oscillators("nope", 1, 1, 1, sink), Error);
}

/// The rows of the targets against the peers (time to error).
std::vector<TargetRow> peer_rows(const ScenarioResult& r, const std::vector<std::string>& peers_not_built) {
  std::vector<TargetRow> out;
  for (TargetRow& row : evaluate_targets(r, RhsTimings{}, Clock::wall, peers_not_built))
    if (row.target.rfind("time to error", 0) == 0) out.push_back(std::move(row));
  return out;
}

TEST(Targets, WithoutAnyPeerBuiltThePeerTargetsAreNotMeasured) {
  ScenarioResult r;
  r.points = {point(1e-3, 1e-11)};  // ours only
  const std::vector<TargetRow> rows = peer_rows(r, {"Boost.Odeint", "SUNDIALS"});
  ASSERT_EQ(rows.size(), 4u);  // 1e-8 and 1e-10, user RHS and shared RHS
  for (const TargetRow& row : rows) {
    EXPECT_EQ(row.measured, "n/a") << row.target;
    EXPECT_FALSE(row.met.has_value()) << row.target;
    EXPECT_EQ(row.note, "not measured: peer not built: Boost.Odeint, SUNDIALS") << row.target;
  }
  // Every peer built but none in the run (e.g. --integrators dop853): not measured either.
  for (const TargetRow& row : peer_rows(r, {})) EXPECT_EQ(row.note, "not measured: no peer in this run");
}

TEST(Targets, WithAPeerMissingTheFigureSaysItIsTheBestOfThoseBuilt) {
  ScenarioResult r;
  r.points = {point(1e-3, 1e-11), point(4e-3, 1e-11)};
  r.points[1].method = "odeint-bs";
  r.points[1].library = "Boost.Odeint";
  r.points[1].label = "Odeint Bulirsch-Stoer";
  r.points[1].rhs = RhsKind::user;
  const std::vector<TargetRow> rows = peer_rows(r, {"SUNDIALS"});
  ASSERT_EQ(rows.size(), 4u);
  const TargetRow& user_1e8 = rows[0];
  EXPECT_EQ(user_1e8.measured, "4x");
  EXPECT_EQ(user_1e8.met, std::optional<bool>(true));  // goal >= 4x
  EXPECT_NE(user_1e8.note.find("best of the peers built (peer not built: SUNDIALS)"), std::string::npos)
      << user_1e8.note;
  const TargetRow& shared_1e8 = rows[1];  // no peer ran with our RHS
  EXPECT_EQ(shared_1e8.note, "not measured: peer not built: SUNDIALS");
  // All peers built: the same figure, and no word of a missing peer.
  EXPECT_EQ(peer_rows(r, {})[0].note.find("not built"), std::string::npos);
}

// The homework on the general path is judged against the best peer with the user's
// right-hand side, beside (not instead of) the closed form.
TEST(Targets, TheGeneralPathHasItsOwnRowsAgainstTheBestPeer) {
  ScenarioResult r;
  r.points = {point(1e-3, 1e-11), point(2e-3, 1e-11), point(8e-3, 1e-11)};
  r.points[1].rhs = RhsKind::general;
  r.points[1].label = "DOP853";
  r.points[2].method = "odeint-bs";
  r.points[2].library = "Boost.Odeint";
  r.points[2].label = "Odeint Bulirsch-Stoer";
  r.points[2].rhs = RhsKind::user;
  RhsTimings rhs;
  rhs.general_evaluator = "compiled (built in)";
  std::vector<TargetRow> general;
  for (TargetRow& row : evaluate_targets(r, rhs, Clock::wall, {}))
    if (row.target.rfind("general path", 0) == 0) general.push_back(std::move(row));
  ASSERT_EQ(general.size(), 2u);  // 1e-8 (goal 4x) and 1e-10 (goal 3x)
  EXPECT_NE(general[0].target.find("general path, compiled (built in), time to error 1e"), std::string::npos)
      << general[0].target;
  EXPECT_EQ(general[0].measured, "4x");
  EXPECT_EQ(general[0].met, std::optional<bool>(true));
  EXPECT_NE(general[0].note.find("DOP853 (Case 3, general path) 2 ms"), std::string::npos) << general[0].note;
  EXPECT_EQ(general[1].goal, ">= 3x");
  // The closed form's row is unchanged: 8x.
  EXPECT_EQ(peer_rows(r, {})[0].measured, "8x");
  // Without general-path runs (--integrators, --cases), its rows say so.
  r.points.erase(r.points.begin() + 1);
  for (const TargetRow& row : evaluate_targets(r, rhs, Clock::wall, {})) {
    if (row.target.rfind("general path", 0) != 0) continue;
    EXPECT_EQ(row.note, "not measured: not in this run (--cases, --integrators)");
  }
}

// A peer that never gets to the error says how close it came and why it stopped.
TEST(Targets, APeerThatFallsShortSaysHowCloseItCameAndWhy) {
  ScenarioResult r;
  r.points = {point(1e-3, 1e-11)};
  for (const auto& [knob, error] : {std::pair{1e-12, 6e-10}, std::pair{1e-13, 5e-10}, std::pair{1e-14, 5.5e-10}}) {
    AccuracyPoint p = point(5e-3, error);
    p.method = "odeint-rkf78";
    p.library = "Boost.Odeint";
    p.label = "Odeint RKF78";
    p.rhs = RhsKind::user;
    p.knob = knob;
    r.points.push_back(p);
  }
  const std::vector<TargetRow> rows = peer_rows(r, {});
  const TargetRow& user_1e10 = rows[2];
  EXPECT_EQ(user_1e10.measured, "n/a");
  EXPECT_NE(user_1e10.note.find("no peer reached the error: Odeint RKF78"), std::string::npos) << user_1e10.note;
  EXPECT_NE(user_1e10.note.find("best 5e-10 at 1e-13, tighter settings no better (round-off)"), std::string::npos)
      << user_1e10.note;
}

}  // namespace
}  // namespace linkage::bench
