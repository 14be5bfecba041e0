#include "scene/scene_builder.hpp"

#include <algorithm>
#include <cmath>

#include "model/kinematics.hpp"

namespace linkage {
namespace {

Vec2 direction(double theta) { return {std::cos(theta), std::sin(theta)}; }

const ArrowScale& scale_of(const SceneOptions& options, ArrowKind kind) {
  return options.arrow_scales[static_cast<std::size_t>(kind)];
}

void add_arrow(DrawList& out, const SceneOptions& options, ArrowKind kind, const Vec2& tail, const Vec2& value,
               std::string_view tag) {
  const ArrowScale& scale = scale_of(options, kind);
  if (!scale.drawable()) return;
  Arrow arrow{kind, tail, value * scale.metres_per_unit, tag, value.norm()};
  const double length = arrow.vector.norm();
  if (length > 0 && length < options.shortest_arrow) {
    arrow.vector *= (options.stretched_length > 0 ? options.stretched_length : options.shortest_arrow) / length;
    arrow.stretched = true;
  }
  // At one scale the forces' values are said too, so their ratio can be read off.
  arrow.valued = arrow.stretched || (options.common_force_scale && kind != ArrowKind::velocity);
  out.arrows.push_back(arrow);
}

void add_trail(const Params& p, const SceneOptions& options, const Motion& motion, std::size_t index, DrawList& out) {
  const MotionSample& now = motion.samples[index];
  const double oldest = now.t - options.trail_seconds;
  std::size_t first = index;
  while (first > 0 && motion.samples[first - 1].t >= oldest) --first;
  for (std::size_t j = first; j <= index; ++j) {
    const BodyState& s = motion.samples[j].state;
    const Vec2 at = pin_position(p, s.x1, s.y1, s.theta1);  // in the world: the path P really took
    const double age = now.t - motion.samples[j].t;
    out.trail.push_back({at, options.trail_seconds > 0 ? 1.0 - age / options.trail_seconds : 1.0});
  }
}

Marker marker(MarkerKind kind, const Vec2& at) {
  Marker m;
  m.kind = kind;
  m.at = at;
  return m;
}

// Beside the pin, across the pin-force arrows (which lie along F) and on the side away
// from G, whose symbol is often next to P.
Vec2 pin_tag_direction(const MotionSample& sample, const Vec2& pin, const Vec2& com) {
  Vec2 across = Vec2(-1, 1).normalized();
  if (sample.pin_force.norm() > 0) across = Vec2(-sample.pin_force.y(), sample.pin_force.x()).normalized();
  const Vec2 away = pin - com;
  if (away.norm() > 0 ? across.dot(away) < 0 : across.y() < 0) across = -across;
  return across;
}

}  // namespace

double default_longest_arrow(const Params& p) {
  // Pin-force arrows start at P, a distance D from each centre of mass: keeping them
  // shorter than D keeps their heads off the centre-of-mass symbols.
  return std::clamp(0.75 * p.pin_offset(), 0.25 * p.L, 0.5 * p.L);
}

SceneOptions scene_options_for(const Params& p, const Motion& motion, ElementSet elements, bool relative_to_com,
                               const ArrowScaleRequest& request, double longest_arrow) {
  SceneOptions options;
  options.elements = elements;
  options.relative_to_com = relative_to_com;
  if (!(longest_arrow > 0)) longest_arrow = default_longest_arrow(p);
  const std::array<double, kArrowKinds> maxima = arrow_maxima(p, motion, relative_to_com);
  const std::array<Element, kArrowKinds> shown_by{Element::pin_force, Element::gravity, Element::velocity};
  constexpr auto pin = static_cast<std::size_t>(ArrowKind::pin_force);
  constexpr auto gravity = static_cast<std::size_t>(ArrowKind::gravity);
  ArrowScale common;
  if (request.common) {
    // Over the forces shown only: a hidden gravity does not shrink the pin force.
    double largest = 0;
    for (const std::size_t kind : {pin, gravity})
      if (elements.has(shown_by[kind])) largest = std::max(largest, maxima[kind]);
    common = request.common_units_per_cm > 0 ? arrow_scale_of(request.common_units_per_cm)
                                             : choose_arrow_scale(largest, longest_arrow);
    options.common_force_scale = true;
  }
  for (std::size_t kind = 0; kind < kArrowKinds; ++kind) {
    if (!elements.has(shown_by[kind])) continue;
    if (const double fixed = request.fixed_for(kArrowKindNames[kind]); fixed > 0)
      options.arrow_scales[kind] = arrow_scale_of(fixed);
    else if (request.common && kind != static_cast<std::size_t>(ArrowKind::velocity))
      options.arrow_scales[kind] = common;
    else
      options.arrow_scales[kind] = choose_arrow_scale(maxima[kind], longest_arrow);
  }
  return options;
}

bool any_stretched(const Params& p, const SceneOptions& options, const Motion& motion) {
  const auto short_at = [&](ArrowKind kind, double magnitude) {
    const double length = magnitude * scale_of(options, kind).metres_per_unit;
    return scale_of(options, kind).drawable() && length > 0 && length < options.shortest_arrow;
  };
  if (short_at(ArrowKind::gravity, p.m * p.g)) return true;
  for (const MotionSample& sample : motion.samples) {
    const BodyState& s = sample.state;
    const Vec2 frame = options.relative_to_com ? system_com_velocity(s) : Vec2::Zero();
    if ((motion.has_pin_force && short_at(ArrowKind::pin_force, sample.pin_force.norm())) ||
        short_at(ArrowKind::velocity, (Vec2(s.x1_dot, s.y1_dot) - frame).norm()) ||
        short_at(ArrowKind::velocity, (Vec2(s.x2_dot, s.y2_dot) - frame).norm()))
      return true;
  }
  return false;
}

void add_ghost(const Params& p, const BodyState& s, double ramp, bool compare, DrawList& out) {
  GhostBlocks ghost;
  ghost.blocks = {BlockShape{1, block_corners(p, s.x1, s.y1, s.theta1), Vec2(s.x1, s.y1)},
                  BlockShape{2, block_corners(p, s.x2, s.y2, s.theta2), Vec2(s.x2, s.y2)}};
  ghost.pin = pin_position(p, s.x1, s.y1, s.theta1);
  ghost.ramp = ramp;
  ghost.compare = compare;
  out.ghosts.push_back(ghost);
}

void build_scene(const Params& p, const SceneOptions& options, const Motion& motion, std::size_t index, DrawList& out) {
  out.clear();
  const ElementSet& shown = options.elements;
  const MotionSample& sample = motion.samples[index];
  const BodyState& s = sample.state;
  const double D = p.pin_offset();
  Vec2 c1(s.x1, s.y1), c2(s.x2, s.y2);
  Vec2 pin1 = c1 + D * direction(s.theta1);  // P as block 1 has it
  Vec2 pin2 = c2 - D * direction(s.theta2);  // P as block 2 has it (differs by Case 1's drift)
  const Vec2 com = system_com(s);
  const bool exploded = options.explode > 0;
  if (exploded) {
    // The free-body view: each block moved half the gap away from the other along the
    // line of their centres, its pin point and loads with it.
    const Vec2 apart = (c2 - c1).norm() > 0 ? Vec2((c2 - c1).normalized()) : Vec2::UnitX();
    c1 -= 0.5 * options.explode * apart;
    pin1 -= 0.5 * options.explode * apart;
    c2 += 0.5 * options.explode * apart;
    pin2 += 0.5 * options.explode * apart;
  }

  if (shown.has(Element::trail) && !exploded) add_trail(p, options, motion, index, out);

  if (shown.has(Element::blocks)) {
    out.blocks.push_back({1, block_corners(p, c1.x(), c1.y(), s.theta1), c1});
    out.blocks.push_back({2, block_corners(p, c2.x(), c2.y(), s.theta2), c2});
  }
  const bool tags = shown.has(Element::labels);
  if (shown.has(Element::com)) {
    out.markers.push_back(marker(MarkerKind::com, c1));
    out.markers.push_back(marker(MarkerKind::com, c2));
    if (!exploded) out.markers.push_back(marker(MarkerKind::com_system, com));
  }
  if (shown.has(Element::pin)) {
    // Apart, each block has its own half of the pin; so has each block once Case 1 has
    // drifted visibly (beyond a hundredth of the width), to show the gap.
    const bool drifted = !exploded && (pin2 - pin1).norm() > 0.01 * p.w;
    for (const Vec2& at : {pin1, pin2}) {
      Marker pin = marker(MarkerKind::pin, at);
      if (tags) {
        pin.tag = drifted ? (at == pin1 ? "P of 1" : "P of 2") : "P";
        pin.tag_direction = pin_tag_direction(sample, at, exploded ? Vec2(at == pin1 ? c1 : c2) : com);
      }
      out.markers.push_back(pin);
      if (!exploded && !drifted) break;
    }
  }

  if (shown.has(Element::gravity)) {
    const Vec2 weight(0.0, -p.m * p.g);
    add_arrow(out, options, ArrowKind::gravity, c1, weight, tags ? "mg" : "");
    add_arrow(out, options, ArrowKind::gravity, c2, weight, tags ? "mg" : "");
  }
  if (shown.has(Element::velocity)) {
    const Vec2 frame_velocity = options.relative_to_com ? system_com_velocity(s) : Vec2::Zero();
    add_arrow(out, options, ArrowKind::velocity, c1, Vec2(s.x1_dot, s.y1_dot) - frame_velocity, tags ? "v1" : "");
    add_arrow(out, options, ArrowKind::velocity, c2, Vec2(s.x2_dot, s.y2_dot) - frame_velocity, tags ? "v2" : "");
  }
  if (shown.has(Element::pin_force) && motion.has_pin_force) {
    // Named by the body each acts on, in the homework's convention: F is the force on block 1.
    add_arrow(out, options, ArrowKind::pin_force, pin1, sample.pin_force, tags ? "F on 1" : "");
    add_arrow(out, options, ArrowKind::pin_force, pin2, -sample.pin_force, tags ? "\u2212F on 2" : "");
    if (exploded && tags) {
      // Past the heads both names would sit in the gap between the bodies: beside each
      // shaft instead, on opposite sides (block 1's across from its P) and leaning away
      // from the other body, so each is plainly at its own arrow.
      const Vec2 apart = (c2 - c1).normalized();
      const Vec2 side = -pin_tag_direction(sample, pin1, c1);
      for (Arrow& arrow : out.arrows)
        if (arrow.kind == ArrowKind::pin_force)
          arrow.tag_side =
              arrow.tail == pin1 ? Vec2((side - 0.2 * apart).normalized()) : Vec2((-side + 0.2 * apart).normalized());
    }
  }

  if (shown.has(Element::labels) && shown.has(Element::blocks)) {
    // Each number sits halfway between the centre of mass and the block's free end.
    out.labels.push_back({c1 - 0.25 * p.L * direction(s.theta1), "1", 1});
    out.labels.push_back({c2 + 0.25 * p.L * direction(s.theta2), "2", 2});
  }
}

}  // namespace linkage
