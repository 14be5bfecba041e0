#include "render/text.hpp"

#include <memory>

#include "render/style.hpp"

namespace linkage::text {
namespace {
struct FontOptionsDeleter {
  void operator()(cairo_font_options_t* o) const { cairo_font_options_destroy(o); }
};

// Where text aligned at x starts (the current font).
double start_x(cairo_t* cr, double x, const char* s, Align align) {
  if (align == Align::left) return x;
  cairo_text_extents_t extents;
  cairo_text_extents(cr, s, &extents);
  return x - (align == Align::centre ? 0.5 * extents.x_advance : extents.x_advance);
}
}  // namespace

void use(cairo_t* cr, const Font& font) {
  // Made once (thread-safe) and copied into each context: no allocation per text.
  static const std::unique_ptr<cairo_font_options_t, FontOptionsDeleter> options = [] {
    std::unique_ptr<cairo_font_options_t, FontOptionsDeleter> o(cairo_font_options_create());
    cairo_font_options_set_antialias(o.get(), CAIRO_ANTIALIAS_GRAY);
    cairo_font_options_set_hint_style(o.get(), CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(o.get(), CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_subpixel_order(o.get(), CAIRO_SUBPIXEL_ORDER_DEFAULT);
    return o;
  }();
  cairo_select_font_face(cr, font.mono ? "DejaVu Sans Mono" : "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         font.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, font.size);
  cairo_set_font_options(cr, options.get());
}

double width(cairo_t* cr, const Font& font, const char* s) {
  use(cr, font);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, s, &extents);
  return extents.x_advance;
}

Metrics metrics(cairo_t* cr, const Font& font) {
  use(cr, font);
  cairo_font_extents_t extents;
  cairo_font_extents(cr, &extents);
  return {extents.ascent, extents.descent};
}

void draw(cairo_t* cr, const Font& font, double x, double y, const char* s, const Rgba& colour, Align align) {
  use(cr, font);
  x = start_x(cr, x, s, align);
  set_colour(cr, colour);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, s);
}

namespace {
// Fills the current text path over a stroked halo.
void fill_with_halo(cairo_t* cr, const Rgba& colour, const Rgba& halo, double halo_width) {
  set_colour(cr, halo);
  cairo_set_line_width(cr, halo_width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke_preserve(cr);
  set_colour(cr, colour);
  cairo_fill(cr);
}
}  // namespace

void draw_with_halo(cairo_t* cr, const Font& font, double x, double y, const char* s, const Rgba& colour,
                    const Rgba& halo, double halo_width, Align align) {
  use(cr, font);
  x = start_x(cr, x, s, align);
  cairo_move_to(cr, x, y);
  cairo_text_path(cr, s);
  fill_with_halo(cr, colour, halo, halo_width);
}

void draw_centred_with_halo(cairo_t* cr, const Font& font, double x, double y, const char* s, const Rgba& colour,
                            const Rgba& halo, double halo_width) {
  use(cr, font);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, s, &extents);
  // Centre the ink box, not the advance, so short labels ("1", "F") sit on the point.
  cairo_move_to(cr, x - extents.x_bearing - 0.5 * extents.width, y - extents.y_bearing - 0.5 * extents.height);
  cairo_text_path(cr, s);
  fill_with_halo(cr, colour, halo, halo_width);
}

}  // namespace linkage::text
