#include "bench/scenarios.hpp"

#include "core/error.hpp"

namespace linkage::bench {

const std::vector<Scenario>& scenarios() {
  static const std::vector<Scenario> list = [] {
    const Params example_params;
    const State example_state;
    std::vector<Scenario> out;
    out.push_back({"example", "the spec's example", example_params, example_state, 10.0});

    State fast = example_state;
    fast.theta1_dot = 20.0;
    fast.theta2_dot = -35.0;
    out.push_back({"fast", "the example with theta1' = 20, theta2' = -35 rad/s", example_params, fast, 10.0});

    Params near_zero_d = example_params;
    near_zero_d.b = near_zero_d.L / 2.0 - 1e-6 * near_zero_d.L;
    out.push_back({"near-zero-d", "the fast spins with the pin almost at the centres of mass, D = 1e-6 L", near_zero_d,
                   fast, 10.0});

    Params tiny_mass = example_params;
    tiny_mass.m = 1e-6;
    out.push_back({"tiny-mass", "the fast spins with m = 1e-6 kg", tiny_mass, fast, 10.0});

    out.push_back({"long", "the fast scenario over 100 s", example_params, fast, 100.0});
    return out;
  }();
  return list;
}

std::string scenario_names() {
  std::string names;
  for (const Scenario& s : scenarios()) {
    if (!names.empty()) names += ", ";
    names += s.name;
  }
  return names;
}

const Scenario& find_scenario(std::string_view name, const std::string& origin) {
  for (const Scenario& s : scenarios())
    if (s.name == name) return s;
  throw Error::invalid(origin, "'" + std::string(name) + "' is not a scenario; valid: " + scenario_names());
}

}  // namespace linkage::bench
