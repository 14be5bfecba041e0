// Where a name goes: past an arrow's head when free, else around what is in the way.
// (That names never cover one another, an arrow or a body in any mechanism's frames, the
// homework's among them: tests/pipeline/mechanism_clip_test.cpp.)
#include "render/label_layout.hpp"

#include <gtest/gtest.h>

#include <array>

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

}  // namespace
}  // namespace linkage
