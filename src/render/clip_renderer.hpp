#pragma once
// Draws the frames of a clip (or one still) from its sampled motion. Everything that
// is the same in every frame (background, grid, axes, title, legend, scale bar) is
// drawn once into cached surfaces and copied into each frame; per frame only the scene
// and the HUD are drawn. Raster frames go into core::Frame buffers (ARGB32); vector
// stills draw everything straight onto a Cairo context (SVG, PDF).
#include <cairo.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "model/params.hpp"
#include "render/cairo_util.hpp"
#include "render/camera.hpp"
#include "render/overlays.hpp"
#include "render/render_stats.hpp"
#include "render/scene_painter.hpp"
#include "render/settings.hpp"
#include "render/style.hpp"
#include "render/theme.hpp"
#include "scene/draw_list.hpp"
#include "scene/motion.hpp"
#include "scene/scene_builder.hpp"

namespace linkage {

/// Another run drawn as outlines over the main one: its block states at the motion's
/// samples, its parameters, and its place (an ensemble member at `ramp`, or the compared run).
struct OverlayRun {
  Params params;
  std::vector<BodyState> states;
  double ramp = 0;
  bool compare = false;
};
/// The other runs and the legend's words for them ("20 runs", "θ₁ + 0 .. 1e-06 rad";
/// "integrator=rk4").
struct ClipOverlays {
  std::vector<OverlayRun> runs;
  std::string ensemble_name, ensemble_note, compare_note;
};

class ClipRenderer {
 public:
  /// `run` is the HUD's second line (e.g. "Case 3 · dop853"). The motion must outlive the
  /// renderer. Chooses arrow scales from the whole motion and the camera for it.
  ClipRenderer(const Params& params, const Motion& motion, const RenderSettings& settings, Theme theme, std::string run,
               ClipOverlays overlays = {});
  ClipRenderer(const ClipRenderer&) = delete;
  ClipRenderer& operator=(const ClipRenderer&) = delete;
  ~ClipRenderer();

  /// Draws sample `index` of the motion into `frame` (settings' width x height).
  void draw(std::size_t index, Frame& frame);
  /// Draws sample `index` onto a vector surface's context, without any cached bitmap.
  void draw_vector(std::size_t index, cairo_t* cr);

  /// The camera of sample `index` (follow moves it with G).
  [[nodiscard]] Camera camera_at(std::size_t index) const;
  /// The camera at the start of sample `index`'s shutter interval (speed / fps of
  /// simulated time before it, not before 0): the follow view's grid streaks from there.
  [[nodiscard]] Camera shutter_camera_at(std::size_t index) const;
  [[nodiscard]] const SceneOptions& scene_options() const { return scene_options_; }
  [[nodiscard]] const std::vector<LegendRow>& legend() const { return legend_; }
  /// The names of the frame drawn last, where they went.
  [[nodiscard]] const SceneLabels& labels() const { return labels_; }
  [[nodiscard]] const RenderStats& stats() const { return stats_; }
  /// The lab-frame inset of a following camera (empty rect otherwise).
  [[nodiscard]] const PathInset& path_inset() const { return path_inset_; }
  /// The inset of the bodies at a readable size, when a fit camera shows them tiny.
  [[nodiscard]] const Inset& bodies_inset() const { return bodies_inset_; }
  [[nodiscard]] const GridSpec& grid() const { return grid_; }
  /// Where the legend is (empty rect when hidden).
  [[nodiscard]] const Rect& legend_rect() const { return legend_rect_; }

 private:
  struct Target {  // a Cairo surface and context per frame buffer, made on first use
    const std::uint8_t* pixels = nullptr;
    cairo::SurfacePtr surface;
    cairo::ContextPtr context;
  };
  struct Panel {  // a cached static overlay
    cairo::SurfacePtr surface;
    Rect rect;
  };
  // What depends on the base camera: grid, panels, insets, and `first` the shortest arrow.
  void lay_out(bool first);
  Target& target_for(Frame& frame);
  void prepare_static_layers();
  void paint_static_background(cairo_t* cr) const;
  void paint_dynamic(std::size_t index, cairo_t* cr);
  void paint_static_overlays(cairo_t* cr) const;
  void paint_hud_of(std::size_t index, cairo_t* cr);
  void paint_grid_of(std::size_t index, cairo_t* cr) const;
  void paint_insets_of(std::size_t index, cairo_t* cr);
  void count_frame(std::chrono::steady_clock::time_point start);
  Panel cache_panel(const Rect& rect, void (ClipRenderer::*paint)(cairo_t*) const);
  void paint_title_panel(cairo_t* cr) const;
  void paint_legend_panel(cairo_t* cr) const;
  void paint_scale_bar_panel(cairo_t* cr) const;

  Params params_;
  const Motion& motion_;
  ClipOverlays overlays_;
  RenderSettings settings_;
  Theme theme_;
  DrawStyle style_;
  SceneOptions scene_options_;
  Camera base_camera_;
  Vec2 fbd_offset_ = Vec2::Zero();  // the free-body view: G this far from the frame's centre (world)
  GridSpec grid_;
  std::vector<LegendRow> legend_;
  std::string scale_label_;
  double scale_length_px_ = 0;
  HudText hud_;
  TitleLayout title_layout_;
  Rect legend_rect_, scale_rect_, hud_rect_;
  std::vector<Rect> panel_rects_;  // where grid labels must not go
  bool moving_grid_ = false;       // drawn per frame: world lines past a following camera
  PathInset path_inset_;
  Inset bodies_inset_;
  Camera bodies_camera_;  // the bodies' inset: its scale, centred on G each frame

  DrawList list_;
  SceneLabels labels_;
  std::vector<Target> targets_;
  cairo::SurfacePtr background_;
  std::vector<Panel> panels_;
  bool static_ready_ = false;
  RenderStats stats_;
};

}  // namespace linkage
