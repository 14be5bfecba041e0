#pragma once
// The spec's reference motion (assets/spec/reference-example.json) as model types,
// for the integration tests.
#include <string>
#include <vector>

#include "bench/closed_form/params.hpp"
#include "bench/closed_form/state.hpp"
#include "support/test_support.hpp"

namespace linkage::test {

/// One reference sample: the time, the state and the derived values it lists.
struct ReferenceSample {
  double t = 0;
  State state;
  nlohmann::json values;  // every key of the sample, as in the file
};

/// The reference's parameters and initial state (the spec's example).
inline Params reference_params() {
  const nlohmann::json& p = spec_reference()["parameters"];
  return {number(p["L"]), number(p["w"]), number(p["b"]), number(p["m"]), number(p["g"])};
}

inline State reference_initial_state() {
  const nlohmann::json& s = spec_reference()["initial_state"];
  return {number(s["x1"]),     number(s["y1"]),     number(s["theta1"]),     number(s["theta2"]),
          number(s["x1_dot"]), number(s["y1_dot"]), number(s["theta1_dot"]), number(s["theta2_dot"])};
}

/// The samples at t = 1, 2, 5 and 10 s.
inline std::vector<ReferenceSample> reference_samples() {
  std::vector<ReferenceSample> samples;
  for (const nlohmann::json& s : spec_reference()["states"]) {
    ReferenceSample r;
    r.t = number(s["t"]);
    r.state = {number(s["x1"]),     number(s["y1"]),     number(s["theta1"]),     number(s["theta2"]),
               number(s["x1_dot"]), number(s["y1_dot"]), number(s["theta1_dot"]), number(s["theta2_dot"])};
    r.values = s;
    samples.push_back(r);
  }
  return samples;
}

/// The reference sample at time t (which must be one of 1, 2, 5, 10).
inline ReferenceSample reference_at(double t) {
  for (const ReferenceSample& s : reference_samples())
    if (s.t == t) return s;
  throw std::runtime_error("no reference sample at t = " + std::to_string(t));
}

/// Largest absolute difference over the eight generalized coordinates and rates.
inline double state_error(const State& a, const State& b) { return (a.vector() - b.vector()).cwiseAbs().maxCoeff(); }

}  // namespace linkage::test
