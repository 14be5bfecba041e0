#pragma once
// What a frame shows, as plain data in world units (metres, y up): no pixels, no
// Cairo. The scene builder fills a DrawList from the motion; a renderer maps it to
// pixels with a camera and a theme. The lists are cleared and refilled every frame, so
// after the first frame they never allocate.
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/types.hpp"

namespace linkage {

enum class ArrowKind : std::uint8_t { pin_force, gravity, velocity };
inline constexpr std::size_t kArrowKinds = 3;

enum class MarkerKind : std::uint8_t {
  pin,         // the pin P
  com,         // a block's centre of mass
  com_system,  // the system's centre of mass G
};

/// A block as the rectangle of its true size, corners counter-clockwise.
struct BlockShape {
  int index = 1;  // 1 or 2
  std::array<Vec2, 4> corners;
  Vec2 centre = Vec2::Zero();
};

/// An arrow drawn from `tail` along `vector`; its length is already scaled to metres
/// by the arrow scale of its kind.
struct Arrow {
  ArrowKind kind = ArrowKind::pin_force;
  Vec2 tail = Vec2::Zero();
  Vec2 vector = Vec2::Zero();
  std::string_view tag;    // a short name drawn at the head when labels are shown, e.g. "F on 1"
  double magnitude = 0;    // N or m/s: the label gives it when `valued`
  bool stretched = false;  // too short to see at its scale: drawn SceneOptions::shortest_arrow long
  bool valued = false;     // the label says the magnitude (stretched, or forces at a common scale)
  // Non-zero (world, unit): the name goes beside the shaft's middle this way, not past
  // the head (the free-body view, where the pin forces' heads meet in the gap).
  Vec2 tag_side = Vec2::Zero();
};

struct Marker {
  MarkerKind kind = MarkerKind::pin;
  Vec2 at = Vec2::Zero();
  std::string_view tag;                           // a name drawn beside it when labels are shown ("P")
  Vec2 tag_direction = Vec2(-1, 1).normalized();  // where the name goes (world, unit)
};

/// A point of the trail of P; `fade` is 1 for the newest point and falls to 0 with age.
struct TrailPoint {
  Vec2 at = Vec2::Zero();
  double fade = 1;
};

/// A text anchored (centred) at a world point, in the colour of `block` (0: text colour).
struct Label {
  Vec2 at = Vec2::Zero();
  std::string_view text;
  int block = 0;
};

/// Another run's blocks and pin, drawn as outlines over this one (render --ensemble,
/// --compare): an ensemble member faint at `ramp` 0..1 of a colour ramp, or the compared run.
struct GhostBlocks {
  std::array<BlockShape, 2> blocks;
  Vec2 pin = Vec2::Zero();
  double ramp = 0;
  bool compare = false;
};

/// Everything of one frame, in drawing order: trail, the ensemble's blocks, blocks, the
/// compared run's blocks, markers and arrows, labels.
struct DrawList {
  std::vector<TrailPoint> trail;  // oldest first
  std::vector<GhostBlocks> ghosts;
  std::vector<BlockShape> blocks;
  std::vector<Marker> markers;
  std::vector<Arrow> arrows;
  std::vector<Label> labels;

  void clear() {
    trail.clear();
    ghosts.clear();
    blocks.clear();
    markers.clear();
    arrows.clear();
    labels.clear();
  }
};

}  // namespace linkage
