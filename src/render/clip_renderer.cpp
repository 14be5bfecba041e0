#include "render/clip_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <utility>

#include "core/error.hpp"

namespace linkage {
namespace {

constexpr std::size_t kMaxTargets = 8;  // frame buffers remembered (a pipeline uses a few)

bool any_arrows(const SceneOptions& options) {
  return std::any_of(options.arrow_scales.begin(), options.arrow_scales.end(),
                     [](const ArrowScale& s) { return s.drawable(); });
}

// The camera of the first frame: how far the scene reaches decides the scale.
Camera first_camera(const Params& p, const Motion& motion, const RenderSettings& settings,
                    const SceneOptions& options) {
  const double arrows = (any_arrows(options) ? default_longest_arrow(p) : 0.0) + 0.5 * options.explode;
  switch (settings.camera) {
    case CameraMode::fixed:
      return {settings.view, settings.width, settings.height};
    case CameraMode::fit: {
      Bounds bounds = motion_bounds(p, motion);
      bounds.min -= Vec2(arrows, arrows);
      bounds.max += Vec2(arrows, arrows);
      return {view_of(bounds, 0.04), settings.width, settings.height};
    }
    case CameraMode::follow:
      break;
  }
  const double reach = 1.12 * (max_radius_about_com(p, motion) + arrows);
  return {view_around(system_com(motion.samples.front().state), reach), settings.width, settings.height};
}

std::string seconds_text(double seconds) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%g s", seconds);
  return buffer.data();
}

std::vector<LegendRow> legend_rows(const Theme& theme, const SceneOptions& options, bool follow, bool stretched) {
  using Glyph = LegendRow::Glyph;
  std::vector<LegendRow> rows;
  if (options.explode > 0)
    rows.push_back(
        {Glyph::none, theme.text_muted, "free-body view: the blocks drawn apart at P, each with its loads", ""});
  const ElementSet& shown = options.elements;
  const auto scale = [&](ArrowKind kind, std::string_view unit) {
    return describe_arrow_scale(options.arrow_scales[static_cast<std::size_t>(kind)], unit);
  };
  // One scale for both forces: said once more on its own row, so their lengths are read
  // as comparable.
  const std::string common = options.common_force_scale ? " (common)" : "";
  if (shown.has(Element::pin_force))
    rows.push_back({Glyph::arrow, theme.pin_force, "pin force", scale(ArrowKind::pin_force, "N") + common});
  if (shown.has(Element::gravity))
    rows.push_back({Glyph::arrow, theme.gravity, "weight", scale(ArrowKind::gravity, "N") + common});
  if (shown.has(Element::velocity))
    rows.push_back({Glyph::arrow, theme.velocity, follow ? "velocity relative to G" : "velocity",
                    scale(ArrowKind::velocity, "m/s")});
  if (stretched)
    rows.push_back(
        {Glyph::stretched_arrow, theme.text_muted, "too short to see", "drawn longer; its label gives the value"});
  if (shown.has(Element::trail) && options.explode <= 0)
    rows.push_back({Glyph::line, theme.trail, "path of P", "last " + seconds_text(options.trail_seconds)});
  if (shown.has(Element::com)) rows.push_back({Glyph::com, theme.com, "centres of mass", ""});
  // Paths and velocities are then relative to G: say so.
  if (follow) rows.push_back({Glyph::none, theme.text_muted, "the view follows G; the grid stays put", ""});
  return rows;
}

// The other runs' rows, before the closing note about the view.
void add_overlay_rows(const Theme& theme, const ClipOverlays& overlays, std::vector<LegendRow>& rows) {
  const auto at = rows.empty() || rows.back().glyph != LegendRow::Glyph::none ? rows.end() : rows.end() - 1;
  std::vector<LegendRow> added;
  if (!overlays.ensemble_name.empty())
    added.push_back(
        {LegendRow::Glyph::outline, overlay_colour(theme, 0.5, false), overlays.ensemble_name, overlays.ensemble_note});
  if (!overlays.compare_note.empty())
    added.push_back(
        {LegendRow::Glyph::dashed_outline, overlay_colour(theme, 0, true), "compared", overlays.compare_note});
  rows.insert(at, added.begin(), added.end());
}

// G over the whole clip, at `count` + 1 even times from 0: a parabola, as the only
// outside force is gravity (exact, so a still needs no motion beyond its own time).
std::vector<Vec2> com_path(const Params& p, const MotionSample& first, double duration, int count) {
  const Vec2 g0 = system_com(first.state), v0 = system_com_velocity(first.state);
  std::vector<Vec2> path;
  for (int i = 0; i <= count; ++i) {
    const double dt = duration * i / count - first.t;
    path.push_back(g0 + dt * v0 + Vec2(0.0, -0.5 * p.g * dt * dt));
  }
  return path;
}

constexpr int kPathSteps = 120;

struct FreeCircle {
  Vec2 centre = Vec2::Zero();
  double radius = 0;
};

// The largest circle inside the frame (less `margin`) clear of every panel by `margin`,
// searched on a grid of 4 px; among equals the first found, nearest the top-left.
FreeCircle largest_free_circle(std::span<const Rect> panels, int width, int height, double margin) {
  FreeCircle best;
  for (double y = 0; y <= height; y += 4)
    for (double x = 0; x <= width; x += 4) {
      double r = std::min({x, width - x, y, height - y});
      for (const Rect& panel : panels) {
        if (panel.empty()) continue;
        const double dx = std::max({panel.x - x, 0.0, x - panel.x - panel.width});
        const double dy = std::max({panel.y - y, 0.0, y - panel.y - panel.height});
        r = std::min(r, std::hypot(dx, dy));
      }
      if (r - margin > best.radius) best = {Vec2(x, y), r - margin};
    }
  return best;
}
constexpr double kReadableBlock = 40;  // a block shorter than this (units of DrawStyle::u) gets an inset

double clip_duration(const RenderSettings& settings, const Motion& motion) {
  return std::max({settings.duration, settings.at, motion.samples.back().t});
}

}  // namespace

