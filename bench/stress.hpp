#pragma once
// `linkage bench stress`: numerical stability, run through the tool's own engine
// (closed_form/simulation.hpp), in four studies:
//   long runs      every integrator on Cases 3 and 1 over 10^4 s: energy and constraint
//                  error against time;
//   stable step    the largest step of each fixed-step method (per case) whose run stays
//                  finite with a bounded energy error, by bisection;
//   extremes       masses 1e-6..1e6 kg, D down to 1e-6 L, width down to 1e-4 L, spins up
//                  to 1e4 rad/s: each case's condition number and the accuracy of its
//                  solve against a long double solve;
//   drift          Case 1's constraint error over time without stabilization, with
//                  Baumgarte at several gains, and with projection.
#include <filesystem>
#include <string>
#include <vector>

namespace linkage::bench {

struct StressOptions {
  std::filesystem::path out{"bench-stress"};
  bool quick = false;  // shorter runs, fewer bisection steps and extremes: for CI
  bool quiet = false;
};

struct StressSummary {
  std::vector<std::string> lines;            // one-line findings for the terminal
  std::vector<std::filesystem::path> files;  // written, in order
};

/// Runs the four studies and writes stress.md, one CSV per study and the plots.
[[nodiscard]] StressSummary run_stress(const StressOptions& options);

}  // namespace linkage::bench
