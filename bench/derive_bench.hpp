#pragma once
// `linkage bench derive`: how long the symbolic derivation and a whole worked solution
// take for every shipped mechanism, and the homework's `solve` against a baseline build
// measured in the same run.
//   Targets: the homework's `linkage solve` at most 1.5x the baseline's in wall time (the
//   command as a user runs it, start-up included; the baseline was the closed-form
//   printer the general procedure replaced); deriving the four-bar
//   in all three cases under 0.2 s (one core).
#include <filesystem>
#include <string>
#include <vector>

namespace linkage::bench {

inline constexpr double kMaxSolveRatio = 1.5;
inline constexpr double kMaxFourBarDeriveSeconds = 0.2;

struct DeriveBenchOptions {
  std::filesystem::path out = "bench-derive";
  bool quick = false;
  std::string baseline;  // another linkage binary to time `solve` against; empty: none
};

struct DeriveRow {
  std::string mechanism;
  int bodies = 0, joints = 0, degrees_of_freedom = 0;
  double derive_seconds = 0;  // the system and the three cases, median
  double solve_seconds = 0;   // work_out_mechanism and the text report, median
  int repeats = 0;
};

struct DeriveBenchResult {
  std::vector<DeriveRow> rows;
  double command_seconds = 0;           // `linkage solve`, the whole process, median
  double baseline_command_seconds = 0;  // the same with the baseline binary; NaN without one
  std::vector<std::string> lines;       // the terminal summary
  std::vector<std::filesystem::path> files;
};

[[nodiscard]] DeriveBenchResult run_derive_bench(const DeriveBenchOptions& options);

}  // namespace linkage::bench