ClipRenderer::ClipRenderer(const Params& params, const Motion& motion, const RenderSettings& settings, Theme theme,
                           std::string run, ClipOverlays overlays)
    : params_(params), motion_(motion), overlays_(std::move(overlays)), settings_(settings), theme_(std::move(theme)) {
  for (const OverlayRun& other : overlays_.runs)
    if (other.states.size() != motion_.samples.size())
      throw Error::failure("an overlaid run has " + std::to_string(other.states.size()) + " states for " +
                           std::to_string(motion_.samples.size()) + " samples");
  if (motion_.samples.empty()) throw Error::failure("nothing to draw: the motion has no samples");
  style_.theme = &theme_;
  style_.u = DrawStyle::unit_for(settings_.width, settings_.height);
  const bool follow = settings_.camera == CameraMode::follow;
  scene_options_ = scene_options_for(params_, motion_, settings_.elements, follow, settings_.arrow_scale);
  // Apart by more than two of the longest arrows, so the halves' pin forces never meet.
  if (settings_.free_body) scene_options_.explode = 2 * default_longest_arrow(params_) + 0.1 * params_.L;
  std::snprintf(hud_.run.data(), hud_.run.size(), "%s", run.c_str());
  base_camera_ = first_camera(params_, motion_, settings_, scene_options_);
  lay_out(true);
  if (settings_.free_body && follow) {
    // The bodies drawn apart reach further than the panels leave room for around the
    // frame's centre: put G at the centre of the largest circle clear of them, scaled
    // so the pair fits in it at any angle.
    const FreeCircle circle = largest_free_circle(panel_rects_, settings_.width, settings_.height, style_.padding());
    // The follow camera's reach less its 12% margin: the circle keeps off the panels already.
    const double reach = 0.5 * std::min(settings_.width, settings_.height) / base_camera_.scale() / 1.12;
    const double scale = circle.radius / reach;
    fbd_offset_ =
        Vec2((0.5 * settings_.width - circle.centre.x()) / scale, (circle.centre.y() - 0.5 * settings_.height) / scale);
    const Vec2 g = system_com(motion_.samples.front().state);
    base_camera_ = Camera(view_around(g, reach * base_camera_.scale() / scale), settings_.width, settings_.height)
                       .centred_at(g + fbd_offset_);
    lay_out(false);
  }
  targets_.reserve(kMaxTargets);
  panels_.reserve(3);
}

