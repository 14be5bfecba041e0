#pragma once
// The steps of a mechanism frame's painting, in the painter's order. One context draws
// them all for a raster or vector frame; a page (`linkage render --out clip.html`) gives
// each its own transparent surface, so a viewer can hide a kind of arrow and what is left
// is still the frame the painter draws. Composited in this order, the layers are the frame.
#include <cairo.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

#include "scene/elements.hpp"
#include "scene/mechanism_scene.hpp"

namespace linkage {

enum class PaintLayer : std::uint8_t {
  backdrop,            // the background
  grid,                // the metric grid
  trail,               // the traced points' fading paths
  scene,               // rails, springs, bodies, ground and guide symbols, another run's bodies
  trail_head,          // the dot at a trail's newest end, over the bodies
  motor,               // the drivers' motor symbols
  markers,             // pins, brackets and centres of mass
  hud,                 // time, run, errors and a followed mechanism's inset
  title,               // the title line
  axes,                // the ticks along the frame's edges, the grid's heights
  body_labels,         // the bodies' names
  torque_applied,      // applied torques' arcs
  torque_driver,       // the drivers' torques' arcs
  arrow_joint,         // the arrows of each kind
  arrow_applied,       //
  arrow_gravity,       //
  arrow_spring,        //
  arrow_velocity,      //
  arrow_acceleration,  //
  arrow_driver,        //
  joint_names,         // each joint's name
  label_joint,         // the labels of each kind of arrow (and torque)
  label_applied,       //
  label_gravity,       //
  label_spring,        //
  label_velocity,      //
  label_acceleration,  //
  label_driver,        //
  legend,              // what the colours and lengths stand for, and the scale bar
  around,              // outside the motion: the panel's plots, the equations, the caption
};
inline constexpr std::size_t kPaintLayers = static_cast<std::size_t>(PaintLayer::around) + 1;

/// The context each layer is painted with.
using LayerContexts = std::function<cairo_t*(PaintLayer)>;

/// The layer an arrow of `kind` is painted in, and its label's.
[[nodiscard]] PaintLayer arrow_layer(MechanismDrawList::Arrow::Kind kind);
[[nodiscard]] PaintLayer label_layer(MechanismDrawList::Arrow::Kind kind);

/// The elements (`--show` names) a layer belongs to: it is seen when every one is shown
/// (an arrow's label needs its kind and labels). Empty: always seen.
struct LayerElements {
  std::optional<Element> first, second;
};
[[nodiscard]] LayerElements layer_elements(PaintLayer layer);
/// The layer's name, for a page's data: "arrow-joint".
[[nodiscard]] std::string_view name(PaintLayer layer);
/// The element an arrow of `kind` is shown with (pin-force for a joint force, ...).
[[nodiscard]] Element arrow_element(MechanismDrawList::Arrow::Kind kind);

}  // namespace linkage
