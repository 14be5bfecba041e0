#pragma once
// Draws one frame of any mechanism (scene/mechanism_scene.hpp) with Cairo: background
// grid, title and time, then trails, rails, springs and dashpots, bodies, joints, ground
// symbols, and the loads with their labels and legend (render/mechanism_forces.hpp). Colours come from the theme
// (bodies alternate the two block colours); sizes from the DrawStyle, so lines and text read the same at any zoom.
#include <cairo.h>

#include <string>
#include <vector>

#include "render/camera.hpp"
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

/// Paints the whole frame (it is fully covered) for the mechanism at time `t`.
void paint_mechanism_frame(cairo_t* cr, const DrawStyle& style, const Camera& camera, const MechanismDrawList& list,
                           const MechanismLabels& labels, double t, int width, int height,
                           const Camera* earlier = nullptr);

}  // namespace linkage
