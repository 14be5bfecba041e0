#pragma once
// The named problems every bench study runs: the spec's example and variations that
// stress the integrators and the formulations.
#include <string>
#include <string_view>
#include <vector>

#include "bench/closed_form/params.hpp"
#include "bench/closed_form/state.hpp"

namespace linkage::bench {

struct Scenario {
  std::string name;         // CLI spelling, e.g. "fast"
  std::string description;  // one line for reports
  Params params;
  State initial;
  double duration = 10.0;  // s, the time the final error is measured at
};

/// Every scenario, in the order reports list them:
///   example    the spec's example (10 s)
///   fast       the example spinning fast: theta1' = 20, theta2' = -35 rad/s (10 s)
///   near-zero-d  the pin almost at the centres of mass: D = 1e-6 L (10 s)
///   tiny-mass  m = 1e-6 kg, the example otherwise (10 s): Case 2 divides by m
///   long       the fast scenario over 100 s
[[nodiscard]] const std::vector<Scenario>& scenarios();

/// The scenario named `name`; throws Error::input naming `origin` and the valid names.
[[nodiscard]] const Scenario& find_scenario(std::string_view name, const std::string& origin);

/// "example, fast, ..." for help texts and errors.
[[nodiscard]] std::string scenario_names();

}  // namespace linkage::bench
