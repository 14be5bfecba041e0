#include "render/frame_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "render/cairo_util.hpp"

namespace linkage {
namespace {

int even(double pixels) { return std::max(2, 2 * static_cast<int>(std::floor(pixels / 2))); }

// Whether the equations fit `settings`' frame (a larger preset, for the error's advice).
bool frame_bands_fit(const RenderSettings& settings) {
  try {
    (void)frame_bands(settings);
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace

FrameBands frame_bands(const RenderSettings& settings) {
  FrameBands bands;
  DrawStyle style;
  style.u = DrawStyle::unit_for(settings.width, settings.height);
  const bool equations = settings.elements.has(Element::equations) && !settings.equations.empty();
  if (settings.captions.empty() && !equations) return bands;
  const cairo::SurfacePtr scratch = cairo::image_surface(1, 1);
  const cairo::ContextPtr cr = cairo::context(scratch.get());
  if (!settings.captions.empty()) {
    bands.caption = caption_band_height(cr.get(), style, settings.captions, settings.width);
    bands.caption = std::min(bands.caption, std::floor(0.4 * settings.height));
  }
  if (!equations) return bands;
  bands.equations = fit_equations(cr.get(), style, settings.equations, settings.width,
                                  kEquationShare * (settings.height - bands.caption));
  if (bands.equations.fits()) return bands;
  const std::string& heading = settings.equations.heading;
  std::string detail = heading.substr(0, heading.find(':'));
  detail += (detail.empty() ? "the equations (" : "'s equations (") + std::to_string(settings.equations.lines.size()) +
            " lines) do not fit a " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
            " frame at a legible size (" + std::to_string(static_cast<int>(kMinEquationFont)) + " px or more); ";
  for (const Quality& q : kQualities) {
    RenderSettings larger = settings;
    larger.width = q.width;
    larger.height = q.height;
    if (q.width > settings.width && q.height > settings.height && frame_bands_fit(larger)) {
      detail += "use quality " + std::string(q.name) + " (" + std::to_string(q.width) + "x" + std::to_string(q.height) +
                ") or a larger size";
      throw Error::invalid("show", detail);
    }
  }
  throw Error::invalid("show", detail + "show fewer lines (another case) or a larger size");
}

FrameLayout::FrameLayout(const RenderSettings& settings, const Theme& theme, PanelData panel)
    : settings_(settings), scene_settings_(settings), theme_(theme), panel_(std::move(panel)) {
  style_.theme = &theme_;
  style_.u = DrawStyle::unit_for(settings_.width, settings_.height);
  convert_angles(panel_, settings_.angles);
  bands_ = frame_bands(settings_);
  double band = bands_.caption;
  const double equations = bands_.equations.height;
  const int above = band > 0 || equations > 0 ? even(settings_.height - band - equations) : settings_.height;
  // Every pixel belongs to one part: rounding goes to the equations' band if any, else the caption's.
  if (equations > 0) {
    const double below = settings_.height - band;
    equations_ = {0, static_cast<double>(above), static_cast<double>(settings_.width), below - above};
  } else {
    band = settings_.height - above;
  }
  layout_ = panel_layout(settings_.width, above, !panel_.empty());
  scene_ = {0, 0, static_cast<double>(even(layout_.scene.width)), static_cast<double>(even(layout_.scene.height))};
  // The panel takes what rounding the scene to even sizes left over.
  if (!layout_.panel.empty()) {
    if (layout_.panel.x > 0) {
      layout_.panel.x = scene_.width;
      layout_.panel.width = settings_.width - scene_.width;
    } else {
      layout_.panel.y = scene_.height;
      layout_.panel.height = above - scene_.height;
    }
  }
  if (band > 0)
    caption_ = {0, static_cast<double>(settings_.height) - band, static_cast<double>(settings_.width), band};
  scene_settings_.width = static_cast<int>(scene_.width);
  scene_settings_.height = static_cast<int>(scene_.height);
  if (!plain()) scene_frame_ = Frame(scene_settings_.width, scene_settings_.height);
}

std::vector<std::string> FrameLayout::equation_lines() const {
  return equations_.empty() ? std::vector<std::string>{} : equation_lines_drawn(settings_.equations);
}

std::vector<PanelPart> FrameLayout::panel_parts() const {
  std::vector<PanelPart> parts;
  if (layout_.panel.empty()) return parts;
  // Laid out as a frame lays it out, onto a surface that keeps nothing.
  const cairo::SurfacePtr scratch(cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, nullptr));
  const cairo::ContextPtr cr = cairo::context(scratch.get());
  (void)paint_panel(cr.get(), style_, panel_, 0, layout_.panel, &parts);
  return parts;
}

void FrameLayout::paint_around(double t, cairo_t* cr) const {
  if (!layout_.panel.empty()) (void)paint_panel(cr, style_, panel_, panel_index(panel_, t), layout_.panel);
  if (!equations_.empty()) paint_equations(cr, style_, settings_.equations, bands_.equations, equations_);
  if (!caption_.empty()) paint_caption(cr, style_, caption_at(settings_.captions, t), caption_);
}

void FrameLayout::draw(std::size_t /*index*/, double t, Frame& frame, const std::function<void(Frame&)>& scene) {
  if (plain()) {
    scene(frame);
    return;
  }
  if (frame.width != settings_.width || frame.height != settings_.height)
    throw Error::failure("frame is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                         ", expected " + std::to_string(settings_.width) + "x" + std::to_string(settings_.height));
  scene(scene_frame_);
  const auto row = static_cast<std::size_t>(4 * scene_frame_.width);
  for (int y = 0; y < scene_frame_.height; ++y)
    std::memcpy(frame.pixels.data() + static_cast<std::ptrdiff_t>(y) * frame.stride,
                scene_frame_.pixels.data() + static_cast<std::ptrdiff_t>(y) * scene_frame_.stride, row);
  const cairo::SurfacePtr surface = cairo::surface_for(frame);
  const cairo::ContextPtr cr = cairo::context(surface.get());
  paint_around(t, cr.get());
  cairo::check(cr.get(), "cannot draw the panel or caption");
  cairo_surface_flush(surface.get());
}

void FrameLayout::draw_vector(std::size_t /*index*/, double t, cairo_t* cr,
                              const std::function<void(cairo_t*)>& scene) {
  cairo_save(cr);
  cairo_rectangle(cr, scene_.x, scene_.y, scene_.width, scene_.height);
  cairo_clip(cr);
  scene(cr);
  cairo_restore(cr);
  paint_around(t, cr);
}

void FrameLayout::draw_layers(double t, const LayerContexts& at,
                              const std::function<void(const LayerContexts&)>& scene) {
  for (std::size_t i = 0; i < kPaintLayers; ++i) {
    cairo_t* cr = at(static_cast<PaintLayer>(i));
    cairo_save(cr);
    cairo_rectangle(cr, scene_.x, scene_.y, scene_.width, scene_.height);
    cairo_clip(cr);
  }
  scene(at);
  for (std::size_t i = 0; i < kPaintLayers; ++i) cairo_restore(at(static_cast<PaintLayer>(i)));
  paint_around(t, at(PaintLayer::around));
}

}  // namespace linkage
