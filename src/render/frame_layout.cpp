#include "render/frame_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "core/error.hpp"
#include "render/cairo_util.hpp"

namespace linkage {
namespace {

int even(double pixels) { return std::max(2, 2 * static_cast<int>(std::floor(pixels / 2))); }

}  // namespace

FrameLayout::FrameLayout(const RenderSettings& settings, const Theme& theme, PanelData panel)
    : settings_(settings), scene_settings_(settings), theme_(theme), panel_(std::move(panel)) {
  style_.theme = &theme_;
  style_.u = DrawStyle::unit_for(settings_.width, settings_.height);
  double band = 0;
  if (!settings_.captions.empty()) {
    const cairo::SurfacePtr scratch = cairo::image_surface(1, 1);
    const cairo::ContextPtr cr = cairo::context(scratch.get());
    band = caption_band_height(cr.get(), style_, settings_.captions, settings_.width);
    band = std::min(band, std::floor(0.4 * settings_.height));
  }
  const int above = band > 0 ? even(settings_.height - band) : settings_.height;
  band = settings_.height - above;  // every pixel belongs to one part
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
  if (band > 0) caption_ = {0, static_cast<double>(above), static_cast<double>(settings_.width), band};
  scene_settings_.width = static_cast<int>(scene_.width);
  scene_settings_.height = static_cast<int>(scene_.height);
  if (!plain()) scene_frame_ = Frame(scene_settings_.width, scene_settings_.height);
}

void FrameLayout::paint_around(std::size_t index, double t, cairo_t* cr) const {
  if (!layout_.panel.empty()) (void)paint_panel(cr, style_, panel_, index, layout_.panel);
  if (!caption_.empty()) paint_caption(cr, style_, caption_at(settings_.captions, t), caption_);
}

void FrameLayout::draw(std::size_t index, double t, Frame& frame, const std::function<void(Frame&)>& scene) {
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
  paint_around(index, t, cr.get());
  cairo::check(cr.get(), "cannot draw the panel or caption");
  cairo_surface_flush(surface.get());
}

void FrameLayout::draw_vector(std::size_t index, double t, cairo_t* cr, const std::function<void(cairo_t*)>& scene) {
  cairo_save(cr);
  cairo_rectangle(cr, scene_.x, scene_.y, scene_.width, scene_.height);
  cairo_clip(cr);
  scene(cr);
  cairo_restore(cr);
  paint_around(index, t, cr);
}

}  // namespace linkage
