#include "render/settings.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

namespace linkage {
namespace {

// The message of the Error::input that `f` throws ("" if none).
template <typename F>
std::string input_error(F f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    return e.what();
  }
  return "";
}

TEST(RenderSettings, FrameCountAndTimes) {
  RenderSettings s;
  s.duration = 10;
  s.speed = 1;
  s.fps = 30;
  EXPECT_EQ(s.frame_count(), 300);
  EXPECT_DOUBLE_EQ(s.frame_time(299), 299.0 / 30);
  s.speed = 0.25;  // slow motion: 40 s of video
  EXPECT_EQ(s.frame_count(), 1200);
  EXPECT_DOUBLE_EQ(s.frame_time(4), 4 * 0.25 / 30);
  s.duration = 1.0;
  s.speed = 3.0;  // 1/3 s of video at 30 fps: round(10) frames
  EXPECT_EQ(s.frame_count(), 10);
  s.duration = 0.05;
  s.speed = 1;
  EXPECT_EQ(s.frame_count(), 2);  // round(1.5) = 2
}

TEST(RenderSettings, Sizes) {
  int w = 0, h = 0;
  parse_size("1280x720", "--size", w, h);
  EXPECT_EQ(w, 1280);
  EXPECT_EQ(h, 720);
  EXPECT_NE(input_error([&] { parse_size("1281x720", "--size", w, h); }).find("even"), std::string::npos);
  EXPECT_NE(input_error([&] { parse_size("0x720", "--size", w, h); }).find("positive"), std::string::npos);
  EXPECT_NE(input_error([&] { parse_size("-2x720", "--size", w, h); }).find("positive"), std::string::npos);
  EXPECT_NE(input_error([&] { parse_size("7682x4320", "--size", w, h); }).find("7680x4320"), std::string::npos);
  EXPECT_NE(input_error([&] { parse_size("1280x", "--size", w, h); }).find("WIDTHxHEIGHT"), std::string::npos);
  EXPECT_NE(input_error([&] { parse_size("big", "--size", w, h); }).find("--size"), std::string::npos);
}

TEST(RenderSettings, Ranges) {
  const auto with = [](auto change) {
    RenderSettings s;
    change(s);
    return input_error([&] { s.validate(); });
  };
  EXPECT_EQ(with([](RenderSettings&) {}), "");
  EXPECT_NE(with([](RenderSettings& s) { s.fps = 0; }).find("fps: "), std::string::npos);
  EXPECT_NE(with([](RenderSettings& s) { s.fps = 241; }).find("1 .. 240"), std::string::npos);
  EXPECT_NE(with([](RenderSettings& s) { s.duration = 0; }).find("duration: "), std::string::npos);
  EXPECT_NE(with([](RenderSettings& s) { s.duration = -1; }).find("positive"), std::string::npos);
  EXPECT_NE(with([](RenderSettings& s) { s.duration = 3601; }).find("an hour"), std::string::npos);
  EXPECT_EQ(with([](RenderSettings& s) {
              s.duration = 7200;
              s.speed = 2;
            }),
            "");  // one hour of video
  EXPECT_NE(with([](RenderSettings& s) { s.speed = 0; }).find("speed: "), std::string::npos);
  EXPECT_NE(with([](RenderSettings& s) { s.duration = 0.001; }).find("less than one frame"), std::string::npos);
  EXPECT_NE(with([](RenderSettings& s) { s.at = -1; }).find("at: "), std::string::npos);
  EXPECT_NE(with([](RenderSettings& s) { s.width = 641; }).find("even"), std::string::npos);
}

TEST(RenderSettings, ViewsCamerasQualitiesAndExtensions) {
  const View view = parse_view("-1,0.5,2,3", "--view");
  EXPECT_DOUBLE_EQ(view.xmin, -1);
  EXPECT_DOUBLE_EQ(view.ymin, 0.5);
  EXPECT_DOUBLE_EQ(view.xmax, 2);
  EXPECT_DOUBLE_EQ(view.ymax, 3);
  EXPECT_NE(input_error([] { (void)parse_view("0,0,0,1", "--view"); }).find("zero or negative area"),
            std::string::npos);
  EXPECT_NE(input_error([] { (void)parse_view("0,0,1", "--view"); }).find("four numbers"), std::string::npos);
  EXPECT_NE(input_error([] { (void)parse_view("0,0,1,x", "--view"); }).find("not a finite number"), std::string::npos);
  // A view whose width would overflow is refused at once, naming the coordinate and the range.
  EXPECT_EQ(input_error([] { (void)parse_view("-1e308,0,1e308,1", "view"); }),
            "view: '-1e308,0,1e308,1': xmin = -1e308 m is outside -1e9 .. 1e9 m");
  EXPECT_DOUBLE_EQ(parse_view("-1e9,0,1e9,1", "view").xmax, 1e9);
  EXPECT_EQ(parse_camera("fit", "--camera"), CameraMode::fit);
  EXPECT_NE(input_error([] { (void)parse_camera("orbit", "--camera"); }).find("follow, fixed, fit"), std::string::npos);
  EXPECT_EQ(parse_quality("4k", "--quality").height, 2160);
  EXPECT_EQ(parse_quality("low", "--quality").width, 854);
  EXPECT_NE(input_error([] { (void)parse_quality("ultra", "--quality"); }).find("medium (1280x720@30)"),
            std::string::npos);
  // A typo gets the nearest name, whether from a flag or a lesson's render key.
  EXPECT_EQ(input_error([] { (void)parse_camera("folow", "camera"); }),
            "camera: 'folow' is not a camera (did you mean 'follow'?); valid: follow, fixed, fit");
  EXPECT_EQ(input_error([] { (void)parse_quality("hgh", "--quality"); }),
            "--quality: 'hgh' is not a quality (did you mean 'high'?); valid: low (854x480@30), medium (1280x720@30), "
            "high (1920x1080@60), 4k (3840x2160@60)");
  EXPECT_EQ(input_error([] { (void)parse_quality("ultra", "--quality"); }).find("did you mean"), std::string::npos);
  EXPECT_EQ(output_kind("a/b.svg", "--out"), OutputKind::svg);
  EXPECT_EQ(output_kind("clip.mp4", "--out"), OutputKind::mp4);
  EXPECT_EQ(output_kind("clip.gif", "--out"), OutputKind::gif);
  EXPECT_EQ(output_kind("a/Clip.WEBM", "--out"), OutputKind::webm);
  for (const OutputKind kind : {OutputKind::mp4, OutputKind::gif, OutputKind::webm}) {
    EXPECT_TRUE(is_video(kind));
    EXPECT_FALSE(is_still(kind));
  }
  for (const OutputKind kind : {OutputKind::png, OutputKind::svg, OutputKind::pdf}) {
    EXPECT_FALSE(is_video(kind));
    EXPECT_TRUE(is_still(kind));
  }
  EXPECT_NE(input_error([] { (void)output_kind("clip.avi", "--out"); }).find("valid: .mp4, .gif or .webm (clip)"),
            std::string::npos);
  EXPECT_NE(input_error([] { (void)output_kind("clip.avi", "--out"); }).find("'.avi'"), std::string::npos);
  EXPECT_NE(input_error([] { (void)output_kind("clip", "--out"); }).find("no extension"), std::string::npos);
}

}  // namespace
}  // namespace linkage
