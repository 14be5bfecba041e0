#pragma once
// The reference solution a study measures errors against: the scenario integrated in
// long double (64-bit mantissa, eps = 1.1e-19) by our DOP853 at a tolerance far tighter
// than any double run can reach, checked against a second method (long double Dopri5),
// and for the spec's example also against the 25-digit states of
// assets/spec/reference-example.json (embedded in the binary at configure time).
#include <array>
#include <optional>
#include <string>

#include "bench/closed_form/state.hpp"
#include "bench/scenarios.hpp"

namespace linkage::bench {

struct Reference {
  /// x1, y1, theta1, theta2 at the scenario's duration, in long double.
  std::array<long double, 4> final{};
  double tolerance = 0;        // rtol = atol of the DOP853 run
  long steps = 0;              // its accepted steps
  double check_tolerance = 0;  // rtol = atol of the Dopri5 check
  /// Largest |difference| over x1, y1, theta1, theta2 between the two methods: a bound
  /// on the reference's absolute error (of the worse of the two).
  double check_difference = 0;
  /// Largest |difference| to reference-example.json at t = 1, 2, 5, 10 s (example only).
  std::optional<double> spec_difference;
  /// Decimal digits the reference has, relative to the largest of |x1|, |y1|, |theta|.
  double digits = 0;
  double seconds = 0;  // wall time of computing and checking it
};

/// Integrates the scenario (initial state and parameters exactly as the double runs
/// see them) to its duration. `quick` loosens both tolerances for CI.
[[nodiscard]] Reference compute_reference(const Scenario& scenario, bool quick);

/// Largest |reference - s| over x1, y1, theta1, theta2 (m and rad).
[[nodiscard]] double final_error(const Reference& reference, const BodyState& s);

}  // namespace linkage::bench
