// What `linkage render` writes: an MP4 that decodes to the promised codec, pixel
// format, size, frame count and duration; byte-identical PNG sequences; a still and a
// well-formed SVG; and, through --stats, that it does only the work the picture needs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "encode/encode_test_support.hpp"
#include "render/xml_check.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

// Small and short, so the suite stays fast under AddressSanitizer.
const std::vector<std::string> kSmall{"render", "--quiet", "--size", "160x90", "--fps", "10"};

RunResult render(std::vector<std::string> extra) {
  std::vector<std::string> args = kSmall;
  args.insert(args.end(), extra.begin(), extra.end());
  return run_linkage(args);
}

nlohmann::json stats_of(const RunResult& r) {
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(RenderCli, Mp4DecodesToTheClipThatWasAskedFor) {
  TempDir dir;
  // 1.5 s of motion at half speed: 3 s of video, round(1.5 / 0.5 x 10) = 30 frames.
  const RunResult r = render({"--duration", "1.5", "--speed", "0.5", "--out", (dir / "clip.mp4").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.mp4"});
  const DecodedVideo video = decode_video(dir / "clip.mp4");
  EXPECT_EQ(video.codec, "h264");
  EXPECT_EQ(video.pixel_format, AV_PIX_FMT_YUV420P);
  EXPECT_EQ(video.width, 160);
  EXPECT_EQ(video.height, 90);
  EXPECT_EQ(video.times.size(), 30u);
  EXPECT_NEAR(video.stream_duration, 3.0, 1e-9);
  EXPECT_NEAR(av_q2d(video.frame_rate), 10.0, 1e-9);
  // The index comes first, so a browser can play while downloading.
  const std::vector<std::string> atoms = top_level_atoms(dir / "clip.mp4");
  const auto moov = std::find(atoms.begin(), atoms.end(), "moov"), mdat = std::find(atoms.begin(), atoms.end(), "mdat");
  ASSERT_NE(moov, atoms.end());
  EXPECT_LT(moov, mdat);
}

TEST(RenderCli, PngSequenceIsNumberedAndByteIdenticalAcrossRuns) {
  TempDir dir;
  std::filesystem::create_directory(dir / "a");
  std::filesystem::create_directory(dir / "b");
  for (const char* folder : {"a", "b"})
    ASSERT_EQ(render({"--duration", "0.5", "--frames", (dir / folder).string()}).exit_code, 0);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a", "b"})) << "--frames alone writes no video";
  const std::vector<std::string> names = entries(dir / "a");
  ASSERT_EQ(names.size(), 5u);
  EXPECT_EQ(names.front(), "frame_00000.png");
  EXPECT_EQ(names.back(), "frame_00004.png");
  for (const std::string& name : names) EXPECT_EQ(file_bytes(dir / "a" / name), file_bytes(dir / "b" / name)) << name;
  const DecodedPng png = decode_png(dir / "a" / names.back());
  EXPECT_EQ(png.width, 160u);
  EXPECT_EQ(png.height, 90u);
}

// --frames makes its folder with the parents (mkdir -p), and a shorter run leaves none of
// an older, longer sequence's frames behind (other files stay).
TEST(RenderCli, FramesFolderIsMadeAndOlderFramesDoNotLinger) {
  TempDir dir;
  const std::string deep = (dir / "x" / "y" / "z").string();
  ASSERT_EQ(render({"--duration", "1", "--frames", deep}).exit_code, 0);
  EXPECT_EQ(entries(deep).size(), 10u);
  test::write_text(dir / "x" / "y" / "z" / "notes.txt", "mine");
  test::write_text(dir / "x" / "y" / "z" / "frame_0000042.png", "an older, wider numbering");
  ASSERT_EQ(render({"--duration", "0.5", "--frames", deep}).exit_code, 0);
  const std::vector<std::string> names = entries(deep);
  EXPECT_EQ(names, (std::vector<std::string>{"frame_00000.png", "frame_00001.png", "frame_00002.png", "frame_00003.png",
                                             "frame_00004.png", "notes.txt"}));
}

TEST(RenderCli, StillsAsPngSvgAndPdf) {
  TempDir dir;
  ASSERT_EQ(render({"--out", (dir / "still.png").string(), "--at", "0.5"}).exit_code, 0);
  ASSERT_EQ(render({"--out", (dir / "fig.svg").string(), "--at", "0.5"}).exit_code, 0);
  ASSERT_EQ(render({"--out", (dir / "fig.pdf").string(), "--at", "0.5", "--theme", "print"}).exit_code, 0);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"fig.pdf", "fig.svg", "still.png"}));
  EXPECT_EQ(decode_png(dir / "still.png").width, 160u);
  const std::string svg = read_text(dir / "fig.svg");
  EXPECT_EQ(xml_error(svg), "");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_EQ(read_text(dir / "fig.pdf").rfind("%PDF-", 0), 0u);
}

