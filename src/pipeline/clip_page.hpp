#pragma once
// A clip as one interactive page (`linkage render --out clip.html`): every frame painted
// by the mechanism painter, each of its steps (render/paint_layer.hpp) onto its own
// Cairo SVG surface, read back as canvas operations (encode/canvas_ops.hpp), so the page
// paints Cairo's own paths and a viewer can hide a kind of arrow; a layer that is the same in every frame (a fixed
// camera's grid, the title) is kept once. With each frame, its arrows' pixels and values for reading under the cursor;
// with the clip, the panel's curves and the motion's table.
#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "encode/canvas_ops.hpp"
#include "pipeline/clip_result.hpp"
#include "pipeline/mechanism_clip.hpp"

namespace linkage {

/// Writes the page of `frames` (the clip `clip`'s, of `system`) to `out` atomically
/// (encode/html_page), with the motion's table to download (motion_csv) and the panel's
/// curves to read under the cursor.
/// Frame k's layers as the page paints them: each paint layer's canvas operations (empty
/// where it draws nothing), their styles, glyphs and paths kept in `canvas`. `settings`:
/// the clip's that `frames` draws.
std::array<nlohmann::json, kPaintLayers> frame_canvas_ops(MechanismClipFrames& frames, std::size_t k,
                                                          const RenderSettings& settings, CanvasOps& canvas);

void produce_clip_page(const sym::System& system, MechanismClipFrames& frames, const MechanismClip& clip,
                       const std::filesystem::path& out, const ClipProgress& progress, ClipResult& result);

}  // namespace linkage
