#pragma once
// Runs for the pipeline's tests, built as a lesson's parser builds them.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "columns/mechanism_columns.hpp"
#include "pipeline/run.hpp"

namespace linkage::test {

/// A run of nothing built yet, for `duration` s by DOP853.
inline Run bare_run(const std::string& label, double duration) {
  Run run;
  run.label = label;
  run.series = label;
  run.options.duration = duration;
  return run;
}

/// The homework from its default inputs (two-blocks.toml, named by its aliases), for
/// `duration` s by DOP853, as a lesson's parser builds it.
inline Run homework_run(const std::string& label, double duration) {
  Run run = bare_run(label, duration);
  run.built = build_mechanism(kDefaultMechanism, default_mechanism_settings(run.inputs), "test", true);
  return run;
}

/// A mechanism (a shipped name) with NAME=VALUE settings, run for `duration` s.
inline Run mechanism_run(const std::string& label, const std::string& spec, const std::vector<std::string>& settings,
                         double duration) {
  Run run = bare_run(label, duration);
  run.mechanism = spec;
  run.settings = settings;
  run.built = build_mechanism(spec, settings, "test");
  return run;
}

/// One column of a built mechanism's trajectory table, by name ("2.theta").
inline MechanismColumn mechanism_column(const Run& run, const std::string& name) {
  for (const MechanismColumn& c : mechanism_columns(*run.built->system))
    if (c.name == name) return c;
  throw std::invalid_argument("no column " + name);
}

/// One column under the names the run's mechanism goes by ("theta1" on the homework).
inline MechanismColumn named_column(const Run& run, const std::string& name) {
  for (const MechanismColumn& c : run.built->named_columns())
    if (c.name == name) return c;
  throw std::invalid_argument("no column " + name);
}

}  // namespace linkage::test