// --arrow-scale and --view fbd change the picture, not whether it is made; a view
// rectangle still means the fixed camera.
TEST(RenderCli, ArrowScalesAndTheFreeBodyView) {
  TempDir dir;
  const auto still = [&](const std::string& name, std::vector<std::string> flags) {
    flags.insert(flags.end(), {"--out", (dir / name).string(), "--at", "0.5"});
    const RunResult r = render(flags);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
    return file_bytes(dir / name);
  };
  const auto plain = still("plain.png", {});
  EXPECT_NE(still("common.png", {"--arrow-scale", "common"}), plain);
  EXPECT_NE(still("set.png", {"--arrow-scale", "pin=0.001,gravity=0.5"}), plain);
  EXPECT_NE(still("fbd.png", {"--view", "fbd"}), plain);
  EXPECT_NE(still("fbd_fit.png", {"--view", "fbd", "--camera", "fit"}), plain);
  EXPECT_NE(still("rectangle.png", {"--view", "-1,-2,3,3"}), plain);
  EXPECT_NE(still("mechanism.png", {"--mechanism", "slider-crank", "--arrow-scale", "joint=100"}),
            still("mechanism_default.png", {"--mechanism", "slider-crank"}));
}

// Overlays on the homework: an ensemble, settings, and a trajectory file from simulate
// (a student's own integrator's output would look the same); each changes the picture,
// the same every time. Then a mechanism's trajectory file and another mechanism.
TEST(RenderCli, HomeworkOverlaysFromSettingsAndATrajectoryFile) {
  TempDir dir;
  const RunResult sim = run_linkage(
      {"simulate", "--integrator", "euler", "--dt", "0.01", "--duration", "2", "--out", (dir / "euler.csv").string()});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto still = [&](const std::string& name, std::vector<std::string> flags) {
    flags.insert(flags.end(), {"--out", (dir / name).string(), "--at", "1.5"});
    const RunResult r = render(flags);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
    return file_bytes(dir / name);
  };
  const auto plain = still("plain.png", {});
  EXPECT_NE(still("ensemble.png", {"--ensemble", "5", "--spread", "0.2"}), plain);
  EXPECT_NE(still("settings.png", {"--compare", "theta2=0.5,integrator=rk4"}), plain);
  const auto file = still("file.png", {"--compare", (dir / "euler.csv").string()});
  EXPECT_NE(file, plain);
  EXPECT_EQ(still("again.png", {"--compare", (dir / "euler.csv").string()}), file);
  const RunResult dp = run_linkage(
      {"simulate", "--mechanism", "double-pendulum", "--duration", "2", "--out", (dir / "dp.csv").string()});
  ASSERT_EQ(dp.exit_code, 0) << dp.err;
  EXPECT_NE(still("dp.png", {"--mechanism", "double-pendulum", "--compare", (dir / "dp.csv").string()}),
            still("dp_plain.png", {"--mechanism", "double-pendulum"}));
  EXPECT_NE(still("blocks.png", {"--mechanism", "two-blocks", "--compare", "unequal-blocks"}),
            still("blocks_plain.png", {"--mechanism", "two-blocks"}));
}

