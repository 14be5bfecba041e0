#include "cli/overlay_options.hpp"

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage::cli {

namespace {

void resolve_compare(const std::string& list, const MechanismOptions& mechanism, const InputOptions& inputs,
                     const SimulationFlags& simulation, MechanismClip& clip, std::unique_ptr<sym::System>& compared) {
  SimulationFlags flags = simulation;
  std::vector<std::string> settings;
  for (const std::string& item : split_commas(list)) {
    const auto equals = item.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == item.size())
      throw Error::input("--compare: '" + item +
                         "' is not NAME=VALUE; e.g. --compare 2.theta=-1.2000001 or --compare integrator=rk4,case=1");
    const std::string name = item.substr(0, equals), value = item.substr(equals + 1);
    if (name == "integrator")
      flags.integrator = value;
    else if (name == "case")
      flags.which_case = value;
    else
      settings.push_back(item);
  }
  MechanismRun run;
  try {
    run.simulation = resolve_simulation_flags(flags, clip.settings.duration);
  } catch (const Error& e) {
    throw Error::input("--compare: " + describe(e));
  }
  run.label = list;
  for (std::size_t at = run.label.find(','); at != std::string::npos; at = run.label.find(',', at + 2))
    run.label.insert(at + 1, " ");
  if (settings.empty()) {
    run.initial = {};  // the clip's own, filled in by the caller
  } else {
    Mechanism other = chosen_mechanism(mechanism, inputs);
    for (const std::string& setting : settings) {
      try {
        apply_setting(other, setting, "--compare " + setting.substr(0, setting.find('=')));
      } catch (const Error& e) {
        throw Error::input("--compare: " + e.detail() + "; or integrator=NAME, case=1|2|3");
      }
    }
    compared = std::make_unique<sym::System>(std::move(other));
    run.system = compared.get();
    run.initial = sym::checked_initial_state(*compared).state;
  }
  clip.compare = std::move(run);
}

}  // namespace

void add_overlay_options(CLI::App* sub, OverlayFlags& flags, const std::string& group) {
  sub->add_option("--ensemble", flags.ensemble,
                  "With --mechanism: draw N runs (2 .. 200) whose first coordinate starts up to --spread apart, "
                  "faint in a colour ramp behind the main run (chaos fanning out)")
      ->type_name("N")
      ->group(group);
  sub->add_option("--spread", flags.spread,
                  "The ensemble's largest initial offset of the first coordinate, rad or m (default 1e-6)")
      ->type_name("X")
      ->group(group);
  sub->add_option("--compare", flags.compare,
                  "With --mechanism: overlay a second run with other settings in a second colour, NAME=VALUE,...: "
                  "a --set name (2.theta=-1.2000001, L=0.4), integrator=NAME, case=N")
      ->type_name("SETTINGS")
      ->group(group);
}

void resolve_overlay_flags(const OverlayFlags& flags, const MechanismOptions& mechanism, const InputOptions& inputs,
                           const SimulationFlags& simulation, MechanismClip& clip,
                           std::unique_ptr<sym::System>& compared) {
  if (!flags.ensemble.empty()) {
    const auto whole = flags.ensemble.find_first_not_of("0123456789");
    const double n = whole == std::string::npos && flags.ensemble.size() < 5 ? std::stod(flags.ensemble) : -1;
    if (n < 2 || n > 200)
      throw Error::input("--ensemble: '" + flags.ensemble + "' is not a whole number of runs in 2 .. 200");
    clip.ensemble = static_cast<int>(n);
  }
  if (!flags.spread.empty()) {
    if (flags.ensemble.empty()) throw Error::input("--spread: applies only with --ensemble N");
    const std::string range = "--spread: '" + flags.spread + "' must be a finite number > 0 (rad or m)";
    double spread = 0;
    try {
      spread = parse_number(flags.spread, "--spread", "");
    } catch (const Error&) {
      throw Error::input(range);
    }
    if (!(std::isfinite(spread) && spread > 0)) throw Error::input(range);
    clip.spread = spread;
  }
  if (!flags.compare.empty()) resolve_compare(flags.compare, mechanism, inputs, simulation, clip, compared);
}

}  // namespace linkage::cli
