#pragma once
// Text with Cairo's toy API in DejaVu Sans or Sans Mono (installed with fonts-dejavu-core), with
// fixed font options (greyscale antialiasing, no hinting, unhinted metrics) so text
// looks the same on every machine and measures the same on raster and vector surfaces.
#include <cairo.h>

#include "render/theme.hpp"

namespace linkage::text {

enum class Align { left, centre, right };

struct Font {
  double size = 12;  // pixels (points on vector surfaces)
  bool bold = false;
  bool mono = false;  // DejaVu Sans Mono: every code point one column wide (equations as printed)
  bool operator==(const Font&) const = default;
};

/// Sets the font and the fixed font options on `cr`.
void use(cairo_t* cr, const Font& font);
/// The advance width of `s` in `font`.
[[nodiscard]] double width(cairo_t* cr, const Font& font, const char* s);
/// The font's ascent and descent (the same for every string, so lines align).
struct Metrics {
  double ascent = 0, descent = 0;
};
[[nodiscard]] Metrics metrics(cairo_t* cr, const Font& font);

/// Draws `s` with its baseline at y, aligned at x.
void draw(cairo_t* cr, const Font& font, double x, double y, const char* s, const Rgba& colour,
          Align align = Align::left);
/// As draw(), over a halo of `halo` colour `halo_width` wide, so the text stays legible
/// on top of grid lines and fills.
void draw_with_halo(cairo_t* cr, const Font& font, double x, double y, const char* s, const Rgba& colour,
                    const Rgba& halo, double halo_width, Align align = Align::left);
/// Draws `s` centred on (x, y) (both ways) over a halo of `halo` colour, so it stays
/// legible on top of lines and fills.
void draw_centred_with_halo(cairo_t* cr, const Font& font, double x, double y, const char* s, const Rgba& colour,
                            const Rgba& halo, double halo_width);

}  // namespace linkage::text
