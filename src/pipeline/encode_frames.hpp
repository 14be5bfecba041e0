#pragma once
// The drawing-and-encoding loop every clip shares (the homework's and any mechanism's):
// frames drawn on this thread into a few reused buffers while the encoder (and PNG
// compression) run on others, into a video and/or a numbered PNG sequence.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>

#include "core/frame.hpp"
#include "pipeline/clip.hpp"

namespace linkage {

/// Draws frame k of `count` with `draw(k, frame)` and encodes it into `video` (an .mp4,
/// .gif or .webm, when given) and `frames` (a folder, when given); adds the encoders' figures to
/// `result` (the drawing's own are the caller's to add).
void encode_frames(const std::optional<std::filesystem::path>& video,
                   const std::optional<std::filesystem::path>& frames, const RenderSettings& settings, long count,
                   const std::function<void(std::size_t, Frame&)>& draw, const ClipProgress& progress,
                   ClipResult& result);

}  // namespace linkage
