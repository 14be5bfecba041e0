#pragma once
// Draws one frame of any mechanism (scene/mechanism_scene.hpp) with Cairo: background
// grid, title and time, then trails, rails, springs and dashpots, bodies, joints, ground
// symbols, and the loads with their labels and legend (render/mechanism_forces.hpp). Colours come from the theme
// (bodies alternate the two block colours); sizes from the DrawStyle, so lines and text read the same at any zoom.
#include <cairo.h>

#include <cstdint>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/mechanism_forces.hpp"
#include "render/paint_layer.hpp"
#include "render/style.hpp"
#include "scene/mechanism_scene.hpp"

namespace linkage {

/// The frame's fixed text: the title (top left) and the run (in the HUD, top right); and
/// what a camera following a floating mechanism adds: the grid's heights named and the
/// inset of the centre of mass's path.
struct MechanismLabels {
  std::string title;
  std::string run;                    // "Case 3 · dop853"
  std::string ensemble{}, compare{};  // legend rows for the other runs, empty without them
  double duration = 0;                // s, the clip's last time (the HUD's widest time)
  bool follows = false;               // the camera follows a floating mechanism's centre of mass
  std::vector<Vec2> com_path{};       // its path over 0 .. duration at even times (empty: no inset)
};

/// What a clip's painter keeps from frame to frame on an image surface: the title's pixels
/// as first drawn and what was under them, to copy the title wherever it lies over the same.
struct MechanismPaintCache {
  struct Region {
    int x = 0, y = 0, width = -1, height = 0;    // width -1: not measured yet
    std::vector<std::uint8_t> under{}, drawn{};  // row after row, 4 bytes a pixel
  };
  Region title;
};

/// Paints the frame's backdrop, all of it that does not move with the mechanism: the
/// background and the grid (`earlier`: the camera a frame before, which the grid streaks from).
void paint_mechanism_backdrop(cairo_t* cr, const DrawStyle& style, const Camera& camera, const ElementSet& shown,
                              const MechanismLabels& labels, int width, int height, const Camera* earlier = nullptr);
void paint_mechanism_backdrop(const LayerContexts& at, const DrawStyle& style, const Camera& camera,
                              const ElementSet& shown, const MechanismLabels& labels, int width, int height,
                              const Camera* earlier = nullptr);

/// Paints the whole frame (it is fully covered) for the mechanism at time `t`; over a
/// backdrop already there (`backdrop_painted`: a fixed camera's, copied from a cache) only
/// what comes after it, so the pixels are the same either way. Returns where it put the
/// legend and the labels.
ForceLayout paint_mechanism_frame(cairo_t* cr, const DrawStyle& style, const Camera& camera,
                                  const MechanismDrawList& list, const MechanismLabels& labels, double t, int width,
                                  int height, const Camera* earlier = nullptr, bool backdrop_painted = false,
                                  MechanismPaintCache* cache = nullptr);
/// The same, each step onto its layer's context (render/paint_layer.hpp): composited in
/// the layers' order they are the frame paint_mechanism_frame draws onto one.
ForceLayout paint_mechanism_frame(const LayerContexts& at, const DrawStyle& style, const Camera& camera,
                                  const MechanismDrawList& list, const MechanismLabels& labels, double t, int width,
                                  int height, const Camera* earlier = nullptr, bool backdrop_painted = false,
                                  MechanismPaintCache* cache = nullptr);

/// The boxes of the HUD, the centre of mass's inset and the title as paint_mechanism_frame
/// places them (those it draws): what the legend and labels keep off. Nothing is painted.
[[nodiscard]] std::vector<Rect> mechanism_frame_panels(cairo_t* cr, const DrawStyle& style,
                                                       const MechanismDrawList& list, const MechanismLabels& labels,
                                                       int width);

}  // namespace linkage
