#include "pipeline/clip_page.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/interrupt.hpp"
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

/// The SVG of a layer with nothing painted: its layer is left out of the frame.
std::string empty_layer(int width, int height) {
  LayerSurfaces blank(width, height);
  return blank.finish()[0];
}

double rounded(double v) { return std::round(v * 100) / 100; }  // hundredths of a pixel

// A number in hundredths, its trailing zeros dropped: "12.5", "-3".
std::string hundredths(double v) {
  std::array<char, 32> text{};
  const int n = std::snprintf(text.data(), text.size(), "%.2f", rounded(v) + 0.0);  // + 0.0: no "-0.00"
  std::size_t length = n > 0 ? static_cast<std::size_t>(n) : 0;
  while (length > 0 && text[length - 1] == '0') --length;
  if (length > 0 && text[length - 1] == '.') --length;
  return {text.data(), length};
}

/// The pieces of every path of every layer of every frame, each kept once. A subpath (a
/// glyph's contour, a pin's circle) is written as its start, absolute, and a book entry:
/// its commands relative, in whole hundredths of a pixel from that exact start, so the
/// same shape elsewhere is the same entry (a label's "0.9" in another place or frame).
class PathBook {
 public:
  /// `svg` (Cairo's: path data of M, L, C and Z with absolute coordinates) with each
  /// subpath's commands replaced by "@N", the book's entry N; the page puts them back.
  std::string compact(const std::string& svg) {
    std::string out;
    out.reserve(svg.size() / 4);
    std::size_t at = 0;
    while (true) {
      const std::size_t d = svg.find(" d=\"", at);
      if (d == std::string::npos) break;
      const std::size_t start = d + 4, stop = svg.find('"', start);
      out.append(svg, at, start - at);
      out += relative(std::string_view(svg).substr(start, stop - start));
      at = stop;
    }
    out.append(svg, at, std::string::npos);
    return out;
  }
  [[nodiscard]] const std::vector<std::string>& entries() const { return entries_; }

 private:
  std::string relative(std::string_view data) {
    std::vector<std::string_view> tokens;
    for (std::size_t i = 0; i < data.size();) {
      const std::size_t next = std::min(data.find(' ', i), data.size());
      if (next > i) tokens.push_back(data.substr(i, next - i));
      i = next + 1;
    }
    const auto number = [&](std::size_t i) {
      return i < tokens.size() ? std::strtod(std::string(tokens[i]).c_str(), nullptr) : 0.0;
    };
    std::string out, body;
    double start[2] = {0, 0};
    long current[2] = {0, 0};  // hundredths from the start
    const auto flush = [&] {
      if (out.empty() && body.empty()) return;
      const auto [entry, added] = index_.try_emplace(body, entries_.size());
      if (added) entries_.push_back(body);
      out.append(" @").append(std::to_string(entry->second));
      body.clear();
    };
    const auto pair = [&](std::size_t i, std::string& to) {
      const long x = std::lround((number(i) - start[0]) * 100), y = std::lround((number(i + 1) - start[1]) * 100);
      to.append(" ").append(hundredths(static_cast<double>(x - current[0]) / 100));
      to.append(" ").append(hundredths(static_cast<double>(y - current[1]) / 100));
      return std::array<long, 2>{x, y};
    };
    bool open = false;
    for (std::size_t i = 0; i < tokens.size();) {
      const std::string_view command = tokens[i];
      if (command == "M") {
        if (open) flush();
        start[0] = number(i + 1);
        start[1] = number(i + 2);
        current[0] = current[1] = 0;
        if (!out.empty()) out += ' ';
        out.append("M ").append(hundredths(start[0])).append(" ").append(hundredths(start[1]));
        open = true;
        i += 3;
      } else if (command == "L") {
        body.append(body.empty() ? "l" : " l");
        const std::array<long, 2> to = pair(i + 1, body);
        current[0] = to[0];
        current[1] = to[1];
        i += 3;
      } else if (command == "C") {
        body.append(body.empty() ? "c" : " c");
        (void)pair(i + 1, body);
        (void)pair(i + 3, body);
        const std::array<long, 2> to = pair(i + 5, body);
        current[0] = to[0];
        current[1] = to[1];
        i += 7;
      } else if (command == "Z") {
        body.append(body.empty() ? "z" : " z");
        current[0] = current[1] = 0;
        i += 1;
      } else {  // not Cairo's: kept as it is
        return std::string(data);
      }
    }
    if (open) flush();
    return out;
  }

  std::unordered_map<std::string, std::size_t> index_;
  std::vector<std::string> entries_;
};

void replace_all(std::string& text, std::string_view from, std::string_view to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

/// What a layer's SVG draws: its content without the document around it, its ids (glyphs,
/// clips) prefixed by the layer's number, so a frame's layers go into one document, which
/// the browser draws at once. Cairo's surface number is left out: a layer the same in two
/// frames is the same text.
std::string layer_body(std::string svg, std::size_t layer) {
  const std::size_t surface = svg.find("<g id=\"surface");
  if (surface != std::string::npos) svg.replace(surface, svg.find('>', surface) - surface, "<g");
  const std::string number = std::to_string(layer);
  for (const std::string_view reference : {"id=\"", "href=\"#", "url(#"}) {
    std::string prefixed(reference);
    prefixed.append("l").append(number).append("-");
    replace_all(svg, reference, prefixed);
  }
  const std::size_t open = svg.find("<svg ");
  const std::size_t begin = open == std::string::npos ? 0 : svg.find('>', open) + 1;
  const std::size_t end = svg.rfind("</svg>");
  return svg.substr(begin, end == std::string::npos || end < begin ? std::string::npos : end - begin);
}

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

void produce_clip_page(const sym::System& system, MechanismClipFrames& frames, const MechanismClip& clip,
                       const std::filesystem::path& out, const ClipProgress& progress, ClipResult& result) {
  const RenderSettings& s = clip.settings;
  const auto start = std::chrono::steady_clock::now();
  PathBook paths;
  const std::string blank = paths.compact(layer_body(empty_layer(s.width, s.height), 0));
  std::unordered_map<std::string, int> index;  // each distinct SVG once
  nlohmann::json svgs = nlohmann::json::array(), frame_layers = nlohmann::json::array(),
                 arrows = nlohmann::json::array(), times = nlohmann::json::array();
  std::array<bool, kPaintLayers> used{};
  const long count = frames.count();
  const Rect scene = frames.scene_rect();
  for (long k = 0; k < count; ++k) {
    throw_if_interrupted();
    const auto frame = static_cast<std::size_t>(k);
    LayerSurfaces layers(s.width, s.height);
    frames.draw_layers(frame, [&](PaintLayer layer) { return layers.at(layer); });
    nlohmann::json row = nlohmann::json::array();
    std::array<std::string, kPaintLayers>& texts = layers.finish();
    for (std::size_t i = 0; i < kPaintLayers; ++i) {
      std::string text = paths.compact(layer_body(std::move(texts[i]), i));
      if (text == blank) {
        row.push_back(-1);
        continue;
      }
      used[i] = true;
      const auto [at, added] = index.try_emplace(std::move(text), static_cast<int>(svgs.size()));
      if (added) svgs.push_back(at->first);
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
                               {"svgs", svgs},
                               {"paths", paths.entries()},
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
