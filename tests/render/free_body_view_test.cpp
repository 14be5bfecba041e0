// The free-body view (--view fbd): each pin force's name sits at its own arrow, not in
// the gap where the other arrow could be meant, and neither body goes under a panel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/clip_renderer.hpp"
#include "render/label_layout.hpp"
#include "render_test_support.hpp"
#include "scene/scene_builder.hpp"

namespace linkage {
namespace {

double distance(const Rect& r, const Vec2& p) {
  const double dx = std::max({r.x - p.x(), 0.0, p.x() - r.x - r.width});
  const double dy = std::max({r.y - p.y(), 0.0, p.y() - r.y - r.height});
  return std::hypot(dx, dy);
}

// Nearest distance from the box to the segment a-b (pixels), sampled finely.
double distance(const Rect& r, const Vec2& a, const Vec2& b) {
  double nearest = 1e300;
  for (int i = 0; i <= 200; ++i) nearest = std::min(nearest, distance(r, a + (b - a) * (i / 200.0)));
  return nearest;
}

TEST(FreeBodyView, PinForceNamesSitAtTheirOwnArrowsAndBodiesClearThePanels) {
  const Params p;
  // Ten seconds every quarter second: the pair turns through every angle.
  const Motion motion = test::closed_form_motion(p, State{}, 41, 0.25, true);
  for (const auto& [width, height] : {std::pair{854, 480}, std::pair{1280, 720}}) {
    SCOPED_TRACE(width);
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.free_body = true;
    ClipRenderer renderer(p, motion, settings, load_theme("light", {}, "theme"), "Case 3");
    ASSERT_FALSE(renderer.legend_rect().empty());
    const std::vector<Rect> panels{renderer.legend_rect(), renderer.path_inset().inset.rect};
    Frame frame(width, height);
    DrawList list;
    for (std::size_t k = 0; k < motion.samples.size(); ++k) {
      SCOPED_TRACE("t = " + std::to_string(motion.samples[k].t));
      renderer.draw(k, frame);
      const Camera camera = renderer.camera_at(k);
      const SceneLabels& layout = renderer.labels();
      // The bodies, as drawn: no edge enters the legend or the inset, no corner inside.
      for (std::size_t i = 0; i < layout.segment_count; ++i) {
        const Segment& s = layout.segments[i];
        if (s.body < 0) continue;
        for (const Rect& panel : panels) {
          EXPECT_FALSE(crosses(panel, s.a, s.b)) << "block " << s.body;
          EXPECT_GT(distance(panel, s.a), 0.0) << "block " << s.body;
        }
      }
      // The pin-force arrows, from the scene itself, by what they act on.
      build_scene(p, renderer.scene_options(), motion, k, list);
      std::vector<std::pair<std::string, std::pair<Vec2, Vec2>>> arrows;
      for (const Arrow& a : list.arrows)
        if (a.kind == ArrowKind::pin_force)
          arrows.push_back({std::string(a.tag), {camera.to_pixels(a.tail), camera.to_pixels(a.tail + a.vector)}});
      ASSERT_EQ(arrows.size(), 2U);
      int named = 0;
      for (std::size_t i = 0; i < layout.count; ++i) {
        const std::string text = layout.labels[i].text.data();
        for (std::size_t own = 0; own < 2; ++own) {
          if (text.rfind(arrows[own].first, 0) != 0) continue;
          ++named;
          const auto& [a, b] = arrows[own].second;
          const auto& [c, d] = arrows[1 - own].second;
          const double mine = distance(layout.labels[i].box, a, b), other = distance(layout.labels[i].box, c, d);
          // Plainly nearer its own: by at least a few pixels, not a tie.
          EXPECT_LT(mine + 3, other) << text << ": " << mine << " px from its arrow, " << other << " px from the other";
        }
      }
      EXPECT_EQ(named, 2);
    }
  }
}

}  // namespace
}  // namespace linkage
