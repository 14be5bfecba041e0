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
  for (std::string& name : clip.settings.panel) name = system.mechanism().unaliased(name);  // theta1: 1.theta
  clip.ensemble = request.ensemble;
  clip.spread = request.spread;
  const std::string& compare = request.compare;
  if (!compare.empty()) {
    switch (kind_of(compare, plan)) {
      case CompareKind::trajectory: {
        MechanismRun run;
        run.label = fs::path(compare).filename().string();
        // By the columns' keys, or by their aliases (the homework's x1, theta1 as simulate writes them).
        const MechanismGeometry geometry = mechanism_geometry(system);
        const auto read = [&](const Mechanism* aliases) {
          return std::make_shared<const TrajectoryTable>(
              read_trajectory_csv(compare, mechanism_pose_columns(geometry, aliases),
                                  plan.compare_origin + ", to draw the bodies of " + system.mechanism().name + ",", 0.0,
                                  clip_end(clip.settings, clip.is_still(), clip.frames.has_value())));
        };
        const bool aliased = mechanism_pose_columns(geometry, &system.mechanism()) != mechanism_pose_columns(geometry);
        try {
          run.table = read(nullptr);
        } catch (const Error& e) {
          // A file without the keys' columns is read by the aliases' names, whose error then stands.
          if (!aliased || std::string(e.what()).find(": no column '") == std::string::npos) throw;
          run.table = read(&system.mechanism());
          run.aliased = true;
        }
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
