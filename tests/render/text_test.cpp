// Haloed labels on an image surface come from sprites kept per quarter-pixel phase: the
// pixels must not depend on what the cache held, a whole-pixel move must be an exact shift,
// and a sprite must land where drawing the outlines directly puts the label.
#include "render/text.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

namespace linkage {
namespace {

constexpr int kWidth = 200, kHeight = 60;
const text::Font kFont{16, true};
const Rgba kInk{0.8, 0.35, 0.05, 1}, kHalo{1, 1, 1, 1};

struct Canvas {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kWidth, kHeight);
  cairo_t* cr = cairo_create(surface);
  Canvas() {
    cairo_set_source_rgb(cr, 0.2, 0.4, 0.6);  // not the halo's colour, so the halo shows
    cairo_paint(cr);
  }
  ~Canvas() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;
  std::vector<unsigned char> pixels() {
    cairo_surface_flush(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    return {data, data + static_cast<std::ptrdiff_t>(cairo_image_surface_get_stride(surface)) * kHeight};
  }
  // The 8-bit channel at (x, y, c), c = 0..3 in memory order.
  int at(int x, int y, int c) {
    cairo_surface_flush(surface);
    return cairo_image_surface_get_data(surface)[y * cairo_image_surface_get_stride(surface) + 4 * x + c];
  }
};

std::vector<unsigned char> label_at(double x, double y, const char* s = "A on 3: 18 N") {
  Canvas canvas;
  text::draw_centred_with_halo(canvas.cr, kFont, x, y, s, kInk, kHalo, 4);
  return canvas.pixels();
}

TEST(HaloLabel, SamePixelsWhetherItsSpriteWasKeptOrDrawnAgain) {
  const std::vector<unsigned char> first = label_at(100.3, 30.6);
  EXPECT_EQ(label_at(100.3, 30.6), first);  // kept
  Canvas other;
  for (int k = 0; k < 3000; ++k)  // more labels than the cache has slots
    text::draw_with_halo(other.cr, kFont, 10 + 0.25 * (k % 4), 30, std::to_string(k).c_str(), kInk, kHalo, 4);
  EXPECT_EQ(label_at(100.3, 30.6), first);  // drawn again
  EXPECT_NE(label_at(100.3, 30.6, "A on 3: 19 N"), first);
}

TEST(HaloLabel, AWholePixelMoveShiftsThePixelsExactlyAQuarterPixelMoveDoesNot) {
  const std::vector<unsigned char> at = label_at(100.3, 30.6), right = label_at(101.3, 30.6),
                                   quarter = label_at(100.55, 30.6);
  const int stride = static_cast<int>(at.size()) / kHeight;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x + 1 < kWidth; ++x)
      for (int c = 0; c < 4; ++c)
        ASSERT_EQ(right[y * stride + 4 * (x + 1) + c], at[y * stride + 4 * x + c]) << x << ", " << y;
  EXPECT_NE(at, Canvas().pixels()) << "the label was drawn";
  EXPECT_NE(quarter, at);
}

// Drawn with a half-pixel translation the label takes the outline path; the sprite drawn
// with its pen at the same quarter-pixel device position must match it to within 8-bit compositing's rounding.
TEST(HaloLabel, ASpriteLandsWhereTheOutlinesDrawnDirectlyDo) {
  for (const double x : {100.0, 100.25, 100.5, 100.75}) {
    Canvas sprite, direct;
    text::draw_with_halo(sprite.cr, kFont, x - 70, 40.25, "O2 on 2: 22.8 N", kInk, kHalo, 4);
    cairo_translate(direct.cr, 0.5, 0);
    text::draw_with_halo(direct.cr, kFont, x - 70.5, 40.25, "O2 on 2: 22.8 N", kInk, kHalo, 4);
    int worst = 0;
    long changed = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int px = 0; px < kWidth; ++px)
        for (int c = 0; c < 3; ++c) {
          worst = std::max(worst, std::abs(sprite.at(px, y, c) - direct.at(px, y, c)));
          changed += direct.at(px, y, c) != direct.at(0, 0, c) ? 1 : 0;
        }
    EXPECT_LE(worst, 2) << "at x = " << x;
    EXPECT_GT(changed, 500) << "the label was drawn";
  }
}

}  // namespace
}  // namespace linkage
