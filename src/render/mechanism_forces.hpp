#pragma once
// The loads of a mechanism's frame in pixels: joint and applied force arrows (a cut one
// crossed by a double bar), torque arcs, their labels placed clear of one another, and
// the legend saying what an arrow's length stands for. Split from mechanism_painter so
// the placement can be tested on its own.
#include <cairo.h>

#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/label_layout.hpp"
#include "render/overlays.hpp"
#include "render/paint_layer.hpp"
#include "render/style.hpp"
#include "scene/mechanism_scene.hpp"

namespace linkage {

/// A label in pixels: its box (the text centred in it) and the head it names.
struct PlacedLabel {
  Rect box;
  Vec2 head = Vec2::Zero();
  std::string text;
  bool applied = false;  // an applied load's, else a joint force's or another kind's
  bool leader = false;   // moved off its head far enough to need a line to it
  MechanismDrawList::Arrow::Kind kind = MechanismDrawList::Arrow::Kind::joint;  // its colour
  bool joint = false;  // a joint's name (in the text colour), else a load's
};

struct ForceLayout {
  Rect legend;              // where it covers nothing drawn; empty without force arrows
  Rect scale_bar;           // beside the legend: what its "1 cm" measures against
  std::string scale_label;  // the bar's length, "10 cm"
  double scale_px = 0;
  std::vector<Rect> body_labels;    // the body names' boxes, fixed at the centres
  std::vector<PlacedLabel> labels;  // one per arrow long enough to carry one, and per torque
  std::vector<Segment> arrows;      // each arrow's tail and tip in pixels as drawn (one along another's moved aside)
};

/// Where the legend and the labels go. Each label sits just past its arrow's head, or
/// the nearest place around it clear of the other labels, the body names, the joints,
/// the legend, `occupied` (title, time) and, where possible, every arrow's shaft and
/// the frame's edge. A joint force's label is left out only when its arrow is shorter
/// than the label is high; an applied load's is always there.
[[nodiscard]] ForceLayout layout_forces(cairo_t* cr, const DrawStyle& style, const Camera& camera,
                                        const MechanismDrawList& list, int width, int height,
                                        const std::vector<Rect>& occupied);

/// Where layout_forces puts the legend and its scale bar (empty without them), and
/// whether it found both a place covering nothing drawn.
struct LegendFit {
  Rect legend, scale_bar;
  bool clear = true;
};
[[nodiscard]] LegendFit fit_legend(cairo_t* cr, const DrawStyle& style, const Camera& camera,
                                   const MechanismDrawList& list, int width, int height,
                                   const std::vector<Rect>& occupied);

/// The shortest arrow that carries its label (pixels): the scene draws a shorter joint
/// force stretched (dashed) to stretched_arrow_px, its label giving the value.
[[nodiscard]] double shortest_labelled_arrow_px(const DrawStyle& style);

/// The colour of an arrow of `kind`.
[[nodiscard]] const Rgba& arrow_colour(const Theme& theme, MechanismDrawList::Arrow::Kind kind);

/// A driver's motor symbol's radius, px.
[[nodiscard]] double motor_radius_px(const DrawStyle& style);
/// Each driver's motor symbol at its joint (under the joint's pin, which sits in its middle).
void paint_motors(cairo_t* cr, const DrawStyle& style, const Camera& camera, const MechanismDrawList& list);

/// The arrows and torque arcs, then the laid-out labels and the legend.
void paint_forces(cairo_t* cr, const DrawStyle& style, const Camera& camera, const MechanismDrawList& list,
                  const ForceLayout& layout);
/// The same, each arrow, torque and label onto its layer's context, the legend onto the legend's.
void paint_forces(const LayerContexts& at, const DrawStyle& style, const Camera& camera, const MechanismDrawList& list,
                  const ForceLayout& layout);

}  // namespace linkage
