#include "render/label_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace linkage {
namespace {

bool inside_frame(const Rect& r, int width, int height) {
  return r.x >= 0 && r.y >= 0 && r.x + r.width <= width && r.y + r.height <= height;
}

// Whether `p` is inside the outline of `body` (even-odd over its edges).
bool inside_body(const Vec2& p, std::span<const Segment> segments, int body) {
  bool in = false;
  for (const Segment& s : segments) {
    if (s.body != body || (s.a.y() > p.y()) == (s.b.y() > p.y())) continue;
    const double x = s.a.x() + (p.y() - s.a.y()) / (s.b.y() - s.a.y()) * (s.b.x() - s.a.x());
    if (x > p.x()) in = !in;
  }
  return in;
}

double distance_to_point(const Rect& r, const Vec2& p) {
  const double dx = std::max({r.x - p.x(), 0.0, p.x() - r.x - r.width});
  const double dy = std::max({r.y - p.y(), 0.0, p.y() - r.y - r.height});
  return std::hypot(dx, dy);
}

Rect grown(const Rect& r, double by) { return {r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by}; }

}  // namespace

bool overlaps(const Rect& a, const Rect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

double overlap_area(const Rect& a, const Rect& b) {
  const double w = std::min(a.x + a.width, b.x + b.width) - std::max(a.x, b.x);
  const double h = std::min(a.y + a.height, b.y + b.height) - std::max(a.y, b.y);
  return w > 0 && h > 0 ? w * h : 0;
}

bool crosses(const Rect& r, const Vec2& a, const Vec2& b) {
  // Liang-Barsky clipping.
  double t0 = 0, t1 = 1;
  const Vec2 d = b - a;
  const std::array<std::pair<double, double>, 4> sides{
      {{-d.x(), a.x() - r.x}, {d.x(), r.x + r.width - a.x()}, {-d.y(), a.y() - r.y}, {d.y(), r.y + r.height - a.y()}}};
  for (const auto& [p, q] : sides) {
    if (p == 0) {
      if (q < 0) return false;
    } else {
      const double t = q / p;
      if (p < 0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
      if (t0 > t1) return false;
    }
  }
  return true;
}

double distance_to(const Rect& r, const Vec2& a, const Vec2& b) {
  if (crosses(r, a, b)) return 0;
  // Otherwise the nearest pair is a corner of the box and a point of the segment, or an
  // end of the segment and the box.
  double nearest = std::min(distance_to_point(r, a), distance_to_point(r, b));
  const Vec2 d = b - a;
  const double length2 = d.squaredNorm();
  for (const Vec2& corner :
       {Vec2(r.x, r.y), Vec2(r.x + r.width, r.y), Vec2(r.x, r.y + r.height), Vec2(r.x + r.width, r.y + r.height)}) {
    const double t = length2 > 0 ? std::clamp((corner - a).dot(d) / length2, 0.0, 1.0) : 0.0;
    nearest = std::min(nearest, (corner - (a + t * d)).norm());
  }
  return nearest;
}

bool touches(const Rect& r, std::span<const Segment> segments) {
  int checked = -1;  // bodies are given edge after edge: test each body's inside once
  const Vec2 centre(r.x + 0.5 * r.width, r.y + 0.5 * r.height);
  for (const Segment& s : segments) {
    if (crosses(r, s.a, s.b)) return true;
    if (s.body >= 0 && s.body != checked) {
      checked = s.body;
      if (inside_body(centre, segments, s.body)) return true;
    }
  }
  return false;
}

Placement place_label(const Rect& size, const Vec2& head, const Vec2& direction, const LabelObstacles& obstacles,
                      const DrawStyle& style, int width, int height) {
  constexpr double degree = std::numbers::pi / 180;
  constexpr double kPlainlyNearer = 4;  // style units: nearer its own arrow than a rival by this
  static constexpr std::array<double, 11> kTurns{0, 30, -30, 60, -60, 90, -90, 120, -120, 150, -150};
  const double gap = 3 * style.u, step = 0.6 * size.height;
  const auto candidate = [&](int ring, double turn) {
    const double c = std::cos(turn * degree), s = std::sin(turn * degree);
    const Vec2 d(c * direction.x() - s * direction.y(), s * direction.x() + c * direction.y());
    // Just far enough along d that the box clears the head by `gap + ring step`.
    const double clear = gap + ring * step;
    const double along_x = std::fabs(d.x()) > 1e-9 ? (0.5 * size.width + clear) / std::fabs(d.x()) : 1e300;
    const double along_y = std::fabs(d.y()) > 1e-9 ? (0.5 * size.height + clear) / std::fabs(d.y()) : 1e300;
    const Vec2 at = head + std::min(along_x, along_y) * d;
    return Rect{at.x() - 0.5 * size.width, at.y() - 0.5 * size.height, size.width, size.height};
  };
  for (int pass = 0; pass < 4; ++pass)
    // A place clear of everything is looked for further out (a crowded middle rod's
    // spring labels find one only past its neighbours), with a line to the head.
    for (int ring = 0; ring < (pass == 0 ? 30 : 10); ++ring)
      for (const double turn : kTurns) {
        const Rect box = candidate(ring, turn);
        if (pass < 3 && !inside_frame(box, width, height)) continue;
        if (std::any_of(obstacles.boxes.begin(), obstacles.boxes.end(),
                        [&](const Rect& r) { return overlaps(box, r); }))
          continue;
        // Lines are kept off by an arrow head's half width, as heads and shafts have width.
        const Rect apart = grown(box, style.arrow_head_half_width());
        if (pass == 0 && touches(apart, obstacles.segments)) continue;
        if (pass < 2 && touches(apart, obstacles.coils)) continue;
        if (pass < 3 && obstacles.own != nullptr) {
          const double mine = distance_to(box, obstacles.own->a, obstacles.own->b);
          if (std::any_of(obstacles.rivals.begin(), obstacles.rivals.end(), [&](const Segment& rival) {
                return distance_to(box, rival.a, rival.b) < mine + kPlainlyNearer * style.u;
              }))
            continue;
        }
        // A line to the head once the box no longer touches it.
        const Vec2 near(std::clamp(head.x(), box.x, box.x + box.width),
                        std::clamp(head.y(), box.y, box.y + box.height));
        return {box, (near - head).norm() > gap + 4 * style.u, pass == 0};
      }
  return {candidate(0, 0), false, false};
}

}  // namespace linkage
