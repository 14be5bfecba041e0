// Pieces of the study's arithmetic: the median, time-to-error interpolation, overhead.
#include "bench/targets.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "bench/timing.hpp"

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

TEST(Overhead, IsTimePerEvaluationLessTheRightHandSide) {
  ScenarioResult r;
  r.points = {point(1e-3, 1e-6, 10000), point(1e-4, 1e-4, 10)};  // the second is too short to count
  // 1 ms / 10000 = 100 ns per evaluation, 40 of them the right-hand side
  EXPECT_NEAR(*overhead_ns(curves(r)[0], 40.0), 60.0, 1e-9);
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
