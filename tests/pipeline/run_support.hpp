#pragma once
// Runs for the pipeline's tests, built as a lesson's parser builds them.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "integrate/mechanism_columns.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/run.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage::test {

/// The homework from its default inputs, for `duration` s by DOP853.
inline Run homework_run(const std::string& label, double duration) {
  Run run;
  run.label = label;
  run.series = label;
  run.options.duration = duration;
  return run;
}

/// A mechanism (a shipped name) with NAME=VALUE settings, run for `duration` s.
inline Run mechanism_run(const std::string& label, const std::string& spec, const std::vector<std::string>& settings,
                         double duration) {
  Mechanism mechanism = load_mechanism(spec);
  for (const std::string& setting : settings) apply_setting(mechanism, setting, "test");
  auto built = std::make_shared<BuiltMechanism>();
  built->spec = spec;
  built->settings = settings;
  built->system = std::make_shared<const sym::System>(mechanism);
  built->initial = sym::checked_initial_state(*built->system).state;
  Run run = homework_run(label, duration);
  run.mechanism = spec;
  run.settings = settings;
  run.built = built;
  return run;
}

/// One column of a built mechanism's trajectory table, by name ("2.theta").
inline MechanismColumn mechanism_column(const Run& run, const std::string& name) {
  for (const MechanismColumn& c : mechanism_columns(*run.built->system))
    if (c.name == name) return c;
  throw std::invalid_argument("no column " + name);
}

}  // namespace linkage::test
