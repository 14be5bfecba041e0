#pragma once
// --ensemble N --spread X and --compare SETTINGS|FILE for `render`, the homework's clip
// or a mechanism's: other runs drawn over the main one (nearby initial states for chaos,
// one run with other settings, another mechanism, or a trajectory file), checked before
// any work.
#include <memory>
#include <string>

#include "cli/input_options.hpp"
#include "cli/mechanism_options.hpp"
#include "cli/simulation_flags.hpp"
#include "pipeline/clip.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "pipeline/render_options.hpp"
#include "symbolic/system.hpp"

namespace linkage::cli {

/// What --compare names, by its form: a trajectory (.csv), a mechanism (.toml or a
/// shipped name), or NAME=VALUE settings.
enum class CompareKind { settings, trajectory, mechanism };
[[nodiscard]] CompareKind compare_kind(const std::string& compare);

/// Sets clip.ensemble, clip.spread and clip.compare from the request (the flags read
/// through render_options, Error::input naming --compare and the valid range). --compare NAME=VALUE,...:
/// integrator=NAME, case=N, or a --set name; a parameter or coordinate, or another mechanism (its bodies named as the
/// clip's), builds the compared run's own system, kept in `compared` (which must outlive the clip); FILE.csv: the
/// bodies' columns, covering the clip.
void resolve_overlay_flags(const RenderRequest& request, const MechanismOptions& mechanism, const InputOptions& inputs,
                           const SimulationFlags& simulation, MechanismClip& clip,
                           std::unique_ptr<sym::System>& compared);

/// The same for the homework's clip: settings are its input names (theta1=0.1000001,
/// L=0.4), integrator=NAME, case=N; FILE.csv needs t, x1, y1, theta1, theta2.
void resolve_homework_overlays(const RenderRequest& request, Clip& clip);

}  // namespace linkage::cli