// --compare FILE.csv with only the generalized coordinates (the homework's t, x1, y1,
// theta1, theta2: x2, y2 follow through the pin), and with its angles in degrees as
// `simulate --angles deg` heads them ("theta1 (deg)"): the same picture as in radians.
TEST(RenderCli, ATrajectoryFileOfTheCoordinatesInRadiansOrDegrees) {
  TempDir dir;
  for (const char* unit : {"rad", "deg"}) {
    std::filesystem::create_directory(dir / unit);
    const RunResult sim =
        run_linkage({"simulate", "--integrator", "euler", "--dt", "0.01", "--duration", "2", "--angles", unit,
                     "--columns", "t,x1,y1,theta1,theta2", "--out", (dir / unit / "run.csv").string()});
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
  }
  EXPECT_EQ(read_text(dir / "deg" / "run.csv").substr(0, 36), "t,x1,y1,theta1 (deg),theta2 (deg)\n0,");
  const auto still = [&](const char* unit) {
    const RunResult r = render(
        {"--compare", (dir / unit / "run.csv").string(), "--at", "1.5", "--out", (dir / unit / "still.png").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return file_bytes(dir / unit / "still.png");
  };
  const auto radians = still("rad");
  EXPECT_FALSE(radians.empty());
  EXPECT_EQ(still("deg"), radians);
  const RunResult plain = render({"--at", "1.5", "--out", (dir / "plain.png").string()});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_NE(file_bytes(dir / "plain.png"), radians);  // the compared blocks are drawn
}

// Issue 23 (f): the homework is two-blocks.toml drawn as any mechanism: its flags and
// `--mechanism two-blocks --set` at the same settings give the same picture, byte for byte,
// a still and a clip's frames alike.
TEST(RenderCli, TheHomeworkIsTwoBlocksDrawnAsAnyMechanism) {
  TempDir dir;
  const auto drawn = [&](const std::string& name, std::vector<std::string> flags) {
    flags.insert(flags.end(), {"--out", (dir / name).string(), "--at", "1.5", "--show", "velocity,acceleration"});
    const RunResult r = render(flags);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
    return file_bytes(dir / name);
  };
  const auto homework = drawn("homework.png", {"--L", "0.4", "--theta1", "0.3", "--case", "1"});
  EXPECT_EQ(homework, drawn("mechanism.png",
                            {"--mechanism", "two-blocks", "--set", "L=0.4", "--set", "1.theta=0.3", "--case", "1"}));
  EXPECT_NE(homework, drawn("other.png", {"--mechanism", "two-blocks", "--case", "1"}));
  // --set is a setting of the default mechanism as of any (simulate and solve take it too).
  EXPECT_EQ(homework, drawn("set.png", {"--set", "L=0.4", "--theta1", "0.3", "--case", "1"}));
  for (const std::string flags : {"homework", "mechanism"}) {
    std::vector<std::string> args{"--duration", "0.2", "--frames", (dir / flags).string()};
    if (flags == "mechanism") args.insert(args.end(), {"--mechanism", "two-blocks"});
    ASSERT_EQ(render(args).exit_code, 0);
  }
  for (const std::string& frame : entries(dir / "homework"))
    EXPECT_EQ(file_bytes(dir / "homework" / frame), file_bytes(dir / "mechanism" / frame)) << frame;
}

TEST(RenderCli, OnlyTheWorkThePictureNeeds) {
  TempDir dir;
  const std::string frames = (dir / "f").string();
  std::filesystem::create_directory(frames);
  // A PNG sequence opens no encoder. The homework is drawn as any mechanism (two-blocks.toml):
  // every frame painted whole, the joint force part of every sample (no separate solves).
  const nlohmann::json sequence = stats_of(render({"--duration", "2", "--frames", frames, "--stats"}));
  EXPECT_EQ(sequence["encoder_opened"], false);
  EXPECT_EQ(sequence["frames_drawn"], 20);
  EXPECT_EQ(sequence["png_files_written"], 20);
  EXPECT_GT(sequence["trail_points_drawn"], 20);  // the file's [picture] trail of P

  // No trail: no trail points, and no samples between the frames for it.
  const nlohmann::json bare =
      stats_of(render({"--duration", "2", "--frames", frames, "--hide", "pin-force,trail", "--stats"}));
  EXPECT_EQ(bare["trail_points_drawn"], 0);
  EXPECT_EQ(bare["frames_drawn"], 20);
  EXPECT_EQ(bare["samples"], 20);
  EXPECT_GT(sequence["samples"], bare["samples"]);

  // A still draws one frame; without a trail it samples only the frames of the 2 s before
  // it (its arrow scales see what a clip's would), none between them.
  const nlohmann::json still =
      stats_of(render({"--out", (dir / "s.png").string(), "--at", "3", "--hide", "trail", "--stats"}));
  const nlohmann::json trailed = stats_of(render({"--out", (dir / "t.png").string(), "--at", "3", "--stats"}));
  EXPECT_EQ(still["frames_drawn"], 1);
  EXPECT_EQ(still["trail_points_drawn"], 0);
  EXPECT_GT(trailed["trail_points_drawn"], 0);
  EXPECT_LT(still["samples"], trailed["samples"]);
  EXPECT_EQ(still["encoder_opened"], false);

  // A video opens its encoder.
  const nlohmann::json video = stats_of(render({"--duration", "0.5", "--out", (dir / "c.mp4").string(), "--stats"}));
  EXPECT_EQ(video["encoder_opened"], true);
  EXPECT_EQ(video["frames_drawn"], 5);
  EXPECT_EQ(video["png_files_written"], 0);
}

TEST(RenderCli, VideoAndSequenceTogether) {
  TempDir dir;
  std::filesystem::create_directory(dir / "f");
  ASSERT_EQ(
      render({"--duration", "0.3", "--out", (dir / "c.mp4").string(), "--frames", (dir / "f").string()}).exit_code, 0);
  EXPECT_EQ(decode_video(dir / "c.mp4").times.size(), 3u);
  EXPECT_EQ(entries(dir / "f").size(), 3u);
}

// A clip of a run whose numbers mean nothing (explicit Euler, Case 1, no stabilization,
// a large step: the pin of a mechanism without loops drifts metres) is made, and ends
// with one warning naming the joint, even with --quiet; the spec's example gives none.
TEST(RenderCli, AMeaninglessRunEndsWithOneWarning) {
  TempDir dir;
  const RunResult r = render({"--out", (dir / "drift.png").string(), "--at", "10", "--case", "1", "--integrator",
                              "euler", "--dt", "0.05", "--theta1-dot", "20", "--theta2-dot", "-35"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.rfind("linkage: warning: the run's numbers do not describe the motion: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("joint P came "), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "drift.png"));
  const RunResult example = render({"--out", (dir / "example.png").string(), "--at", "10"});
  ASSERT_EQ(example.exit_code, 0) << example.err;
  EXPECT_EQ(example.err, "");
}

TEST(RenderCli, PanelAndCaptionInAStillAndAClip) {
  TempDir dir;
  const RunResult still = run_linkage({"render", "--quiet", "--size", "320x180", "--panel", "theta1,F_y", "--caption",
                                       "Both angles so far", "--at", "0.5", "--out", (dir / "panel.png").string()});
  ASSERT_EQ(still.exit_code, 0) << still.err;
  const RunResult clip =
      render({"--duration", "0.5", "--panel", "energy_error", "--out", (dir / "panel.mp4").string()});
  ASSERT_EQ(clip.exit_code, 0) << clip.err;
  EXPECT_EQ(decode_video(dir / "panel.mp4").times.size(), 5u);
  // An unknown name: one line naming it and the valid ones, exit 2, no file.
  const RunResult bad = render({"--panel", "theta1,energy_eror", "--out", (dir / "bad.png").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_NE(bad.err.find("--panel: 'energy_eror' is not a quantity to plot (did you mean 'energy_error'?); valid: t,"),
            std::string::npos)
      << bad.err;
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"panel.mp4", "panel.png"}));
}

TEST(RenderCli, HelpListsElementsQualitiesAndThemes) {
  const RunResult r = run_linkage({"render", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* text : {"pin-force", "1920x1080@60", "dark, light, print", "--camera", "--view", "--frames", "--at"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text;
}

}  // namespace
}  // namespace linkage::test

namespace linkage::test {
namespace {

// A ring (a hoop: inertia m r^2) is drawn as a rim around a hole, a disc filled: the
// picture tells them apart as the physics does. 100 px per m; the centres at (50, 50) and
// (150, 50) px, the ring's hole out to 0.8 r = 0.24 m.
TEST(RenderCli, ARingIsARimAroundAHoleADiscIsFilled) {
  TempDir dir;
  std::ofstream(dir / "ring.toml") << R"(title = "A ring and a disc"
[parameters]
r = { value = 0.3, unit = "m", meaning = "radius" }
[[body]]
name = "ring"
shape = "ring"
mass = 1
radius = "r"
[[body]]
name = "disc"
shape = "disc"
mass = 1
radius = "r"
[initial]
ring = { x = -0.5, y = 0, theta = 0, x_dot = 0, y_dot = 0, theta_dot = 0 }
disc = { x = 0.5, y = 0, theta = 0, x_dot = 0, y_dot = 0, theta_dot = 0 }
)";
  const RunResult r = run_linkage({"render", "--quiet", "--mechanism", (dir / "ring.toml").string(), "--at", "0",
                                   "--view=-1,-0.5,1,0.5", "--size", "200x100", "--hide",
                                   "grid,labels,com,hud,legend,title", "--out", (dir / "ring.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const DecodedPng png = decode_png(dir / "ring.png");
  ASSERT_EQ(png.width, 200u);
  const auto pixel = [&](std::uint32_t x, std::uint32_t y) {
    const std::size_t at = 4 * (static_cast<std::size_t>(y) * png.width + x);
    return std::vector<std::uint8_t>(png.rgba.begin() + static_cast<std::ptrdiff_t>(at),
                                     png.rgba.begin() + static_cast<std::ptrdiff_t>(at + 4));
  };
  const auto background = pixel(100, 10);
  EXPECT_EQ(pixel(50, 38), background) << "0.12 m above the ring's centre: its hole";
  EXPECT_NE(pixel(50, 23), background) << "0.27 m above the ring's centre: its rim";
  EXPECT_NE(pixel(150, 38), background) << "0.12 m above the disc's centre: filled";
}

}  // namespace
}  // namespace linkage::test
