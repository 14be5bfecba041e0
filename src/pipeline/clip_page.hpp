#pragma once
// A clip as one interactive page (`linkage render --out clip.html`): every frame painted
// by the mechanism painter, each of its steps (render/paint_layer.hpp) onto its own
// Cairo SVG surface, so the browser draws Cairo's own paths and a viewer can hide a kind
// of arrow; a layer that is the same in every frame (a fixed camera's grid, the title) is
// kept once. With each frame, its arrows' pixels and values for reading under the cursor.
#include <filesystem>

#include "pipeline/clip_result.hpp"
#include "pipeline/mechanism_clip.hpp"

namespace linkage {

/// Writes the page of `frames` (the clip `clip`'s) to `out` atomically (encode/html_page).
void produce_clip_page(MechanismClipFrames& frames, const MechanismClip& clip, const std::filesystem::path& out,
                       const ClipProgress& progress, ClipResult& result);

}  // namespace linkage
