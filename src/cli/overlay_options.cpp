#include "cli/overlay_options.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "model/mechanism_toml.hpp"
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
  const SimulationOptions options = resolve_simulation_flags(simulation, clip.settings.duration);
  clip.compare =
      mechanism_compared_run(split_commas(list), chosen_mechanism(mechanism, inputs), options, "--compare", compared);
  if (!compared) clip.compare->initial = {};  // the clip's own, filled in by the caller
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

void resolve_overlay_flags(const RenderRequest& request, const MechanismOptions& mechanism, const InputOptions& inputs,
                           const SimulationFlags& simulation, MechanismClip& clip,
                           std::unique_ptr<sym::System>& compared) {
  clip.ensemble = request.ensemble;
  clip.spread = request.spread;
  if (!request.compare.empty()) resolve_compare(request.compare, mechanism, inputs, simulation, clip, compared);
}

void resolve_homework_overlays(const RenderRequest& request, Clip& clip) {
  clip.ensemble = request.ensemble;
  clip.spread = request.spread;
  const std::string& compare = request.compare;
  if (compare.empty()) return;
  switch (compare_kind(compare)) {
    case CompareKind::trajectory: {
      HomeworkRun run{clip.inputs, clip.simulation, fs::path(compare).filename().string(), nullptr};
      run.table = std::make_shared<const TrajectoryTable>(read_homework_trajectory(
          compare, "--compare", clip_end(clip.settings, clip.is_still(), clip.frames.has_value())));
      clip.compare = std::move(run);
      break;
    }
    case CompareKind::mechanism:
      throw Error::input("--compare " + compare +
                         ": another mechanism applies with --mechanism; the homework compares settings "
                         "(theta1=0.1000001, L=0.4, integrator=rk4, case=1) or a trajectory FILE.csv");
    case CompareKind::settings: {
      HomeworkRun run = homework_compared_run(split_commas(compare), clip.inputs, clip.simulation, "--compare");
      run.label = with_spaces(compare);
      clip.compare = std::move(run);
      break;
    }
  }
}

}  // namespace linkage::cli
