// Names never cover one another, an arrow or a block: the homework's frames at many
// times, at the default and the common arrow scale, and at two frame sizes. (Any
// mechanism's frames: tests/pipeline/mechanism_clip_test.cpp.)
#include "render/label_layout.hpp"

#include <gtest/gtest.h>

#include <string>

#include "render/clip_renderer.hpp"
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

TEST(LabelLayout, HomeworkNamesKeepClearOfEachOtherArrowsAndBlocks) {
  const Params p;
  // Ten seconds: the blocks turn through every relative angle and the pin force through
  // every direction; every quarter second.
  const Motion motion = test::closed_form_motion(p, State{}, 41, 0.25, true);
  for (const bool common : {false, true}) {
    for (const auto& [width, height] : {std::pair{854, 480}, std::pair{1280, 720}}) {
      SCOPED_TRACE(std::string(common ? "common" : "own") + " scale, " + std::to_string(width));
      RenderSettings settings;
      settings.width = width;
      settings.height = height;
      settings.elements.show(Element::velocity);  // the most arrows
      settings.arrow_scale.common = common;
      ClipRenderer renderer(p, motion, settings, load_theme("light", {}, "theme"), "Case 3");
      Frame frame(width, height);
      std::size_t valued = 0;
      for (std::size_t k = 0; k < motion.samples.size(); ++k) {
        SCOPED_TRACE("t = " + std::to_string(motion.samples[k].t));
        renderer.draw(k, frame);
        const SceneLabels& layout = renderer.labels();
        // Both blocks, the pin and six arrows are named.
        ASSERT_EQ(layout.count, 2U + 1U + 6U);
        const std::span<const Segment> segments(layout.segments.data(), layout.segment_count);
        for (std::size_t i = 0; i < layout.count; ++i) {
          const SceneLabels::Placed& a = layout.labels[i];
          const std::string text = a.text.data();
          if (text.find(" = ") != std::string::npos) ++valued;
          for (std::size_t j = i + 1; j < layout.count; ++j)
            EXPECT_FALSE(overlaps(a.box, layout.labels[j].box)) << text << " / " << layout.labels[j].text.data();
          for (const Segment& s : segments) {
            // A block's number is on its block; nothing else touches a block or an arrow.
            if (s.body >= 0 && a.block) continue;
            EXPECT_FALSE(crosses(a.box, s.a, s.b)) << text;
          }
          if (!a.block) {
            EXPECT_FALSE(touches(a.box, segments)) << text;
            // Nor the title, legend, scale bar or HUD (the first boxes taken).
            for (std::size_t panel = 0; panel < 4; ++panel) EXPECT_FALSE(overlaps(a.box, layout.boxes[panel])) << text;
          }
        }
      }
      // At one scale both forces' labels give their values (the pin force's arrow too
      // short to see, drawn longer), so their ratio reads off the frame.
      if (common) {
        EXPECT_EQ(valued, 4 * motion.samples.size());
      }
    }
  }
}

}  // namespace
}  // namespace linkage
