#include "render/paint_layer.hpp"

namespace linkage {

using Kind = MechanismDrawList::Arrow::Kind;

PaintLayer arrow_layer(Kind kind) {
  switch (kind) {
    case Kind::joint:
      return PaintLayer::arrow_joint;
    case Kind::applied:
      return PaintLayer::arrow_applied;
    case Kind::gravity:
      return PaintLayer::arrow_gravity;
    case Kind::spring:
      return PaintLayer::arrow_spring;
    case Kind::velocity:
      return PaintLayer::arrow_velocity;
    case Kind::acceleration:
      return PaintLayer::arrow_acceleration;
    case Kind::driver:
      return PaintLayer::arrow_driver;
  }
  return PaintLayer::arrow_joint;
}

PaintLayer label_layer(Kind kind) {
  switch (kind) {
    case Kind::joint:
      return PaintLayer::label_joint;
    case Kind::applied:
      return PaintLayer::label_applied;
    case Kind::gravity:
      return PaintLayer::label_gravity;
    case Kind::spring:
      return PaintLayer::label_spring;
    case Kind::velocity:
      return PaintLayer::label_velocity;
    case Kind::acceleration:
      return PaintLayer::label_acceleration;
    case Kind::driver:
      return PaintLayer::label_driver;
  }
  return PaintLayer::label_joint;
}

Element arrow_element(Kind kind) {
  switch (kind) {
    case Kind::joint:
      return Element::pin_force;
    case Kind::applied:
      return Element::loads;
    case Kind::gravity:
      return Element::gravity;
    case Kind::spring:
      return Element::spring_force;
    case Kind::velocity:
      return Element::velocity;
    case Kind::acceleration:
      return Element::acceleration;
    case Kind::driver:
      return Element::motor;
  }
  return Element::pin_force;
}

LayerElements layer_elements(PaintLayer layer) {
  switch (layer) {
    case PaintLayer::backdrop:
    case PaintLayer::scene:
    case PaintLayer::markers:
    case PaintLayer::around:
      return {};
    case PaintLayer::grid:
      return {Element::grid, {}};
    case PaintLayer::trail:
    case PaintLayer::trail_head:
      return {Element::trail, {}};
    case PaintLayer::motor:
    case PaintLayer::torque_driver:
      return {Element::motor, {}};
    case PaintLayer::hud:
      return {Element::hud, {}};
    case PaintLayer::title:
      return {Element::title, {}};
    case PaintLayer::axes:
      return {Element::axes, {}};
    case PaintLayer::body_labels:
    case PaintLayer::joint_names:
      return {Element::labels, {}};
    case PaintLayer::torque_applied:
      return {Element::loads, {}};
    case PaintLayer::arrow_joint:
      return {arrow_element(Kind::joint), {}};
    case PaintLayer::arrow_applied:
      return {arrow_element(Kind::applied), {}};
    case PaintLayer::arrow_gravity:
      return {arrow_element(Kind::gravity), {}};
    case PaintLayer::arrow_spring:
      return {arrow_element(Kind::spring), {}};
    case PaintLayer::arrow_velocity:
      return {arrow_element(Kind::velocity), {}};
    case PaintLayer::arrow_acceleration:
      return {arrow_element(Kind::acceleration), {}};
    case PaintLayer::arrow_driver:
      return {arrow_element(Kind::driver), {}};
    case PaintLayer::label_joint:
      return {arrow_element(Kind::joint), Element::labels};
    case PaintLayer::label_applied:
      return {arrow_element(Kind::applied), Element::labels};
    case PaintLayer::label_gravity:
      return {arrow_element(Kind::gravity), Element::labels};
    case PaintLayer::label_spring:
      return {arrow_element(Kind::spring), Element::labels};
    case PaintLayer::label_velocity:
      return {arrow_element(Kind::velocity), Element::labels};
    case PaintLayer::label_acceleration:
      return {arrow_element(Kind::acceleration), Element::labels};
    case PaintLayer::label_driver:
      return {arrow_element(Kind::driver), Element::labels};
    case PaintLayer::legend:
      return {Element::legend, {}};
  }
  return {};
}

std::string_view name(PaintLayer layer) {
  switch (layer) {
    case PaintLayer::backdrop:
      return "backdrop";
    case PaintLayer::grid:
      return "grid";
    case PaintLayer::trail:
      return "trail";
    case PaintLayer::scene:
      return "scene";
    case PaintLayer::trail_head:
      return "trail-head";
    case PaintLayer::motor:
      return "motor";
    case PaintLayer::markers:
      return "markers";
    case PaintLayer::hud:
      return "hud";
    case PaintLayer::title:
      return "title";
    case PaintLayer::axes:
      return "axes";
    case PaintLayer::body_labels:
      return "body-labels";
    case PaintLayer::torque_applied:
      return "torque-applied";
    case PaintLayer::torque_driver:
      return "torque-driver";
    case PaintLayer::arrow_joint:
      return "arrow-joint";
    case PaintLayer::arrow_applied:
      return "arrow-applied";
    case PaintLayer::arrow_gravity:
      return "arrow-gravity";
    case PaintLayer::arrow_spring:
      return "arrow-spring";
    case PaintLayer::arrow_velocity:
      return "arrow-velocity";
    case PaintLayer::arrow_acceleration:
      return "arrow-acceleration";
    case PaintLayer::arrow_driver:
      return "arrow-driver";
    case PaintLayer::joint_names:
      return "joint-names";
    case PaintLayer::label_joint:
      return "label-joint";
    case PaintLayer::label_applied:
      return "label-applied";
    case PaintLayer::label_gravity:
      return "label-gravity";
    case PaintLayer::label_spring:
      return "label-spring";
    case PaintLayer::label_velocity:
      return "label-velocity";
    case PaintLayer::label_acceleration:
      return "label-acceleration";
    case PaintLayer::label_driver:
      return "label-driver";
    case PaintLayer::legend:
      return "legend";
    case PaintLayer::around:
      return "around";
  }
  return "";
}

}  // namespace linkage
