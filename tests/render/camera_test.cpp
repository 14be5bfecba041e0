#include "render/camera.hpp"

#include <gtest/gtest.h>

namespace linkage {
namespace {

TEST(Camera, WorldToPixelsWithYUpAndUniformScale) {
  const Camera camera({0.0, 0.0, 2.0, 1.0}, 800, 400);  // the frame's aspect exactly
  EXPECT_DOUBLE_EQ(camera.scale(), 400.0);
  EXPECT_EQ(camera.to_pixels({0.0, 0.0}), Vec2(0.0, 400.0));  // bottom left
  EXPECT_EQ(camera.to_pixels({2.0, 1.0}), Vec2(800.0, 0.0));  // top right
  EXPECT_EQ(camera.to_pixels({1.0, 0.75}), Vec2(400.0, 100.0));
  const Vec2 back = camera.to_world(camera.to_pixels({0.3, 0.2}));
  EXPECT_NEAR((back - Vec2(0.3, 0.2)).norm(), 0, 1e-15);
}

TEST(Camera, ViewIsWidenedToTheFrameNeverCut) {
  // A square view in a 16:9 frame: all of it shows, with extra width on both sides.
  const Camera camera({-1.0, -1.0, 1.0, 1.0}, 1280, 720);
  const View visible = camera.visible();
  EXPECT_DOUBLE_EQ(visible.ymin, -1.0);
  EXPECT_DOUBLE_EQ(visible.ymax, 1.0);
  EXPECT_NEAR(visible.xmin, -16.0 / 9.0, 1e-15);
  EXPECT_NEAR(visible.xmax, 16.0 / 9.0, 1e-15);
}

TEST(Camera, FollowingMovesTheCentreKeepsTheScale) {
  const Camera camera({-1.0, -1.0, 1.0, 1.0}, 640, 360);
  const Camera moved = camera.centred_at({5.0, -20.0});
  EXPECT_EQ(moved.scale(), camera.scale());
  EXPECT_EQ(moved.to_pixels({5.0, -20.0}), Vec2(320.0, 180.0));
}

TEST(Camera, AViewFittedBesideAKeptStripFillsTheRestOfTheFrame) {
  // A 2 x 1 view in the right 600 of an 800 x 400 frame: 300 px per metre (the width
  // decides), centred in that part; the left 200 px show what lies left of the view.
  Bounds area;
  area.include({200.0, 0.0});
  area.include({800.0, 400.0});
  const Camera camera({0.0, 0.0, 2.0, 1.0}, area, 800, 400);
  EXPECT_DOUBLE_EQ(camera.scale(), 300.0);
  EXPECT_NEAR((camera.to_pixels({1.0, 0.5}) - Vec2(500.0, 200.0)).norm(), 0, 1e-12);  // the centres
  EXPECT_NEAR((camera.to_pixels({0.0, 0.0}) - Vec2(200.0, 350.0)).norm(), 0, 1e-12);
  EXPECT_NEAR((camera.to_pixels({2.0, 1.0}) - Vec2(800.0, 50.0)).norm(), 0, 1e-12);
  const View visible = camera.visible();
  EXPECT_NEAR(visible.xmin, -2.0 / 3.0, 1e-12);
  EXPECT_NEAR(visible.ymax, 1.0 + 1.0 / 6.0, 1e-12);
  // Following moves what the area's middle shows, not the area.
  const Camera moved = camera.centred_at({5.0, -20.0});
  EXPECT_EQ(moved.scale(), camera.scale());
  EXPECT_NEAR((moved.to_pixels({5.0, -20.0}) - Vec2(500.0, 200.0)).norm(), 0, 1e-12);
  EXPECT_NEAR((moved.to_world(moved.to_pixels({4.0, -19.0})) - Vec2(4.0, -19.0)).norm(), 0, 1e-12);
}

TEST(Camera, ViewsAroundAPointAndOfBounds) {
  const View around = view_around({1.0, 2.0}, 0.5);
  EXPECT_DOUBLE_EQ(around.xmin, 0.5);
  EXPECT_DOUBLE_EQ(around.ymax, 2.5);
  Bounds bounds;
  bounds.include({0.0, 0.0});
  bounds.include({4.0, 2.0});
  const View grown = view_of(bounds, 0.25);  // a quarter of the larger side on every side
  EXPECT_DOUBLE_EQ(grown.xmin, -1.0);
  EXPECT_DOUBLE_EQ(grown.ymax, 3.0);
}

}  // namespace
}  // namespace linkage
