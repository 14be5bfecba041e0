#pragma once
// A picture's request (render_options) made into a mechanism's checked clip: the overlays
// (--ensemble, --spread, --compare), the trails, the equations shown, the mechanism's title
// as the default, then every check before any work. One assembly for `linkage render` and
// a lesson's render step.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "integrate/simulation_options.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "pipeline/render_options.hpp"
#include "render/settings.hpp"
#include "symbolic/system.hpp"

namespace linkage {

/// Case `case_id`'s equations of `system` as the text report prints them (report's
/// case_equations, which pipeline may not call: the caller passes it).
using CaseEquationsOf = std::function<EquationsText(const sym::System& system, int case_id)>;

/// What the clip needs besides the request and the run.
struct ClipPlan {
  std::optional<std::filesystem::path> out;     // the video or still, if any
  std::optional<std::filesystem::path> frames;  // a numbered PNG sequence's folder, if any
  std::filesystem::path assets;                 // where the themes are (render/theme)
  CaseEquationsOf equations;                    // for a picture that shows them
  /// How messages name compare: "--compare", or a lesson key's place.
  std::string compare_origin = "--compare";
  /// compare may name a trajectory FILE.csv or another mechanism (the render command's);
  /// else only NAME=VALUE settings.
  bool compare_files = true;
  /// How messages name a setting ("--mechanism" for the command's flag).
  std::function<std::string(std::string_view name)> spell = [](std::string_view name) { return std::string(name); };
  /// A draft: equations too large for the frame are left out instead of refused.
  bool draft = false;
};

/// What --compare names, by its form: a trajectory (.csv), a mechanism (.toml or a
/// shipped name), or NAME=VALUE settings.
enum class CompareKind { settings, trajectory, mechanism };
[[nodiscard]] CompareKind compare_kind(const std::string& compare);

/// A mechanism's clip and the compared run's own system, when compare gives it one (another
/// mechanism, or settings of a parameter or coordinate); the clip points into it.
struct CheckedMechanismClip {
  MechanismClip clip;
  std::unique_ptr<sym::System> compared;
};

/// The clip of `system` from `initial` (loops closed): the request's settings (the title
/// and trails the file's [picture] unless given), trails and overlays (compare: a --set name, integrator=NAME,
/// case=N; another mechanism, its bodies named as the clip's; FILE.csv, the bodies'
/// columns covering the clip), the equations, validated; a compared run without a
/// system of its own starts from `initial`.
[[nodiscard]] CheckedMechanismClip mechanism_clip(const RenderRequest& request, const sym::System& system,
                                                  const GiNaC::exmap& initial, const SimulationOptions& simulation,
                                                  const ClipPlan& plan);

}  // namespace linkage
