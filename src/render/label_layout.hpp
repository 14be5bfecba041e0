#pragma once
// Where a name goes beside what it names, in pixels: the first place around a point
// that is clear of other names, marks, arrows and bodies. Shared by the homework's frame
// and any mechanism's. Takes views, so a frame can lay out its names without allocating.
#include <span>

#include "core/types.hpp"
#include "render/overlays.hpp"
#include "render/style.hpp"

namespace linkage {

/// A line a name keeps off: an arrow's shaft, or an edge of body `body`'s outline (a
/// closed polygon given edge by edge; a name inside it touches it too).
struct Segment {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
  int body = -1;  // >= 0: an outline edge
};

struct LabelObstacles {
  std::span<const Rect> boxes;        // never overlapped
  std::span<const Segment> segments;  // avoided unless there is no other place
  // When set, the name must be plainly nearer `own` (what it names) than any of the
  // `rivals` (arrows it could be taken for), unless there is no other place.
  const Segment* own = nullptr;
  std::span<const Segment> rivals{};
  // Springs' coils: avoided as the segments are, and still when those cannot be.
  std::span<const Segment> coils{};
};

/// The shortest distance between a box and the segment a-b (0 when they meet).
[[nodiscard]] double distance_to(const Rect& r, const Vec2& a, const Vec2& b);

/// Whether two boxes share any area.
[[nodiscard]] bool overlaps(const Rect& a, const Rect& b);
/// The area of a and b's intersection (zero when apart).
[[nodiscard]] double overlap_area(const Rect& a, const Rect& b);
/// Whether the segment a-b passes through r.
[[nodiscard]] bool crosses(const Rect& r, const Vec2& a, const Vec2& b);
/// Whether r crosses any segment or lies inside a body's outline.
[[nodiscard]] bool touches(const Rect& r, std::span<const Segment> segments);

struct Placement {
  Rect box;
  bool leader = false;  // moved off its head far enough to need a line to it
  bool clear = false;   // clear of every box and segment, inside the frame
};

/// The first place for a box of `size` (only its width and height count) around `head`:
/// along `direction` first, then turning away from it, then further out; clear of every
/// box, segment and coil and inside the frame if possible, else clear of the boxes and
/// coils inside the frame, else clear of the boxes inside the frame, else clear of the
/// boxes; the plain place past the head if none.
[[nodiscard]] Placement place_label(const Rect& size, const Vec2& head, const Vec2& direction,
                                    const LabelObstacles& obstacles, const DrawStyle& style, int width, int height);

}  // namespace linkage
