#include "pipeline/clip_page.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/interrupt.hpp"
#include "encode/canvas_ops.hpp"
#include "encode/html_page.hpp"
#include "render/cairo_util.hpp"
#include "render/paint_layer.hpp"
#include "render/plot_text.hpp"

namespace linkage {
namespace {

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

/// One SVG surface per layer, the frame's size; finished into text.
class LayerSurfaces {
 public:
  LayerSurfaces(int width, int height) {
    for (std::size_t i = 0; i < kPaintLayers; ++i) {
      surfaces_[i].reset(cairo_svg_surface_create_for_stream(append, &texts_[i], width, height));
      cairo::check(surfaces_[i].get(), "cannot start a page's SVG layer");
      cairo_svg_surface_restrict_to_version(surfaces_[i].get(), CAIRO_SVG_VERSION_1_1);
      cairo_svg_surface_set_document_unit(surfaces_[i].get(), CAIRO_SVG_UNIT_PX);
      contexts_[i] = cairo::context(surfaces_[i].get());
    }
  }
  [[nodiscard]] cairo_t* at(PaintLayer layer) const { return contexts_[static_cast<std::size_t>(layer)].get(); }
  /// Every layer's SVG text, the surfaces finished.
  std::array<std::string, kPaintLayers>& finish() {
    for (std::size_t i = 0; i < kPaintLayers; ++i) {
      cairo::check(contexts_[i].get(), "drawing a page's layer");
      contexts_[i].reset();
      cairo_surface_finish(surfaces_[i].get());
      cairo::check(surfaces_[i].get(), "writing a page's SVG layer");
    }
    return texts_;
  }