void ClipRenderer::lay_out(bool first) {
  // Too short to see: drawn longer, its label giving the value; not when the blocks
  // themselves are too small to carry names (a fit camera over a long fall).
  // The free-body view's second layout keeps the first's minimum: its smaller scale
  // would otherwise call every arrow too short.
  if (first) {
    scene_options_.shortest_arrow = 0;
    if (params_.L * base_camera_.scale() >= 3 * style_.block_label_size()) {
      scene_options_.shortest_arrow = least_visible_arrow_px(style_) / base_camera_.scale();
      scene_options_.stretched_length = stretched_arrow_px(style_) / base_camera_.scale();
    }
  }
  // A following camera sees world-fixed lines stream past, each named by its height,
  // a few to a frame so the numbers can be read.
  const bool follow = settings_.camera == CameraMode::follow;
  const ElementSet& shown = settings_.elements;
  moving_grid_ = follow;
  grid_.spacing = grid_spacing_for(base_camera_, settings_.width, settings_.height, follow ? 5 : 10);
  grid_.name_every = follow;
  grid_.x_ticks = !follow || shown.has(Element::axes);

  if (shown.has(Element::legend)) {
    legend_ = legend_rows(theme_, scene_options_, follow, any_stretched(params_, scene_options_, motion_));
    add_overlay_rows(theme_, overlays_, legend_);
    scale_label_ = describe_length(grid_.spacing.mantissa, grid_.spacing.exponent);
    scale_length_px_ = grid_.spacing.metres() * base_camera_.scale();
  }

  // Layout, measured once on a scratch surface (metrics are unhinted, so they hold for
  // raster and vector output alike).
  const cairo::SurfacePtr scratch = cairo::image_surface(1, 1);
  const cairo::ContextPtr cr = cairo::context(scratch.get());
  if (shown.has(Element::title)) title_layout_ = title_layout(cr.get(), style_, settings_.title, settings_.width);
  if (shown.has(Element::legend)) {
    legend_rect_ = linkage::legend_rect(cr.get(), style_, legend_, settings_.height);
    scale_rect_ = scale_bar_rect(cr.get(), style_, scale_label_, scale_length_px_, settings_.width, settings_.height);
  }
  if (shown.has(Element::hud)) {
    HudText widest = hud_;
    format_hud(widest, -std::max(9.99, motion_.samples.back().t), -8.8e-88, 8.8e-88);
    hud_rect_ = hud_rect(cr.get(), style_, widest, settings_.width);
  }
  const double inset_top =
      hud_rect_.empty() ? style_.padding() : hud_rect_.y + hud_rect_.height + 0.6 * style_.padding();
  const double duration = clip_duration(settings_, motion_);
  if (follow) {
    std::array<char, 96> caption{};
    std::snprintf(caption.data(), caption.size(), "path of the centre of mass, 0\u2013%g s", duration);
    path_inset_ = linkage::path_inset(inset_layout(cr.get(), style_, caption.data(), inset_top, settings_.width),
                                      com_path(params_, motion_.samples.front(), duration, kPathSteps));
  } else if (settings_.camera == CameraMode::fit && shown.has(Element::blocks) &&
             params_.L * base_camera_.scale() < kReadableBlock * style_.u) {
    // The whole fall leaves the blocks a few pixels long: show them beside it at a
    // size that reads, with the magnification said.
    bodies_inset_ = inset_layout(cr.get(), style_, "", inset_top, settings_.width);
    const double arrows = any_arrows(scene_options_) ? default_longest_arrow(params_) : 0.0;
    const double reach = 1.12 * (max_radius_about_com(params_, motion_) + arrows);
    bodies_camera_ = Camera(view_around(Vec2::Zero(), reach), static_cast<int>(bodies_inset_.plot.width),
                            static_cast<int>(bodies_inset_.plot.height));
    std::array<char, 96> caption{};
    std::snprintf(caption.data(), caption.size(), "the bodies, enlarged %.0f\u00d7",
                  bodies_camera_.scale() / base_camera_.scale());
    bodies_inset_ = inset_layout(cr.get(), style_, caption.data(), inset_top, settings_.width);
  }
  panel_rects_ = {title_layout_.rect, legend_rect_, scale_rect_, hud_rect_, path_inset_.inset.rect, bodies_inset_.rect};
}

ClipRenderer::~ClipRenderer() = default;

Camera ClipRenderer::camera_at(std::size_t index) const {
  if (settings_.camera != CameraMode::follow) return base_camera_;
  return base_camera_.centred_at(system_com(motion_.samples[index].state) + fbd_offset_);
}

