// The render step: the step's clip or still produced in process by the same pipeline as
// the render command (src/pipeline), so a lesson's clips are exactly what it gives.
#include <algorithm>

#include "core/progress.hpp"
#include "lesson/runner_context.hpp"

namespace linkage::lesson {

Clip render_clip(const RenderStep& render, Quality quality, const std::filesystem::path& out_dir,
                 const std::filesystem::path& assets) {
  Clip clip;
  clip.inputs = render.run.inputs;
  clip.simulation = render.run.options;
  clip.settings = render.settings;
  if (quality == Quality::draft) {
    clip.settings.width = kDraftWidth;
    clip.settings.height = kDraftHeight;
    clip.settings.fps = std::min(render.settings.fps, kDraftFps);
  }
  clip.theme = load_theme(clip.settings.theme, assets, "theme");
  clip.out = out_dir / render.out;
  return clip;
}

void run_render(RunContext& c, const Step& step, const RenderStep& s) {
  const nlohmann::json results = c.cached(step, [&] {
    const Clip clip = render_clip(s, c.options.quality, c.options.out_dir, c.options.assets);
    std::optional<Progress> progress;
    const ClipResult made = produce_clip(clip, [&](ClipStage stage, long done, long total) {
      if (stage != ClipStage::draw) return;
      if (!progress) progress.emplace("render " + s.out, total, "frames");
      progress->update(done);
    });
    nlohmann::json made_results = nlohmann::json::object();
    if (!made.warnings.empty()) made_results["warnings"] = made.warnings;
    return made_results;
  });
  c.warn(step, results);
  const FigureRef::Kind kind = is_still(s.kind) ? FigureRef::Kind::image : FigureRef::Kind::video;
  c.both([&](Writer& w) { w.figure(c.figure(s.out, kind, s.caption)); });
}

}  // namespace linkage::lesson
