#pragma once
// Clips for the pipeline's tests.
#include "pipeline/mechanism_clip.hpp"
#include "render/theme.hpp"
#include "symbolic/system.hpp"

namespace linkage::test {

/// A 1 s clip of `system` at 640x360 (30 frames), light theme, a title (drawn with its
/// halo) and the file's trails.
inline MechanismClip small_clip(const sym::System& system) {
  MechanismClip clip;
  clip.settings.width = 640;
  clip.settings.height = 360;
  clip.settings.duration = 1.0;
  clip.settings.title = "A title with a halo";
  clip.simulation.duration = 1.0;
  clip.theme = load_theme("light", {}, "theme");
  clip.trails = system.mechanism().picture.trails;
  return clip;
}

}  // namespace linkage::test
