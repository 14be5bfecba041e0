#include "render/camera.hpp"

#include <algorithm>

namespace linkage {

Camera::Camera(const View& view, int width, int height)
    : width_(width),
      height_(height),
      scale_(std::min(width / (view.xmax - view.xmin), height / (view.ymax - view.ymin))),
      centre_(0.5 * (view.xmin + view.xmax), 0.5 * (view.ymin + view.ymax)),
      anchor_(0.5 * width, 0.5 * height) {}

Camera::Camera(const View& view, const Bounds& area, int width, int height)
    : width_(width),
      height_(height),
      scale_(std::min((area.max.x() - area.min.x()) / (view.xmax - view.xmin),
                      (area.max.y() - area.min.y()) / (view.ymax - view.ymin))),
      centre_(0.5 * (view.xmin + view.xmax), 0.5 * (view.ymin + view.ymax)),
      anchor_(0.5 * (area.min + area.max)) {}

View Camera::visible() const {
  const Vec2 low = to_world({0.0, static_cast<double>(height_)});
  const Vec2 high = to_world({static_cast<double>(width_), 0.0});
  return {low.x(), low.y(), high.x(), high.y()};
}

View view_around(const Vec2& centre, double reach) {
  return {centre.x() - reach, centre.y() - reach, centre.x() + reach, centre.y() + reach};
}

View view_of(const Bounds& bounds, double margin) {
  const double size = std::max({bounds.max.x() - bounds.min.x(), bounds.max.y() - bounds.min.y(), 1e-9});
  const double grow = margin * size;
  return {bounds.min.x() - grow, bounds.min.y() - grow, bounds.max.x() + grow, bounds.max.y() + grow};
}

}  // namespace linkage
