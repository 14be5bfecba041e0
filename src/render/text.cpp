#include "render/text.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <functional>
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

// Stroking a halo around glyph outlines is about half of a frame's drawing, and a clip
// draws the same labels frame after frame, so on an image surface a haloed label is drawn
// once into a small sprite for each quarter-pixel phase of its pen, then copied. Every
// haloed label on an image surface goes through a sprite, hit or miss, so the pixels never
// depend on what the cache held. A memo per thread of fixed slots: no heap allocation
// but the sprites' own pixels (Cairo's).
constexpr int kPhases = 4;            // sub-pixel positions a pixel, each way
constexpr std::size_t kLongest = 47;  // longer text is drawn directly
constexpr std::size_t kSlots = 512;

struct SpriteKey {
  std::array<char, kLongest + 1> text{};
  Font font{};
  Rgba colour{}, halo{};
  double halo_width = 0;
  int phase_x = 0, phase_y = 0;
  bool operator==(const SpriteKey&) const = default;
};

struct Sprite {
  SpriteKey key{};
  cairo_surface_t* pixels = nullptr;  // the label with its halo on transparent, pen at origin + phase
  int origin_x = 0, origin_y = 0;     // the pen's whole pixel in the sprite
};

class Sprites {
 public:
  Sprites() = default;
  Sprites(const Sprites&) = delete;
  Sprites& operator=(const Sprites&) = delete;
  ~Sprites() {
    for (Sprite& sprite : slots_)
      if (sprite.pixels != nullptr) cairo_surface_destroy(sprite.pixels);
  }

  // The sprite for `key`, drawn now when its slot holds another (or nothing); null when
  // Cairo cannot make one.
  const Sprite* find(const SpriteKey& key, const cairo_text_extents_t& ink) {
    Sprite& slot = slots_[hash(key) % kSlots];
    if (slot.pixels != nullptr && slot.key == key) return &slot;
    if (slot.pixels != nullptr) cairo_surface_destroy(slot.pixels);
    slot.pixels = nullptr;
    slot.key = key;
    const double reach = 0.5 * key.halo_width + 2;  // the halo's half width and antialiasing
    slot.origin_x = static_cast<int>(std::ceil(reach - ink.x_bearing));
    slot.origin_y = static_cast<int>(std::ceil(reach - ink.y_bearing));
    const int width = static_cast<int>(std::ceil(slot.origin_x + ink.x_bearing + ink.width + reach)) + 1;
    const int height = static_cast<int>(std::ceil(slot.origin_y + ink.y_bearing + ink.height + reach)) + 1;
    cairo_surface_t* pixels = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    if (cairo_surface_status(pixels) != CAIRO_STATUS_SUCCESS) {
      cairo_surface_destroy(pixels);
      return nullptr;
    }
    cairo_t* cr = cairo_create(pixels);
    use(cr, key.font);
    cairo_move_to(cr, slot.origin_x + static_cast<double>(key.phase_x) / kPhases,
                  slot.origin_y + static_cast<double>(key.phase_y) / kPhases);
    cairo_text_path(cr, key.text.data());
    fill_with_halo(cr, key.colour, key.halo, key.halo_width);
    cairo_destroy(cr);
    cairo_surface_flush(pixels);
    slot.pixels = pixels;
    return &slot;
  }

 private:
  static std::size_t hash(const SpriteKey& key) {
    std::size_t h = 1469598103934665603ull;  // FNV-1a over the text, then the phase
    for (const char* c = key.text.data(); *c != '\0'; ++c) h = (h ^ static_cast<unsigned char>(*c)) * 1099511628211ull;
    h = (h ^ static_cast<std::size_t>(key.phase_x * kPhases + key.phase_y)) * 1099511628211ull;
    return h ^ std::hash<double>{}(key.font.size);
  }

  std::array<Sprite, kSlots> slots_{};
};

// Splits a device coordinate into its whole pixel and its quarter-pixel phase.
void snap(double device, int& whole, int& phase) {
  whole = static_cast<int>(std::floor(device));
  phase = static_cast<int>(std::lround((device - whole) * kPhases));
  if (phase == kPhases) ++whole, phase = 0;
}

// Draws `s` with its pen at (x, y) over its halo, from a sprite when the target is an
// image surface drawn at unit scale with a whole-pixel offset; otherwise as paths (SVG and
// PDF keep their text as outlines). `ink`: the text's extents in the current font.
void draw_pen_with_halo(cairo_t* cr, const Font& font, double x, double y, const char* s, const Rgba& colour,
                        const Rgba& halo, double halo_width, const cairo_text_extents_t& ink) {
  cairo_matrix_t m;
  cairo_get_matrix(cr, &m);
  const bool raster = cairo_surface_get_type(cairo_get_target(cr)) == CAIRO_SURFACE_TYPE_IMAGE;
  const bool unit = m.xx == 1 && m.yy == 1 && m.xy == 0 && m.yx == 0 && m.x0 == std::floor(m.x0) &&
                    m.y0 == std::floor(m.y0) && std::isfinite(x) && std::isfinite(y) && std::fabs(x) < 1e6 &&
                    std::fabs(y) < 1e6;
  const std::size_t length = std::strlen(s);
  if (raster && unit && length <= kLongest) {
    thread_local Sprites sprites;
    SpriteKey key;
    std::memcpy(key.text.data(), s, length);
    key.font = font;
    key.colour = colour;
    key.halo = halo;
    key.halo_width = halo_width;
    int px = 0, py = 0;
    snap(x + m.x0, px, key.phase_x);
    snap(y + m.y0, py, key.phase_y);
    if (const Sprite* sprite = sprites.find(key, ink)) {
      cairo_set_source_surface(cr, sprite->pixels, px - sprite->origin_x - m.x0, py - sprite->origin_y - m.y0);
      cairo_paint(cr);
      // The state a drawn label leaves, which callers may rely on.
      cairo_new_path(cr);
      cairo_set_line_width(cr, halo_width);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
      set_colour(cr, colour);
      return;
    }
  }
  cairo_move_to(cr, x, y);
  cairo_text_path(cr, s);
  fill_with_halo(cr, colour, halo, halo_width);
}
}  // namespace

void draw_with_halo(cairo_t* cr, const Font& font, double x, double y, const char* s, const Rgba& colour,
                    const Rgba& halo, double halo_width, Align align) {
  use(cr, font);
  cairo_text_extents_t ink;
  cairo_text_extents(cr, s, &ink);
  if (align != Align::left) x -= align == Align::centre ? 0.5 * ink.x_advance : ink.x_advance;
  draw_pen_with_halo(cr, font, x, y, s, colour, halo, halo_width, ink);
}

void draw_centred_with_halo(cairo_t* cr, const Font& font, double x, double y, const char* s, const Rgba& colour,
                            const Rgba& halo, double halo_width) {
  use(cr, font);
  cairo_text_extents_t ink;
  cairo_text_extents(cr, s, &ink);
  // Centre the ink box, not the advance, so short labels ("1", "F") sit on the point.
  draw_pen_with_halo(cr, font, x - ink.x_bearing - 0.5 * ink.width, y - ink.y_bearing - 0.5 * ink.height, s, colour,
                     halo, halo_width, ink);
}

}  // namespace linkage::text
