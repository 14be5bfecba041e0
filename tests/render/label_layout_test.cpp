// Where a name goes: past an arrow's head when free, else around what is in the way.
// (That names never cover one another, an arrow or a body in any mechanism's frames, the
// homework's among them: tests/pipeline/mechanism_clip_test.cpp.)
#include "render/label_layout.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "render_test_support.hpp"

namespace linkage {
namespace {

TEST(LabelLayout, PlacesPastTheHeadWhenFreeAndAroundWhatIsInTheWay) {
  const Theme theme = load_theme("light", {}, "theme");
  DrawStyle style;
  style.theme = &theme;
  const Rect size{0, 0, 40, 12};
  const Placement free = place_label(size, {100, 100}, {1, 0}, {}, style, 400, 300);
  EXPECT_TRUE(free.clear);
  EXPECT_GT(free.box.x, 100);  // past the head, along the arrow
  EXPECT_NEAR(free.box.y + 0.5 * free.box.height, 100, 1e-9);
  // A box there and an arrow crossing the next places: the label goes elsewhere, clear of both.
  const std::array<Rect, 1> boxes{free.box};
  const std::array<Segment, 1> lines{Segment{{90, 80}, {200, 80}}};
  const Placement moved = place_label(size, {100, 100}, {1, 0}, {boxes, lines}, style, 400, 300);
  EXPECT_TRUE(moved.clear);
  EXPECT_FALSE(overlaps(moved.box, free.box));
  EXPECT_FALSE(crosses(moved.box, lines[0].a, lines[0].b));
  // A body's inside counts, not only its edges.
  const std::array<Segment, 4> square{Segment{{0, 0}, {50, 0}, 0}, Segment{{50, 0}, {50, 50}, 0},
                                      Segment{{50, 50}, {0, 50}, 0}, Segment{{0, 50}, {0, 0}, 0}};
  EXPECT_TRUE(touches({20, 20, 5, 5}, square));
  EXPECT_FALSE(touches({60, 20, 5, 5}, square));
}

// Issue 26: a spring's label sat on its coil. When every place crosses some line, the
// name still keeps off the coils: it may cross an arrow's shaft, not a spring.
TEST(LabelLayout, KeepsOffACoilWhenEveryPlaceCrossesSomeLine) {
  const Theme theme = load_theme("light", {}, "theme");
  DrawStyle style;
  style.theme = &theme;
  const Rect size{0, 0, 40, 12};
  std::vector<Segment> cage;  // upright lines 10 px apart: no 40 px box clears them
  for (double x = 5; x < 400; x += 10) cage.push_back({{x, 0}, {x, 300}});
  const std::array<Segment, 1> coil{Segment{{0, 100}, {400, 100}}};
  const Placement plain = place_label(size, {100, 100}, {1, 0}, {{}, cage}, style, 400, 300);
  EXPECT_FALSE(plain.clear);
  EXPECT_TRUE(crosses(plain.box, coil[0].a, coil[0].b));  // past the head, along the line
  const Placement off = place_label(size, {100, 100}, {1, 0}, {{}, cage, nullptr, {}, coil}, style, 400, 300);
  EXPECT_FALSE(off.clear);
  EXPECT_FALSE(touches(off.box, coil));
  EXPECT_LT(std::fabs(off.box.y + 0.5 * off.box.height - 100), 40);  // still beside the head
}

}  // namespace
}  // namespace linkage