ClipRenderer::Target& ClipRenderer::target_for(Frame& frame) {
  if (frame.width != settings_.width || frame.height != settings_.height)
    throw Error::failure("frame is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                         ", expected " + std::to_string(settings_.width) + "x" + std::to_string(settings_.height));
  for (Target& target : targets_)
    if (target.pixels == frame.pixels.data()) return target;
  if (targets_.size() == kMaxTargets) targets_.erase(targets_.begin());  // only when callers keep new buffers coming
  Target target;
  target.pixels = frame.pixels.data();
  target.surface = cairo::surface_for(frame);
  target.context = cairo::context(target.surface.get());
  targets_.push_back(std::move(target));
  return targets_.back();
}

void ClipRenderer::paint_static_background(cairo_t* cr) const {
  paint_background(cr, style_, settings_.width, settings_.height);
  if (moving_grid_) return;  // drawn per frame
  if (settings_.elements.has(Element::grid))
    paint_grid(cr, style_, base_camera_, grid_, settings_.width, settings_.height);
  if (settings_.elements.has(Element::axes))
    paint_axes(cr, style_, base_camera_, grid_, settings_.width, settings_.height, panel_rects_);
}

Camera ClipRenderer::shutter_camera_at(std::size_t index) const {
  if (settings_.camera != CameraMode::follow) return base_camera_;
  // G's parabola is exact, so the camera at t - interval needs no earlier sample.
  const MotionSample& sample = motion_.samples[index];
  const double interval = std::clamp(settings_.speed / settings_.fps, 0.0, std::max(sample.t, 0.0));
  const Vec2 g = system_com(sample.state), v = system_com_velocity(sample.state);
  const Vec2 before = g - interval * v + Vec2(0.0, -0.5 * params_.g * interval * interval);
  return base_camera_.centred_at(before + fbd_offset_);
}

void ClipRenderer::paint_grid_of(std::size_t index, cairo_t* cr) const {
  if (!moving_grid_) return;
  const Camera camera = camera_at(index);
  const ElementSet& shown = settings_.elements;
  const Camera earlier = shutter_camera_at(index);
  if (shown.has(Element::grid)) paint_grid(cr, style_, camera, grid_, settings_.width, settings_.height, &earlier);
  if (shown.has(Element::grid) || shown.has(Element::axes))
    paint_axes(cr, style_, camera, grid_, settings_.width, settings_.height, panel_rects_);
}

void ClipRenderer::paint_insets_of(std::size_t index, cairo_t* cr) {
  const MotionSample& sample = motion_.samples[index];
  if (!path_inset_.inset.rect.empty()) {
    const double duration = clip_duration(settings_, motion_);
    const auto travelled = static_cast<std::size_t>(std::floor(sample.t / duration * kPathSteps)) + 1;
    paint_path_inset(cr, style_, path_inset_, system_com(sample.state), travelled);
  }
  if (!bodies_inset_.rect.empty()) {
    const Rect& plot = bodies_inset_.plot;
    paint_inset_frame(cr, style_, bodies_inset_);
    cairo_save(cr);
    cairo_rectangle(cr, plot.x, plot.y, plot.width, plot.height);
    cairo_clip(cr);
    cairo_translate(cr, plot.x, plot.y);
    SceneLabels inset_labels;  // names laid out within the inset, not kept for tests
    paint_scene(cr, style_, list_, bodies_camera_.centred_at(system_com(sample.state)), static_cast<int>(plot.width),
                static_cast<int>(plot.height), {}, inset_labels);
    cairo_restore(cr);
  }
}

void ClipRenderer::paint_title_panel(cairo_t* cr) const { paint_title(cr, style_, settings_.title, title_layout_); }
void ClipRenderer::paint_legend_panel(cairo_t* cr) const { paint_legend(cr, style_, legend_, legend_rect_); }
void ClipRenderer::paint_scale_bar_panel(cairo_t* cr) const {
  paint_scale_bar(cr, style_, scale_label_, scale_length_px_, scale_rect_);
}

void ClipRenderer::paint_static_overlays(cairo_t* cr) const {
  if (!title_layout_.rect.empty()) paint_title_panel(cr);
  if (!legend_rect_.empty()) paint_legend_panel(cr);
  if (!scale_rect_.empty()) paint_scale_bar_panel(cr);
}

ClipRenderer::Panel ClipRenderer::cache_panel(const Rect& rect, void (ClipRenderer::*paint)(cairo_t*) const) {
  Panel panel;
  panel.rect = rect;
  panel.surface = cairo::image_surface(static_cast<int>(rect.width), static_cast<int>(rect.height));
  const cairo::ContextPtr cr = cairo::context(panel.surface.get());
  cairo_translate(cr.get(), -rect.x, -rect.y);
  (this->*paint)(cr.get());
  cairo::check(cr.get(), "cannot draw a legend or title");
  cairo_surface_flush(panel.surface.get());
  ++stats_.static_layer_draws;
  return panel;
}

void ClipRenderer::prepare_static_layers() {
  if (static_ready_) return;
  background_ = cairo::image_surface(settings_.width, settings_.height);
  {
    const cairo::ContextPtr cr = cairo::context(background_.get());
    paint_static_background(cr.get());
    cairo::check(cr.get(), "cannot draw the background");
  }
  cairo_surface_flush(background_.get());
  ++stats_.static_layer_draws;
  if (!title_layout_.rect.empty()) panels_.push_back(cache_panel(title_layout_.rect, &ClipRenderer::paint_title_panel));
  if (!legend_rect_.empty()) panels_.push_back(cache_panel(legend_rect_, &ClipRenderer::paint_legend_panel));
  if (!scale_rect_.empty()) panels_.push_back(cache_panel(scale_rect_, &ClipRenderer::paint_scale_bar_panel));
  static_ready_ = true;
}

void ClipRenderer::paint_dynamic(std::size_t index, cairo_t* cr) {
  build_scene(params_, scene_options_, motion_, index, list_);
  if (settings_.elements.has(Element::blocks))
    for (const OverlayRun& other : overlays_.runs)
      add_ghost(other.params, other.states[index], other.ramp, other.compare, list_);
  stats_.trail_points_drawn += static_cast<std::int64_t>(list_.trail.size());
  const std::array<Rect, 4> occupied{title_layout_.rect, legend_rect_, scale_rect_, hud_rect_};
  paint_scene(cr, style_, list_, camera_at(index), settings_.width, settings_.height, occupied, labels_);
}

void ClipRenderer::draw(std::size_t index, Frame& frame) {
  const auto start = std::chrono::steady_clock::now();
  Target& target = target_for(frame);
  prepare_static_layers();

  // Start from the cached background (same size and stride), then draw on top.
  const int stride = cairo_image_surface_get_stride(background_.get());
  if (stride != frame.stride) throw Error::failure("frame stride differs from the background's");
  std::memcpy(frame.pixels.data(), cairo_image_surface_get_data(background_.get()),
              static_cast<std::size_t>(stride) * static_cast<std::size_t>(frame.height));
  cairo_surface_mark_dirty(target.surface.get());

  cairo_t* cr = target.context.get();
  cairo_save(cr);
  paint_grid_of(index, cr);
  paint_dynamic(index, cr);
  for (const Panel& panel : panels_) {
    cairo_set_source_surface(cr, panel.surface.get(), panel.rect.x, panel.rect.y);
    cairo_paint(cr);
  }
  paint_insets_of(index, cr);
  paint_hud_of(index, cr);
  cairo_restore(cr);
  cairo::check(cr, "cannot draw a frame");
  cairo_surface_flush(target.surface.get());
  count_frame(start);
}

void ClipRenderer::draw_vector(std::size_t index, cairo_t* cr) {
  const auto start = std::chrono::steady_clock::now();
  cairo_save(cr);
  paint_static_background(cr);
  paint_grid_of(index, cr);
  paint_dynamic(index, cr);
  paint_static_overlays(cr);
  paint_insets_of(index, cr);
  paint_hud_of(index, cr);
  cairo_restore(cr);
  cairo::check(cr, "cannot draw the figure");
  count_frame(start);
}

void ClipRenderer::paint_hud_of(std::size_t index, cairo_t* cr) {
  if (!settings_.elements.has(Element::hud)) return;
  const SampleErrors errors = sample_errors(params_, motion_, index);
  format_hud(hud_, motion_.samples[index].t, errors.energy, errors.constraint);
  paint_hud(cr, style_, hud_, hud_rect_);
}

void ClipRenderer::count_frame(std::chrono::steady_clock::time_point start) {
  ++stats_.frames_drawn;
  stats_.draw_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace linkage
