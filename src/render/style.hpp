#pragma once
// Sizes of lines, marks and text, all proportional to the frame so a clip looks the
// same at 480p and at 4K: one unit `u` is a pixel of an 854x480 frame.
#include <cairo.h>

#include <algorithm>

#include "render/theme.hpp"

namespace linkage {

struct DrawStyle {
  const Theme* theme = nullptr;
  double u = 1;  // pixels per unit

  /// u for a width x height frame: the 16:9 box inside it compared with 854x480.
  [[nodiscard]] static double unit_for(int width, int height) { return std::min(width / 854.0, height / 480.0); }

  // Text sizes (pixels).
  [[nodiscard]] double title_size() const { return 17 * u; }
  [[nodiscard]] double text_size() const { return 12 * u; }
  [[nodiscard]] double small_size() const { return 10.5 * u; }
  [[nodiscard]] double block_label_size() const { return 15 * u; }
  // Line widths and marks (pixels).
  [[nodiscard]] double edge_width() const { return 1.6 * u; }
  [[nodiscard]] double grid_width() const { return std::max(1.0, 0.8 * u); }
  [[nodiscard]] double arrow_width() const { return 2.6 * u; }
  [[nodiscard]] double arrow_head_length() const { return 10 * u; }
  [[nodiscard]] double arrow_head_half_width() const { return 5 * u; }
  [[nodiscard]] double trail_width() const { return 2.2 * u; }
  [[nodiscard]] double pin_radius() const { return 4.2 * u; }
  [[nodiscard]] double com_radius() const { return 4.5 * u; }
  [[nodiscard]] double system_com_radius() const { return 6.5 * u; }
  [[nodiscard]] double padding() const { return 12 * u; }
};

/// Sets the source colour.
inline void set_colour(cairo_t* cr, const Rgba& c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }
/// The colour at a different opacity.
[[nodiscard]] inline Rgba with_alpha(Rgba c, double alpha) {
  c.a = alpha;
  return c;
}

}  // namespace linkage
