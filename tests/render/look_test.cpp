// Lines, marks and text scale with the frame, so a clip reads the same at 480p and 4K.
// Also writes sample pictures to $LINKAGE_RENDER_OUT (when set) for a person to look at.
#include <gtest/gtest.h>

#include "render/clip_renderer.hpp"
#include "render/theme.hpp"
#include "render_test_support.hpp"

namespace linkage {
namespace {

// Draws `motion` sample `index`; returns the number of pixels of the pin's fill colour.
long pin_pixels(const std::string& name, RenderSettings settings, const Motion& motion, std::size_t index) {
  const Params p;
  Theme theme = load_theme(settings.theme, {}, "--theme");
  ClipRenderer renderer(p, motion, settings, theme, "Case 3 \u00b7 dop853");
  Frame frame(settings.width, settings.height);
  renderer.draw(index, frame);
  if (const auto folder = test::picture_folder(); !folder.empty())
    test::write_png_file(frame, folder / (name + ".png"));
  theme.pin_fill = {1, 0, 1, 1};  // again with a unique pin colour, to measure it
  ClipRenderer marked(p, motion, settings, theme, "Case 3");
  marked.draw(index, frame);
  long count = 0;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x)
      if (test::colour_distance(test::rgb_at(frame, x, y), {255, 0, 255}) == 0) ++count;
  return count;
}

TEST(Look, MarksScaleWithTheFrameInEveryTheme) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 61, 1.0 / 30, true);
  RenderSettings settings;
  settings.elements.show(Element::velocity);
  for (const char* theme : {"light", "dark", "print"}) {
    settings.theme = theme;
    EXPECT_GT(pin_pixels(std::string("still_") + theme, settings, motion, 60), 20) << theme;
  }
  settings.theme = "light";
  settings.width = 854;
  settings.height = 480;
  const long small = pin_pixels("still_480p", settings, motion, 60);
  settings.width = 3840;
  settings.height = 2160;
  const long large = pin_pixels("still_4k", settings, motion, 60);
  // The pin's disc grows with the frame's height squared (4.5^2), edges aside.
  EXPECT_NEAR(static_cast<double>(large) / static_cast<double>(small), 4.5 * 4.5, 0.25 * 4.5 * 4.5);
}

}  // namespace
}  // namespace linkage
