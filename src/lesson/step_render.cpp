// The render step: the step's clip or still produced in process by the same pipeline as
// the render command (src/pipeline), so a lesson's clips are exactly what it gives.
#include <algorithm>

#include "core/error.hpp"
#include "core/progress.hpp"
#include "lesson/mechanism_render.hpp"
#include "lesson/runner_context.hpp"
#include "model/mechanism_toml.hpp"
#include "render/frame_layout.hpp"
#include "report/mechanism_text.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage::lesson {

namespace {

// A draft previews the motion: equations that need a larger frame to be legible are left out.
void draft_equations(RenderSettings& settings, Quality quality) {
  if (quality != Quality::draft || !settings.elements.has(Element::equations)) return;
  try {
    (void)frame_bands(settings);
  } catch (const Error&) {
    settings.elements.hide(Element::equations);
  }
}

}  // namespace

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
  draft_equations(clip.settings, quality);
  clip.theme = load_theme(clip.settings.theme, assets, "theme");
  clip.out = out_dir / render.out;
  if (render.mechanism.empty()) {  // a mechanism's are its own (mechanism_render)
    clip.ensemble = render.ensemble;
    clip.spread = render.spread;
    if (!render.compare.empty())
      clip.compare = homework_compared_run(render.compare, clip.inputs, clip.simulation, "compare");
  }
  return clip;
}

EquationsText render_equations(const sym::System& system, int case_id) {
  CaseEquations e = case_equations(system, static_cast<CaseId>(case_id));
  return {std::move(e.heading), std::move(e.lines)};
}

MechanismRender mechanism_render(const RenderStep& render, const std::string& origin) {
  MechanismRender out;
  Mechanism mechanism = load_mechanism(render.mechanism);
  for (const std::string& setting : render.settings_list) apply_setting(mechanism, setting, origin);
  out.system = std::make_unique<sym::System>(mechanism);
  out.state = sym::checked_initial_state(*out.system).state;
  out.clip.simulation = render.run.options;
  out.clip.settings = render.settings;
  out.clip.trails = render.trails;
  out.clip.ensemble = render.ensemble;
  out.clip.spread = render.spread;
  if (!render.compare.empty()) {
    out.clip.compare = mechanism_compared_run(render.compare, mechanism, render.run.options, "compare", out.compared);
    if (!out.compared) out.clip.compare->initial = out.state;
  }
  if (out.clip.settings.elements.has(Element::equations))
    out.clip.settings.equations = render_equations(*out.system, out.clip.simulation.case_id);
  out.clip.out = render.out;  // checked by its name here; the step puts it in the output folder
  out.clip.validate(*out.system);
  return out;
}

void run_render(RunContext& c, const Step& step, const RenderStep& s) {
  const nlohmann::json results = c.cached(step, [&] {
    std::optional<Progress> progress;
    const ClipProgress report = [&](ClipStage stage, long done, long total) {
      if (stage != ClipStage::draw) return;
      if (!progress) progress.emplace("render " + s.out, total, "frames");
      progress->update(done);
    };
    const Clip clip = render_clip(s, c.options.quality, c.options.out_dir, c.options.assets);
    ClipResult made;
    if (s.mechanism.empty()) {
      made = produce_clip(clip, report);
    } else {
      MechanismRender m = mechanism_render(s, step.where);
      EquationsText equations = std::move(m.clip.settings.equations);
      m.clip.settings = clip.settings;  // the quality's size and frame rate
      if (m.clip.settings.elements.has(Element::equations)) m.clip.settings.equations = std::move(equations);
      draft_equations(m.clip.settings, c.options.quality);
      m.clip.theme = clip.theme;
      m.clip.out = clip.out;
      made = produce_mechanism_clip(*m.system, m.state, m.clip, report);
    }
    nlohmann::json made_results = nlohmann::json::object();
    if (!made.warnings.empty()) made_results["warnings"] = made.warnings;
    return made_results;
  });
  c.warn(step, results);
  const FigureRef::Kind kind = is_still(s.kind) ? FigureRef::Kind::image : FigureRef::Kind::video;
  c.both([&](Writer& w) { w.figure(c.figure(s.out, kind, s.caption)); });
}

}  // namespace linkage::lesson
