#include "pipeline/clip_request.hpp"

#include <algorithm>
#include <vector>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "model/mechanism_toml.hpp"
#include "render/frame_layout.hpp"
#include "render/theme.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace fs = std::filesystem;

namespace {

/// The last time drawn: the duration of a clip or frames, the time of a still, or both.
double clip_end(const RenderSettings& s, bool still, bool frames) {
  return std::max(still ? s.at : 0.0, !still || frames ? s.duration : 0.0);
}

/// The settings the clip draws: the request's, with the equations it shows (made only
/// then: `equations` derives the case); a draft leaves out equations that need a larger
/// frame to be legible.
RenderSettings shown_settings(RenderSettings settings, const std::function<EquationsText()>& equations,
                              const ClipPlan& plan) {
  if (!settings.elements.has(Element::equations)) return settings;
  settings.equations = equations();
  if (plan.draft) {
    try {
      (void)frame_bands(settings);
    } catch (const Error&) {
      settings.elements.hide(Element::equations);
    }
  }
  return settings;
}

CompareKind kind_of(const std::string& compare, const ClipPlan& plan) {
  return plan.compare_files ? compare_kind(compare) : CompareKind::settings;
}

/// Another mechanism drawn over the clip's (its bodies named as the clip's).
MechanismRun compared_mechanism(const std::string& spec, const sym::System& system, const MechanismClip& clip,
                                const ClipPlan& plan, std::unique_ptr<sym::System>& compared) {
  const Mechanism& own = system.mechanism();
  Mechanism other;
  try {
    other = load_mechanism(spec);
  } catch (const Error& e) {
    throw Error::input(plan.compare_origin + ": " +
                       (e.setting_is_name() ? plan.spell(e.setting()) + ": " + e.detail() : e.what()));
  }
  std::vector<std::string> ours, theirs;
  for (const Body& body : own.bodies) ours.push_back(body.name);
  for (const Body& body : other.bodies) theirs.push_back(body.name);
  if (ours != theirs) {
    std::string message = plan.compare_origin;
    message.append(" ").append(spec).append(": its bodies (").append(join_names(theirs, "")).append(") are not ");
    message.append(own.name).append("'s (").append(join_names(ours, ""));
    message.append("); a compared mechanism's bodies must be named as the clip's");
    throw Error::input(message);
  }
  MechanismRun run;
  run.simulation = clip.simulation;
  run.label = other.name;
  run.centred = true;
  compared = std::make_unique<sym::System>(std::move(other));
  run.system = compared.get();
  run.initial = sym::checked_initial_state(*compared).state;
  return run;
}

// A trajectory file to draw the bodies of `system` from (render --compare FILE.csv): by
// the columns' keys or by the names the file's [aliases] give them (the homework's x1,
// theta1 as simulate writes them; then `aliased`), with each body's pose or the
// generalized coordinates it follows from. Error::input naming the first column missing,
// and the header's name it may be a misspelling of.
TrajectoryTable compared_table(const std::string& file, const sym::System& system, const std::string& purpose,
                               double end, bool& aliased) {
  TrajectoryTable table = read_trajectory_csv(file, {"t"}, purpose, 0.0, end);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const auto missing = [&](const std::vector<std::string>& names) {
    const auto it = std::find_if(names.begin(), names.end(), [&](const std::string& n) { return !table.find(n); });
    return it == names.end() ? std::string() : *it;
  };
  for (const Mechanism* names : {static_cast<const Mechanism*>(nullptr), &system.mechanism()}) {
    if (missing(mechanism_pose_columns(geometry, names)).empty() ||
        missing(mechanism_coordinate_columns(system, names)).empty()) {
      aliased = names != nullptr;
      return table;
    }
  }
  // Named as the file names its other columns: by the aliases when it has any of them.
  const std::vector<std::string> keys = mechanism_coordinate_columns(system);
  const std::vector<std::string> aliases = mechanism_coordinate_columns(system, &system.mechanism());
  const bool by_alias = std::any_of(aliases.begin() + 1, aliases.end(), [&](const std::string& n) {
    return table.find(n) && std::find(keys.begin(), keys.end(), n) == keys.end();
  });
  const std::vector<std::string>& needed = by_alias ? aliases : keys;
  const std::vector<std::string> poses = mechanism_pose_columns(geometry, by_alias ? &system.mechanism() : nullptr);
  const std::string absent = missing(needed);
  std::string hint;  // a name of the header that is none of those looked for, but close to the one missing
  for (const std::string& name : table.names)
    if (hint.empty() && std::find(needed.begin(), needed.end(), name) == needed.end() &&
        std::find(poses.begin(), poses.end(), name) == poses.end() && closest_name(name, {absent}))
      hint = " (the header has '" + name + "': did you mean '" + absent + "'?)";
  throw Error::input(table.file + ": no column '" + absent + "'" + hint + "; " + purpose + " needs the columns " +
                     join_names(needed, "") + ", or each body's pose " + join_names(poses, "") +
                     " (as linkage simulate writes them); the header has " + join_names(table.names, ""));
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

CheckedMechanismClip mechanism_clip(const RenderRequest& request, const sym::System& system,
                                    const GiNaC::exmap& initial, const SimulationOptions& simulation,
                                    const ClipPlan& plan) {
  CheckedMechanismClip made;
  MechanismClip& clip = made.clip;
  clip.settings = request.settings;
  // The file's [picture] gives the defaults the flags have not set.
  const Picture& picture = system.mechanism().picture;
  if (!request.titled) clip.settings.title = picture.title.empty() ? system.mechanism().title : picture.title;
  clip.frames = plan.frames;
  clip.out = plan.out;
  clip.theme = load_theme(clip.settings.theme, plan.assets, "theme");
  clip.simulation = simulation;
  clip.trails = request.trails.empty() ? picture.trails : request.trails;
  clip.trail_seconds = trail_seconds_of(system, request.trail_length);
  clip.trail_cycle = request.trail_length == "cycle";
  clip.points = request.points;
  for (std::string& name : clip.settings.panel) name = system.mechanism().unaliased(name);  // theta1: 1.theta
  clip.ensemble = request.ensemble;
  clip.spread = request.spread;
  const std::string& compare = request.compare;
  if (!compare.empty()) {
    switch (kind_of(compare, plan)) {
      case CompareKind::trajectory: {
        MechanismRun run;
        run.label = fs::path(compare).filename().string();
        run.table = std::make_shared<const TrajectoryTable>(compared_table(
            compare, system, plan.compare_origin + ", to draw the bodies of " + system.mechanism().name + ",",
            clip_end(clip.settings, clip.is_still(), clip.frames.has_value()), run.aliased));
        clip.compare = std::move(run);
        break;
      }
      case CompareKind::mechanism:
        clip.compare = compared_mechanism(compare, system, clip, plan, made.compared);
        break;
      case CompareKind::settings:
        clip.compare = mechanism_compared_run(split_commas(compare), system.mechanism(), clip.simulation,
                                              plan.compare_origin, made.compared);
        break;
    }
  }
  clip.settings = shown_settings(
      std::move(clip.settings), [&] { return plan.equations(system, simulation.case_id); }, plan);
  clip.validate(system);
  if (clip.compare && clip.compare->system == nullptr) clip.compare->initial = initial;
  return made;
}

}  // namespace linkage
