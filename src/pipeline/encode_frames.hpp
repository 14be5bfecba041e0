#pragma once
// The drawing-and-encoding loop every clip shares (the homework's and any mechanism's):
// frames drawn on this thread into a few reused buffers while the encoder (and PNG
// compression) run on others, into a video and/or a numbered PNG sequence.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>

#include "core/frame.hpp"
#include "pipeline/clip_result.hpp"
#include "render/frame_layout.hpp"

namespace linkage {

/// Draws frame k of `count` with `draw(k, frame)` and encodes it into `video` (an .mp4,
/// .gif or .webm, when given) and `frames` (a folder, when given); adds the encoders' figures to
/// `result` (the drawing's own are the caller's to add).
void encode_frames(const std::optional<std::filesystem::path>& video,
                   const std::optional<std::filesystem::path>& frames, const RenderSettings& settings, long count,
                   const std::function<void(std::size_t, Frame&)>& draw, const ClipProgress& progress,
                   ClipResult& result);

/// One still, frame `index` at time `t` of `layout`, into `out`: a PNG, with `raster`
/// drawing the motion into the scene's buffer, or an SVG or PDF, with `vector` drawing it
/// onto the vector surface's context; counts a PNG written in `result`.
void write_still(FrameLayout& layout, std::size_t index, double t, const RenderSettings& settings,
                 const std::filesystem::path& out, const std::function<void(Frame&)>& raster,
                 const std::function<void(cairo_t*)>& vector, ClipResult& result);

}  // namespace linkage
