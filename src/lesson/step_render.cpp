// The render step: the step's clip or still assembled and produced in process by the same
// pipeline as the render command (src/pipeline), so a lesson's clips are exactly what it gives:
// a mode's (mode, amplitude, nonlinear) and every mode's sheet (modes_sheet) among them.
#include <algorithm>
#include <optional>

#include "core/progress.hpp"
#include "lesson/runner_context.hpp"
#include "pipeline/clip_request.hpp"
#include "pipeline/mode_motion.hpp"
#include "pipeline/modes_sheet.hpp"
#include "report/mechanism_latex.hpp"
#include "report/mechanism_text.hpp"

namespace linkage::lesson {

namespace {

/// The step's request as parse_render read it: at draft quality 480x270 and at most 15 fps.
RenderRequest step_request(const RenderStep& render, Quality quality) {
  RenderRequest request = render.request;
  request.titled = true;  // the mechanism's title, the default, was set when the lesson was read
  if (quality == Quality::draft) {
    request.settings.width = kDraftWidth;
    request.settings.height = kDraftHeight;
    request.settings.fps = std::min(render.request.settings.fps, kDraftFps);
  }
  return request;
}

ClipPlan step_plan(const std::filesystem::path& out, const std::filesystem::path& assets, Quality quality) {
  ClipPlan plan;
  plan.out = out;
  plan.assets = assets;
  plan.equations = case_equations_as<EquationsText>;
  plan.compare_origin = "compare";
  plan.compare_files = false;
  plan.draft = quality == Quality::draft;  // a draft previews the motion
  return plan;
}

/// How a handout shows a render step's output: a still as a figure, a clip as a video, a
/// page (.html) as a link to open.
FigureRef::Kind figure_kind(OutputKind kind) {
  switch (kind) {
    case OutputKind::png:
    case OutputKind::svg:
    case OutputKind::pdf:
      return FigureRef::Kind::image;
    case OutputKind::mp4:
    case OutputKind::gif:
    case OutputKind::webm:
      return FigureRef::Kind::video;
    case OutputKind::html:
      return FigureRef::Kind::file;
  }
  return FigureRef::Kind::file;
}

}  // namespace

CheckedMechanismClip render_clip(const RenderStep& render, Quality quality, const std::filesystem::path& out_dir,
                                 const std::filesystem::path& assets, const ModeMotion* mode) {
  const BuiltMechanism& built = *render.run.built;
  RenderRequest request = step_request(render, quality);
  if (mode != nullptr && request.settings.captions.empty()) request.settings.captions = {{0.0, mode->caption}};
  CheckedMechanismClip made = mechanism_clip(request, *built.system, mode != nullptr ? mode->initial : built.initial,
                                             render.run.options, step_plan(out_dir / render.out, assets, quality));
  if (mode != nullptr) show_mode(made.clip, *mode);
  return made;
}

void run_render(RunContext& c, const Step& step, const RenderStep& s) {
  const nlohmann::json results = c.cached(step, [&] {
    std::optional<Progress> progress;
    const ClipProgress report = [&](ClipStage stage, long done, long total) {
      if (stage != ClipStage::draw) return;
      if (!progress) progress.emplace("render " + s.out, total, "frames");
      progress->update(done);
    };
    const sym::System& system = *s.run.built->system;
    std::optional<ModeMotion> mode;  // the mode drawn instead of the run's motion
    if (s.mode > 0) {
      const Linearization linear = linearize(system);
      mode = mode_motion(system, linear, modal_analysis(linear), s.mode, s.amplitude, s.nonlinear);
    }
    CheckedMechanismClip clip =
        render_clip(s, c.options.quality, c.options.out_dir, c.options.assets, mode ? &*mode : nullptr);
    if (s.kind == OutputKind::html)  // the page's worked equations of the run's case, as render's
      clip.clip.equations_html = mechanism_html(
          work_out_mechanism(s.run.built->system, {static_cast<CaseId>(s.run.options.case_id)}), ReportOptions{});
    ClipResult made;
    if (s.modes_sheet)
      produce_modes_sheet(system, clip.clip, s.amplitude, c.options.out_dir / s.out, "modes_sheet");
    else
      made = produce_mechanism_clip(system, mode ? mode->initial : s.run.built->initial, clip.clip, report);
    nlohmann::json made_results = nlohmann::json::object();
    if (!made.warnings.empty()) made_results["warnings"] = made.warnings;
    return made_results;
  });
  c.warn(step, results);
  c.both([&](Writer& w) { w.figure(c.figure(s.out, figure_kind(s.kind), s.caption)); });
}

}  // namespace linkage::lesson