 private:
  std::array<std::string, kPaintLayers> texts_;
  std::array<cairo::SurfacePtr, kPaintLayers> surfaces_;
  std::array<cairo::ContextPtr, kPaintLayers> contexts_;
};

double rounded(double v) { return std::round(v * 100) / 100; }  // hundredths of a pixel

/// A value to six significant digits: what a reader reads under the cursor, in fewer bytes.
double six_digits(double v) {
  if (!std::isfinite(v) || v == 0) return v;
  const double scale = std::pow(10.0, 5 - static_cast<int>(std::floor(std::log10(std::abs(v)))));
  return std::round(v * scale) / scale;
}

/// Plot markup as plain text: subscripts run on ("θ1"), superscript digits raised ("m/s²").
std::string plain_text(const std::string& markup) {
  static constexpr std::array<std::string_view, 10> kRaised{"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out;
  for (const plot::TextRun& run : plot::parse_markup(markup)) {
    if (run.shift != plot::TextRun::Shift::superscript) {
      out += run.text;
      continue;
    }
    for (const char c : run.text) {
      if (c >= '0' && c <= '9')
        out += kRaised[static_cast<std::size_t>(c - '0')];
      else if (c == '-')
        out += "⁻";
      else
        out += c;
    }
  }
  return out;
}

nlohmann::json axis(const plot::AxisMap& map) {
  return {
      {"log", map.scale == plot::Scale::log}, {"min", map.min}, {"max", map.max}, {"from", map.from}, {"to", map.to}};
}

/// The panel's curves and where each plot put them, for reading values under the cursor.
nlohmann::json panel_json(const MechanismClipFrames& frames) {
  const PanelData& panel = frames.panel();
  nlohmann::json curves = nlohmann::json::array(), plots = nlohmann::json::array(), t = nlohmann::json::array();
  if (panel.empty()) return nullptr;
  for (const double time : panel.t) t.push_back(six_digits(time));
  for (const PanelCurve& curve : panel.curves) {
    nlohmann::json values = nlohmann::json::array();
    for (const double v : curve.values) values.push_back(six_digits(v));  // NaN: null
    curves.push_back({{"label", plain_text(curve.label)}, {"unit", plain_text(curve.unit)}, {"values", values}});
  }
  for (const PanelPart& part : frames.panel_parts())
    plots.push_back({{"area", {part.area.x, part.area.y, part.area.width, part.area.height}},
                     {"time", axis(part.time)},
                     {"value", axis(part.value)},
                     {"curves", part.curves}});
  return {{"t", t}, {"curves", curves}, {"plots", plots}};
}

}  // namespace

std::array<nlohmann::json, kPaintLayers> frame_canvas_ops(MechanismClipFrames& frames, std::size_t k,
                                                          const RenderSettings& settings, CanvasOps& canvas) {
  LayerSurfaces layers(settings.width, settings.height);
  frames.draw_layers(k, [&](PaintLayer layer) { return layers.at(layer); });
  std::array<std::string, kPaintLayers>& texts = layers.finish();
  std::array<nlohmann::json, kPaintLayers> ops;
  for (std::size_t i = 0; i < kPaintLayers; ++i) ops[i] = canvas.layer(texts[i]);
  return ops;
}

void produce_clip_page(const sym::System& system, MechanismClipFrames& frames, const MechanismClip& clip,
                       const std::filesystem::path& out, const ClipProgress& progress, ClipResult& result) {
  const RenderSettings& s = clip.settings;
  const auto start = std::chrono::steady_clock::now();
  CanvasOps canvas;
  std::unordered_map<std::string, int> index;  // each distinct drawing of a layer once
  nlohmann::json drawings = nlohmann::json::array(), frame_layers = nlohmann::json::array(),
                 arrows = nlohmann::json::array(), times = nlohmann::json::array();
  std::array<bool, kPaintLayers> used{};
  const long count = frames.count();
  const Rect scene = frames.scene_rect();
  for (long k = 0; k < count; ++k) {
    throw_if_interrupted();
    const auto frame = static_cast<std::size_t>(k);
    std::array<nlohmann::json, kPaintLayers> layers = frame_canvas_ops(frames, frame, s, canvas);
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t i = 0; i < kPaintLayers; ++i) {
      nlohmann::json& ops = layers[i];
      if (ops.empty()) {
        row.push_back(-1);
        continue;
      }
      used[i] = true;
      const auto [at, added] = index.try_emplace(ops.dump(), static_cast<int>(drawings.size()));
      if (added) drawings.push_back(std::move(ops));
      row.push_back(at->second);
    }
    frame_layers.push_back(std::move(row));
    // Each arrow as drawn, in the frame's pixels, with its value to read under the cursor.
    const MechanismDrawList& list = frames.list();
    const ForceLayout& layout = frames.layout();
    nlohmann::json drawn = nlohmann::json::array();
    for (std::size_t i = 0; i < list.arrows.size() && i < layout.arrows.size(); ++i) {
      const MechanismDrawList::Arrow& arrow = list.arrows[i];
      const Segment& seg = layout.arrows[i];
      drawn.push_back({{"a", {rounded(scene.x + seg.a.x()), rounded(scene.y + seg.a.y())}},
                       {"b", {rounded(scene.x + seg.b.x()), rounded(scene.y + seg.b.y())}},
                       {"layer", static_cast<int>(arrow_layer(arrow.kind))},
                       {"kind", name(arrow_element(arrow.kind))},
                       {"label", arrow.label},
                       {"value", format_quantity(arrow.force, arrow_unit(arrow.kind))}});
    }
    arrows.push_back(std::move(drawn));
    times.push_back(frames.time(frame));
    if (progress) progress(ClipStage::draw, k + 1, count);
  }
  // The layers a viewer shows or hides: each with the elements it needs shown.
  nlohmann::json layer_list = nlohmann::json::array();
  std::vector<std::string> toggles;
  for (std::size_t i = 0; i < kPaintLayers; ++i) {
    const LayerElements elements = layer_elements(static_cast<PaintLayer>(i));
    nlohmann::json needs = nlohmann::json::array();
    for (const std::optional<Element>& e : {elements.first, elements.second})
      if (e) {
        needs.push_back(name(*e));
        if (used[i] && std::find(toggles.begin(), toggles.end(), name(*e)) == toggles.end())
          toggles.emplace_back(name(*e));
      }
    layer_list.push_back({{"name", name(static_cast<PaintLayer>(i))}, {"needs", needs}});
  }
  std::vector<std::string> ordered;  // in the order --show lists the elements
  for (const ElementInfo& info : kElements)
    if (std::find(toggles.begin(), toggles.end(), info.name) != toggles.end()) ordered.emplace_back(info.name);
  const nlohmann::json data = {{"width", s.width},
                               {"height", s.height},
                               {"fps", s.fps},
                               {"speed", s.speed},
                               {"times", times},
                               {"layers", layer_list},
                               {"toggles", ordered},
                               {"drawings", drawings},
                               {"styles", canvas.styles()},
                               {"gradients", canvas.gradients()},
                               {"glyphs", canvas.glyphs()},
                               {"paths", canvas.paths()},
                               {"frames", frame_layers},
                               {"arrows", arrows},
                               {"panel", panel_json(frames)},
                               {"csv", motion_csv(system, frames.motion())},
                               {"csvName", out.stem().string() + ".csv"}};
  PageText text;
  text.title = s.title;
  text.equations = clip.equations_html;
  write_html_page(text, data.dump(), out, "out");
  result.stats.draw_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace linkage
