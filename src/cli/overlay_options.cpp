#include "cli/overlay_options.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "model/name_match.hpp"
#include "report/notation.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage::cli {
namespace fs = std::filesystem;

namespace {

/// The last time drawn: the duration of a clip or frames, the time of a still, or both.
double clip_end(const RenderSettings& s, bool still, bool frames) {
  return std::max(still ? s.at : 0.0, !still || frames ? s.duration : 0.0);
}

bool is_still_out(const std::optional<std::filesystem::path>& out) { return out && out->extension() == ".png"; }

std::string with_spaces(std::string label) {
  for (std::size_t at = label.find(','); at != std::string::npos; at = label.find(',', at + 2))
    label.insert(at + 1, " ");
  return label;
}

void resolve_compare(const std::string& list, const MechanismOptions& mechanism, const InputOptions& inputs,
                     const SimulationFlags& simulation, MechanismClip& clip, std::unique_ptr<sym::System>& compared) {
  const CompareKind kind = compare_kind(list);
  if (kind == CompareKind::trajectory) {
    const sym::System main(chosen_mechanism(mechanism, inputs));
    MechanismRun run;
    run.label = fs::path(list).filename().string();
    run.table = std::make_shared<const TrajectoryTable>(
        read_trajectory_csv(list, mechanism_pose_columns(mechanism_geometry(main)),
                            "--compare, to draw the bodies of " + main.mechanism().name + ",", 0.0,
                            clip_end(clip.settings, is_still_out(clip.out), clip.frames.has_value())));
    clip.compare = std::move(run);
    return;
  }
  if (kind == CompareKind::mechanism) {
    const Mechanism own = chosen_mechanism(mechanism, inputs);
    Mechanism other;
    try {
      other = load_mechanism(list);
    } catch (const Error& e) {
      throw Error::input("--compare: " + describe(e));
    }
    std::vector<std::string> ours, theirs;
    for (const Body& body : own.bodies) ours.push_back(body.name);
    for (const Body& body : other.bodies) theirs.push_back(body.name);
    if (ours != theirs)
      throw Error::input(
          concat({"--compare ", list, ": its bodies (", join_names(theirs, ""), ") are not ", own.name, "'s (",
                  join_names(ours, ""), "); a compared mechanism's bodies must be named as the clip's"}));
    MechanismRun run;
    try {
      run.simulation = resolve_simulation_flags(simulation, clip.settings.duration);
    } catch (const Error& e) {
      throw Error::input("--compare: " + describe(e));
    }
    run.label = other.name;
    run.centred = true;
    compared = std::make_unique<sym::System>(std::move(other));
    run.system = compared.get();
    run.initial = sym::checked_initial_state(*compared).state;
    clip.compare = std::move(run);
    return;
  }
  SimulationFlags flags = simulation;
  std::vector<std::string> settings;
  for (const std::string& item : split_commas(list)) {
    const auto equals = item.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == item.size())
      throw Error::input("--compare: '" + item +
                         "' is not NAME=VALUE, a .csv trajectory, a .toml mechanism or a shipped mechanism's name; "
                         "e.g. --compare 2.theta=-1.2000001, --compare integrator=rk4,case=1 or --compare run.csv");
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
  run.label = with_spaces(list);
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

// --ensemble N and --spread X, as numbers in range.
void resolve_ensemble(const OverlayFlags& flags, int& ensemble, double& spread) {
  if (!flags.ensemble.empty()) {
    const auto whole = flags.ensemble.find_first_not_of("0123456789");
    const double n = whole == std::string::npos && flags.ensemble.size() < 5 ? std::stod(flags.ensemble) : -1;
    if (n < 2 || n > 200)
      throw Error::input("--ensemble: '" + flags.ensemble + "' is not a whole number of runs in 2 .. 200");
    ensemble = static_cast<int>(n);
  }
  if (!flags.spread.empty()) {
    if (flags.ensemble.empty()) throw Error::input("--spread: applies only with --ensemble N");
    const std::string range = "--spread: '" + flags.spread + "' must be a finite number > 0 (rad or m)";
    double value = 0;
    try {
      value = parse_number(flags.spread, "--spread", "");
    } catch (const Error&) {
      throw Error::input(range);
    }
    if (!(std::isfinite(value) && value > 0)) throw Error::input(range);
    spread = value;
  }
}

}  // namespace

CompareKind compare_kind(const std::string& compare) {
  if (compare.find('=') != std::string::npos) return CompareKind::settings;
  const std::string extension = fs::path(compare).extension().string();
  if (extension == ".csv") return CompareKind::trajectory;
  if (extension == ".toml") return CompareKind::mechanism;
  const std::vector<std::string> shipped = shipped_mechanism_names();
  if (std::find(shipped.begin(), shipped.end(), compare) != shipped.end()) return CompareKind::mechanism;
  return CompareKind::settings;
}

void add_overlay_options(CLI::App* sub, OverlayFlags& flags, const std::string& group) {
  sub->add_option("--ensemble", flags.ensemble,
                  "Draw N runs (2 .. 200) starting up to --spread apart, faint in a colour ramp behind the main "
                  "run (chaos fanning out): the homework's theta1, a mechanism's first coordinate")
      ->type_name("N")
      ->group(group);
  sub->add_option("--spread", flags.spread,
                  "The ensemble's largest initial offset, rad or m (default 1e-6); run k starts spread k/(N-1) away")
      ->type_name("X")
      ->group(group);
  sub->add_option("--compare", flags.compare,
                  "Overlay a second run in a second colour: NAME=VALUE,... settings (the homework's input names "
                  "theta1=0.1000001, L=0.4; with --mechanism a --set name 2.theta=-1.2000001; integrator=NAME, "
                  "case=N); FILE.csv, a trajectory as linkage simulate writes it (e.g. your own integrator's), "
                  "interpolated linearly in t at each frame; or with --mechanism another mechanism (FILE.toml or a "
                  "shipped name) whose bodies have the same names, run with the same settings")
      ->type_name("SETTINGS|FILE")
      ->group(group);
}

void resolve_overlay_flags(const OverlayFlags& flags, const MechanismOptions& mechanism, const InputOptions& inputs,
                           const SimulationFlags& simulation, MechanismClip& clip,
                           std::unique_ptr<sym::System>& compared) {
  resolve_ensemble(flags, clip.ensemble, clip.spread);
  if (!flags.compare.empty()) resolve_compare(flags.compare, mechanism, inputs, simulation, clip, compared);
}

void resolve_homework_overlays(const OverlayFlags& flags, Clip& clip) {
  resolve_ensemble(flags, clip.ensemble, clip.spread);
  if (flags.compare.empty()) return;
  switch (compare_kind(flags.compare)) {
    case CompareKind::trajectory: {
      HomeworkRun run{clip.inputs, clip.simulation, fs::path(flags.compare).filename().string(), nullptr};
      run.table = std::make_shared<const TrajectoryTable>(read_homework_trajectory(
          flags.compare, "--compare", clip_end(clip.settings, clip.is_still(), clip.frames.has_value())));
      clip.compare = std::move(run);
      break;
    }
    case CompareKind::mechanism:
      throw Error::input("--compare " + flags.compare +
                         ": another mechanism applies with --mechanism; the homework compares settings "
                         "(theta1=0.1000001, L=0.4, integrator=rk4, case=1) or a trajectory FILE.csv");
    case CompareKind::settings: {
      HomeworkRun run = homework_compared_run(split_commas(flags.compare), clip.inputs, clip.simulation, "--compare");
      run.label = with_spaces(flags.compare);
      clip.compare = std::move(run);
      break;
    }
  }
}

}  // namespace linkage::cli
