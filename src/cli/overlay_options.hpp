#pragma once
// --ensemble N --spread X and --compare SETTINGS for `render --mechanism`: other runs
// drawn over the main one (nearby initial states for chaos, or one run with other
// settings), checked before any work.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "cli/input_options.hpp"
#include "cli/mechanism_options.hpp"
#include "cli/simulation_flags.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "symbolic/system.hpp"

namespace linkage::cli {

struct OverlayFlags {
  std::string ensemble, spread, compare;
  /// Whether any of the flags was given.
  [[nodiscard]] bool any() const { return !ensemble.empty() || !spread.empty() || !compare.empty(); }
};

/// Adds --ensemble, --spread and --compare to `sub` in `group`.
void add_overlay_options(CLI::App* sub, OverlayFlags& flags, const std::string& group);

/// Sets clip.ensemble, clip.spread and clip.compare from the flags (Error::input naming
/// the flag and the valid range). --compare NAME=VALUE,...: integrator=NAME, case=N, or
/// a --set name; a parameter or coordinate builds the compared run's own system, kept
/// in `compared` (which must outlive the clip).
void resolve_overlay_flags(const OverlayFlags& flags, const MechanismOptions& mechanism, const InputOptions& inputs,
                           const SimulationFlags& simulation, MechanismClip& clip,
                           std::unique_ptr<sym::System>& compared);

}  // namespace linkage::cli
