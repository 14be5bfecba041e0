#pragma once
// `linkage bench accuracy`: the work-precision study. For each scenario, case, method
// and accuracy setting (adaptive: rtol = atol from 1e-3 to 1e-13 by half decades;
// fixed step: step counts by factors of two) it measures the run time (steady clock,
// repeated until 20 ms, median), right-hand-side evaluations, steps, the final error
// (largest absolute error over x1, y1, theta1, theta2 against a long double reference),
// the energy error and, for Case 1, the constraint error. Our integrators and the peer
// libraries' run in the same process, so the comparison is fair.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench/method.hpp"
#include "bench/overhead.hpp"
#include "bench/reference.hpp"
#include "bench/scenarios.hpp"
#include "bench/timing.hpp"

namespace linkage::bench {

struct AccuracyOptions {
  std::vector<std::string> scenarios{"fast"};
  std::vector<int> cases{1, 2, 3};
  std::vector<std::string> integrators;  // method ids to run; empty: all of them
  std::optional<double> duration;        // s; overrides the scenarios' own
  std::filesystem::path out{"bench-accuracy"};
  bool quick = false;  // few settings, one repeat, looser reference: for CI
  bool quiet = false;  // no progress line
};

/// One run of one method at one setting.
struct AccuracyPoint {
  std::string method;  // Method::id
  std::string library;
  std::string label;
  int case_id = 3;
  RhsKind rhs = RhsKind::fastest;
  bool adaptive = true;
  double knob = 0;  // tolerance or step count
  Timing timing;
  Outcome outcome;
  double error = 0;             // m or rad; NaN when the run failed
  double energy_error = 0;      // |E(T) - E(0)| / energy_scale at T
  double constraint_error = 0;  // |C(T)| in m, Case 1 only (NaN otherwise)
};

struct ScenarioResult {
  Scenario scenario;  // as run (duration overridden if asked)
  Reference reference;
  std::vector<AccuracyPoint> points;
  /// Our integrators' own cost per evaluation (bench/overhead.hpp), each copying its
  /// Case 3 run that first reaches 1e-8 (or its most accurate).
  std::vector<OverheadTiming> overhead;
};

/// Cost of one right-hand-side evaluation, measured in the same run on states taken
/// along the first scenario's motion.
struct RhsTimings {
  PerCall case3_fast;        // closed form (ours, fastest)
  PerCall case3_definition;  // definition's matrices + block solve
  PerCall case3_user;        // hand-typed 4x4 + Eigen partialPivLu
  PerCall case2;
  PerCall case1;
  PerCall solve_blocks;           // the Case 3 4x4 solve alone: our block solve
  PerCall solve_lu;               //                         and Eigen's partialPivLu
  PerCall oscillators;            // OscillatorsRhs, on which the integrators' overhead is timed
  PerCall case3_general;          // the general path (general_rhs.hpp): two-blocks.toml as simulate runs it
  std::string general_evaluator;  // what computes it: "compiled (built in)", "interpreted (why)"
};

struct AccuracyResult {
  std::vector<ScenarioResult> scenarios;
  RhsTimings rhs;
  /// 1-minute load average when the run started, and the cores there are. On a busy
  /// machine (load above the cores) other processes take the cores in turns and the
  /// steady clock counts their time too: the targets are then judged by this thread's
  /// CPU time, and the report says so.
  double load_average = 0;
  unsigned cores = 1;
  [[nodiscard]] bool busy() const { return load_average > static_cast<double>(cores); }
  std::vector<std::string> peers_not_built;  // peer libraries this build lacks (PeerLibrary::library)
  std::vector<std::filesystem::path> files;  // written, in order
};

/// The ids --integrators accepts, in report order.
[[nodiscard]] std::vector<std::string> method_ids();

/// Throws Error::input naming the flag when an option is out of range, or names an
/// integrator of a peer this build lacks.
void validate(const AccuracyOptions& options);

/// Validates the options (throws Error::input naming the flag), runs the study and
/// writes accuracy.csv, accuracy.md and the work-precision plots into options.out.
[[nodiscard]] AccuracyResult run_accuracy(const AccuracyOptions& options);

/// The methods the options select, ours first, then the peers.
[[nodiscard]] std::vector<Method> selected_methods(const AccuracyOptions& options);

}  // namespace linkage::bench
