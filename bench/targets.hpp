#pragma once
// The performance targets of the benchmark issue, evaluated from one accuracy run on
// the `fast` scenario (error at t = 10 s), as ratios measured in that same run.
#include <optional>
#include <string>
#include <vector>

#include "bench/accuracy.hpp"

namespace linkage::bench {

/// Points of one curve: one method on one case with one right-hand side, in sweep
/// order (loosest setting first).
struct Curve {
  std::string method;
  std::string library;
  std::string label;
  int case_id = 3;
  RhsKind rhs = RhsKind::fastest;
  std::vector<const AccuracyPoint*> points;
  /// Legend text, e.g. "DOP853 (Case 3)", "Odeint RKF78 (user RHS)".
  [[nodiscard]] std::string name() const;
  [[nodiscard]] bool ours() const { return library == "linkage"; }
};

/// The curves of a scenario's points, in the order their first point appears.
[[nodiscard]] std::vector<Curve> curves(const ScenarioResult& result);

/// Which time of a point to use.
enum class Clock { wall, cpu };

/// The run time (s) at which a curve first reaches `error`: interpolated log-log
/// between the last setting above it and the first at or below it. None if never.
[[nodiscard]] std::optional<double> time_to_error(const Curve& curve, double error, Clock clock = Clock::wall);

/// The error at which the integrators' overhead is measured: the speed target's.
inline constexpr double kOverheadError = 1e-8;

/// The run whose work the overhead measurement copies: the first point that reaches
/// `error`, else the last one that ran to the end. None if no run did.
[[nodiscard]] const AccuracyPoint* overhead_point(const Curve& curve, double error = kOverheadError);

struct TargetRow {
  std::string target;       // what is measured
  std::string measured;     // the value, formatted
  std::string goal;         // e.g. "<= 40 ns", ">= 4x"
  std::optional<bool> met;  // none when it could not be measured (say why in note)
  std::string note;         // which methods, or why not measured
};

/// Evaluates every target on a run of the fast scenario, judged by `clock` (the other
/// clock's figure is given in the note). A target against the peers is not measured
/// when no peer ran, and says which peer libraries (`peers_not_built`) it could not
/// compare against.
[[nodiscard]] std::vector<TargetRow> evaluate_targets(const ScenarioResult& fast, const RhsTimings& rhs, Clock clock,
                                                      const std::vector<std::string>& peers_not_built);

}  // namespace linkage::bench
