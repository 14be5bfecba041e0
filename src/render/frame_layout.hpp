#pragma once
// The frame around the motion: the live plot beside or below it (--panel), the case's
// equations in a band under both (--show equations) and a caption band at the bottom
// (--caption, a lesson's timed captions). The motion is drawn by its own renderer into
// the scene's part of the frame, so the homework's clips and any mechanism's are framed
// alike; with none of them, the motion has the whole frame.
#include <cairo.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "render/equations_overlay.hpp"
#include "render/paint_layer.hpp"
#include "render/panel.hpp"
#include "render/settings.hpp"
#include "render/style.hpp"
#include "render/theme.hpp"

namespace linkage {

/// The bands across the bottom of a frame: the caption's height and the equations' fit
/// (zero when not shown). Error::invalid("show", ...) when the equations shown cannot be
/// drawn at a legible size, naming the smallest --quality preset where they can.
struct FrameBands {
  double caption = 0;
  EquationsFit equations;
};
[[nodiscard]] FrameBands frame_bands(const RenderSettings& settings);

class FrameLayout {
 public:
  /// `settings` is the whole frame's; `panel` may be empty. Keeps a copy of both.
  FrameLayout(const RenderSettings& settings, const Theme& theme, PanelData panel);
  FrameLayout(const FrameLayout&) = delete;
  FrameLayout& operator=(const FrameLayout&) = delete;

  /// The settings to draw the motion with: the frame's, sized to the scene's part.
  [[nodiscard]] const RenderSettings& scene_settings() const { return scene_settings_; }
  [[nodiscard]] const Rect& scene_rect() const { return scene_; }
  [[nodiscard]] const Rect& panel_rect() const { return layout_.panel; }
  [[nodiscard]] const Rect& caption_rect() const { return caption_; }
  [[nodiscard]] const Rect& equations_rect() const { return equations_; }
  /// The panel's data as plotted (angles in the settings' unit).
  [[nodiscard]] const PanelData& panel() const { return panel_; }
  /// Where the panel's plots put their data (the same in every frame: their limits are
  /// the whole data's); empty without a panel.
  [[nodiscard]] std::vector<PanelPart> panel_parts() const;
  [[nodiscard]] const EquationsFit& equations_fit() const { return bands_.equations; }
  /// The equation lines drawn (the report's, their shared indentation removed).
  [[nodiscard]] std::vector<std::string> equation_lines() const;
  /// Nothing around the motion: draw straight into the frame.
  [[nodiscard]] bool plain() const { return layout_.panel.empty() && caption_.empty() && equations_.empty(); }

  /// Frame `index` of the motion at time t: `scene` draws the motion into a buffer of
  /// scene_settings()' size, which is copied into `frame`; then the panel and caption.
  void draw(std::size_t index, double t, Frame& frame, const std::function<void(Frame&)>& scene);
  /// The same onto a vector surface's context, `scene` drawing at the origin.
  void draw_vector(std::size_t index, double t, cairo_t* cr, const std::function<void(cairo_t*)>& scene);
  /// The same with each step of the painting onto its layer's context: `scene` paints the
  /// motion (clipped to its part), the panel, equations and caption go onto PaintLayer::around's.
  void draw_layers(double t, const LayerContexts& at, const std::function<void(const LayerContexts&)>& scene);

 private:
  /// The panel (its sample at t: it may be sampled more finely than the frames), equations, caption.
  void paint_around(double t, cairo_t* cr) const;

  RenderSettings settings_, scene_settings_;
  Theme theme_;
  DrawStyle style_;
  PanelData panel_;
  PanelLayout layout_;
  FrameBands bands_;
  Rect scene_, caption_, equations_;
  Frame scene_frame_;
};

}  // namespace linkage
