#pragma once
// World (metres, y up) to pixels (y down): one uniform scale, so blocks keep their
// true shape, and a centre shown at an anchor, the frame's middle (W/2, H/2) or the
// middle of the part of the frame a legend leaves:
//   px = ax + s (x - cx),   py = ay - s (y - cy)
// follow: the centre is the system's centre of mass at each frame (it free-falls);
//         the scale fits the largest reach of the blocks and arrows about it.
// fixed:  the scale and centre show --view (xmin, ymin, xmax, ymax), widened along
//         one axis to the frame's aspect ratio.
// fit:    as fixed, for the bounds of the whole motion plus a margin.
#include "core/types.hpp"
#include "scene/bounds.hpp"

namespace linkage {

enum class CameraMode { follow, fixed, fit };

/// A world rectangle in metres.
struct View {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};

class Camera {
 public:
  Camera() = default;
  /// Shows `view` (positive area) centred in a width x height frame.
  Camera(const View& view, int width, int height);
  /// Shows `view` centred in `area` (pixels) of a width x height frame: the rest of the
  /// frame is kept for what must not cover the view (a legend).
  Camera(const View& view, const Bounds& area, int width, int height);

  [[nodiscard]] Vec2 to_pixels(const Vec2& world) const {
    return {anchor_.x() + scale_ * (world.x() - centre_.x()), anchor_.y() - scale_ * (world.y() - centre_.y())};
  }
  [[nodiscard]] Vec2 to_world(const Vec2& pixels) const {
    return {centre_.x() + (pixels.x() - anchor_.x()) / scale_, centre_.y() - (pixels.y() - anchor_.y()) / scale_};
  }
  /// Pixels per metre.
  [[nodiscard]] double scale() const { return scale_; }
  /// The world point shown at the anchor.
  [[nodiscard]] const Vec2& centre() const { return centre_; }
  /// The same scale and anchor, centred elsewhere (the follow camera's per-frame move).
  [[nodiscard]] Camera centred_at(const Vec2& centre) const {
    Camera moved = *this;
    moved.centre_ = centre;
    return moved;
  }
  /// The world rectangle the frame shows.
  [[nodiscard]] View visible() const;

 private:
  int width_ = 1, height_ = 1;
  double scale_ = 1;
  Vec2 centre_ = Vec2::Zero();
  Vec2 anchor_{0.5, 0.5};  // pixels
};

/// A view around `centre` of half-size `reach` (the smaller frame side shows 2 reach).
[[nodiscard]] View view_around(const Vec2& centre, double reach);
/// `bounds` grown by `margin` (a fraction of the larger side) on every side.
[[nodiscard]] View view_of(const Bounds& bounds, double margin);

}  // namespace linkage
