// Every bad input of `linkage render`: a non-zero exit (2 for input, 3 for a diverging
// simulation), one line naming the flag, the value and what is allowed, and nothing
// left on disk.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace linkage::test {
namespace {

struct BadInput {
  std::vector<std::string> args;  // "{dir}" is replaced by the test's folder
  std::string expected;           // a part of the one-line message
  int exit_code = 2;
};

class RenderBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(RenderBadInput, IsOneLineAndLeavesNothing) {
  TempDir dir;
  std::filesystem::create_directory(dir / "frames");
  write_text(dir / "plain", "not a folder");
  const auto in_dir = [&](std::string text) {
    if (const auto at = text.find("{dir}"); at != std::string::npos) text.replace(at, 5, dir.path().string());
    return text;
  };
  // Small defaults for the flags the case does not set itself.
  std::vector<std::string> args{"render", "--quiet"};
  const auto given = [&](const std::string& flag) {
    return std::find(GetParam().args.begin(), GetParam().args.end(), flag) != GetParam().args.end();
  };
  if (!given("--size")) args.insert(args.end(), {"--size", "64x36"});
  if (!given("--duration")) args.insert(args.end(), {"--duration", "0.2"});
  if (!given("--out")) args.insert(args.end(), {"--out", (dir / "clip.mp4").string()});
  for (const std::string& a : GetParam().args) args.push_back(in_dir(a));
  const RunResult r = run_linkage(args);
  EXPECT_EQ(r.exit_code, GetParam().exit_code) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(in_dir(GetParam().expected)), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"frames", "plain"}));
  EXPECT_TRUE(std::filesystem::is_empty(dir / "frames"));
}

INSTANTIATE_TEST_SUITE_P(
    Flags, RenderBadInput,
    ::testing::Values(
        BadInput{{"--size", "0x36"}, "--size: size 0x36 must be positive"},
        BadInput{{"--size", "-64x36"}, "--size: size -64x36 must be positive"},
        BadInput{{"--size", "65x36"}, "must have an even width and height"},
        BadInput{{"--size", "7682x4320"}, "is above the largest, 7680x4320"},
        BadInput{{"--size", "7680x4322"}, "is above the largest, 7680x4320"},
        BadInput{{"--size", "640*360"}, "--size: '640*360' is not a size WIDTHxHEIGHT"},
        BadInput{{"--quality", "ultra"}, "--quality: 'ultra' is not a quality; valid: low (854x480@30)"},
        BadInput{{"--fps", "0"}, "--fps: 0 is outside 1 .. 240"},
        BadInput{{"--fps", "241"}, "--fps: 241 is outside 1 .. 240"},
        BadInput{{"--fps", "29.97"}, "--fps: '29.97' is not a whole number"},
        BadInput{{"--duration", "0"}, "--duration: 0 s must be positive"},
        BadInput{{"--duration", "-1"}, "--duration: -1 s must be positive"},
        BadInput{{"--duration", "3601"}, "s of video; at most 3600 s (an hour)"},
        BadInput{{"--duration", "100", "--speed", "0.01"}, "makes 10000 s of video"},
        BadInput{{"--duration", "nan"}, "--duration: 'nan' is not a finite number"},
        BadInput{{"--speed", "0"}, "--speed: 0 must be a positive number"},
        BadInput{{"--duration", "0.001"}, "is less than one frame"},
        BadInput{{"--show", "arrows"}, "--show: 'arrows' is not an element; valid: blocks, pin, pin-force, gravity"},
        BadInput{{"--hide", "grid,legnd"}, "--hide: 'legnd' is not an element (did you mean 'legend'?); valid: "},
        BadInput{{"--theme", "neon"}, "--theme: 'neon' is not a theme; valid: dark, light, print"},
        BadInput{{"--camera", "orbit"}, "--camera: 'orbit' is not a camera; valid: follow, fixed, fit"},
        BadInput{{"--camera", "folow"}, "--camera: 'folow' is not a camera (did you mean 'follow'?); valid: follow"},
        BadInput{{"--quality", "hgh"}, "--quality: 'hgh' is not a quality (did you mean 'high'?); valid: low"},
        BadInput{{"--theme", "lihgt"}, "--theme: 'lihgt' is not a theme (did you mean 'light'?); valid: dark"},
        BadInput{{"--camera", "fixed"}, "--camera: fixed needs --view xmin,ymin,xmax,ymax"},
        BadInput{{"--view", "0,0,1,0"}, "--view: '0,0,1,0' has zero or negative area"},
        BadInput{{"--view", "0,0,1"}, "is not xmin,ymin,xmax,ymax"},
        BadInput{{"--camera", "fit", "--view", "0,0,1,1"}, "--view: applies only to --camera fixed"},
        BadInput{{"--arrow-scale", "same"}, "--arrow-scale: 'same' names no kind of arrow; expected common"},
        BadInput{{"--arrow-scale", "pin=0"}, "--arrow-scale: 'pin=0' has no positive number after '='"},
        BadInput{{"--arrow-scale", "weight=1"},
                 "KIND one of joint, pin, applied, gravity, spring, velocity, acceleration"},
        BadInput{{"--mechanism", "four-bar", "--arrow-scale", "weight=1"}, "KIND one of joint, pin, applied"},
        BadInput{{"--out", "{dir}/clip.avi"}, "--out: '{dir}/clip.avi' has extension '.avi'; valid: .mp4"},
        BadInput{{"--out", "{dir}/clip"}, "has no extension"},
        BadInput{{"--out", "{dir}/missing/clip.mp4"}, "--out: folder '{dir}/missing' does not exist"},
        BadInput{{"--out", "{dir}/frames"}, "is a folder, expected a file name"},
        BadInput{{"--frames", "{dir}/plain"}, "--frames: '{dir}/plain' exists and is not a folder"},
        BadInput{{"--frames", "{dir}/plain/sub"}, "--frames: '{dir}/plain' exists and is not a folder"},
        BadInput{{"--out", "{dir}/plain/clip.mp4"}, "--out: '{dir}/plain' is not a folder"},
        BadInput{{"--at", "1"}, "--at: applies to a still"},
        BadInput{{"--out", "{dir}/a.png", "--at", "-1"}, "--at: -1 s is outside 0 .. 3600 s"},
        BadInput{{"--integrator", "rk45"}, "--integrator: 'rk45' is not an integrator"},
        BadInput{{"--case", "4"}, "--case: '4' is not a case"}, BadInput{{"--m", "-1"}, "--m"},
        BadInput{{"--case", "1", "--integrator", "rk4", "--dt", "0.01", "--stabilize", "baumgarte", "--baumgarte-alpha",
                  "1e6", "--baumgarte-beta", "1e6", "--duration", "5"},
                 "the simulation failed at t = ",
                 3},
        BadInput{{"--out", "{dir}/a.png", "--case", "1", "--integrator", "rk4", "--dt", "0.01", "--stabilize",
                  "baumgarte", "--baumgarte-alpha", "1e6", "--baumgarte-beta", "1e6", "--at", "5"},
                 "the simulation failed at t = ",
                 3}));

// --ensemble, --spread and --compare (render --mechanism): the flag and the valid range.
INSTANTIATE_TEST_SUITE_P(
    Overlays, RenderBadInput,
    ::testing::Values(
        BadInput{{"--mechanism", "double-pendulum", "--ensemble", "1"},
                 "--ensemble: '1' is not a whole number of runs in 2 .. 200"},
        BadInput{{"--mechanism", "double-pendulum", "--ensemble", "201"}, "in 2 .. 200"},
        BadInput{{"--mechanism", "double-pendulum", "--ensemble", "2.5"}, "in 2 .. 200"},
        BadInput{{"--mechanism", "double-pendulum", "--ensemble", "5", "--spread", "0"},
                 "--spread: '0' is out of range; valid: 0 < spread <= 1000 (rad or m)"},
        BadInput{{"--mechanism", "double-pendulum", "--ensemble", "5", "--spread", "nan"},
                 "--spread: 'nan' is not a finite number; valid: 0 < spread <= 1000 (rad or m)"},
        BadInput{{"--mechanism", "double-pendulum", "--spread", "1e-3"}, "--spread: applies only with --ensemble"},
        BadInput{{"--ensemble", "1"}, "--ensemble: '1' is not a whole number of runs in 2 .. 200"},
        BadInput{{"--compare", "thta1=0.2"},
                 "--compare: 'thta1' (--compare thta1) is not a parameter or initial coordinate of 'two-blocks'"},
        BadInput{{"--compare", "L=-1"}, "--compare: two-blocks.toml:27:10: length of body 1 \"L\" is -1"},
        BadInput{{"--compare", "four-bar"}, "--compare four-bar: its bodies (2, 3, 4) are not two-blocks's (1, 2)"},
        BadInput{{"--compare", "{dir}/none.csv"}, "none.csv: cannot read the trajectory file"},
        BadInput{{"--mechanism", "double-pendulum", "--compare", "four-bar"},
                 "--compare four-bar: its bodies (2, 3, 4) are not double-pendulum's (1, 2)"},
        BadInput{{"--mechanism", "double-pendulum", "--compare", "2.thet=1"},
                 "--compare: '2.thet' (--compare 2.thet) is not a parameter or initial coordinate of "
                 "'double-pendulum' (did you mean '2.theta'?)"},
        BadInput{{"--mechanism", "double-pendulum", "--compare", "integrator=rk5"},
                 "--compare: integrator: 'rk5' is not an integrator (did you mean 'rk4'?); valid: "},
        BadInput{{"--mechanism", "double-pendulum", "--compare", "2.theta"},
                 "--compare: '2.theta' is not NAME=VALUE"}));

// --compare FILE.csv: the file's line and what is wrong or missing; no output.
struct BadTrajectory {
  std::vector<std::string> args;
  std::string csv;
  std::string expected;  // "{file}" stands for the CSV's path
};
class RenderBadTrajectory : public ::testing::TestWithParam<BadTrajectory> {};

TEST_P(RenderBadTrajectory, NamesTheFileAndLine) {
  TempDir dir;
  const std::filesystem::path csv = dir / "run.csv";
  write_text(csv, GetParam().csv);
  std::vector<std::string> args{"render", "--quiet",   "--size",     "64x36", "--duration",
                                "1",      "--compare", csv.string(), "--out", (dir / "clip.mp4").string()};
  args.insert(args.end(), GetParam().args.begin(), GetParam().args.end());
  const RunResult r = run_linkage(args);
  std::string expected = GetParam().expected;
  if (const auto at = expected.find("{file}"); at != std::string::npos) expected.replace(at, 6, csv.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"run.csv"}));
}

INSTANTIATE_TEST_SUITE_P(
    Files, RenderBadTrajectory,
    ::testing::Values(
        // The generalized coordinates are enough (x2, y2 follow through the pin); one is missing.
        BadTrajectory{{},
                      "t,x1,y1,theta1\n0,1,2,0.1\n1,1,2,0.1\n",
                      "{file}: no column 'theta2'; --compare, to draw the bodies of two-blocks, needs the columns t, "
                      "x1, y1, theta1, theta2, or each body's pose t, x1, y1, theta1, x2, y2, theta2 (as linkage "
                      "simulate writes them); the header has t, x1, y1, theta1"},
        // A misspelt column: the header's name it is close to.
        BadTrajectory{{},
                      "t,x1,y1,thetaa1,theta2\n0,1,2,0.1,0.2\n1,1,2,0.1,0.2\n",
                      "{file}: no column 'theta1' (the header has 'thetaa1': did you mean 'theta1'?); --compare"},
        BadTrajectory{{},
                      "t,x1,y1,theta1,theta2,x2,y2\n0,1,2,0.1,0.2,1,2\n0.5,1,2,0.1,0.2,1,2\n0.5,1,2,0.1,0.2,1,2\n1,1,2,"
                      "0.1,0.2,1,2\n",
                      "{file}:4: t = 0.5 s does not increase (the row before has t = 0.5 s)"},
        BadTrajectory{{},
                      "t,x1,y1,theta1,theta2,x2,y2\n0,1,2,0.1,0.2,1,2\n0.5,1,abc,0.1,0.2,1,2\n1,1,2,0.1,0.2,1,2\n",
                      "{file}:3: y1 = 'abc' is not a number"},
        BadTrajectory{{},
                      "t,x1,y1,theta1,theta2,x2,y2\n0,1,2,0.1,0.2,1,2\n0.5,1,2,nan,0.2,1,2\n1,1,2,0.1,0.2,1,2\n",
                      "{file}:3: theta1 is nan; every value must be a finite number"},
        BadTrajectory{{},
                      "t,x1,y1,theta1,theta2,x2,y2\n0,1,2,0.1,0.2,1,2\n0.5,1,2,0.1\n",
                      "{file}:3: 4 fields; the header has 7"},
        BadTrajectory{{},
                      "t,x1,y1,theta1,theta2,x2,y2\n0,1,2,0.1,0.2,1,2\n0.5,1,2,0.1,0.2,1,2\n",
                      "{file}:3: the last row has t = 0.5 s, before the clip's end at 1 s"},
        BadTrajectory{{},
                      "t,x1,y1,theta1,theta2,x2,y2\n0.1,1,2,0.1,0.2,1,2\n1,1,2,0.1,0.2,1,2\n",
                      "{file}:2: the first row has t = 0.1 s, after the clip's start at 0 s"},
        BadTrajectory{{"--mechanism", "double-pendulum"},
                      "t,1.x,1.y,1.theta\n0,1,2,0.1\n1,1,2,0.1\n",
                      "{file}: no column '2.theta'; --compare, to draw the bodies of double-pendulum, needs the "
                      "columns t, 1.theta, 2.theta, or each body's pose t, 1.x, 1.y, 1.theta, 2.x, 2.y, 2.theta"}));

TEST(RenderBadInputFolder, UnwritableFolderIsAnInputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes anywhere";
  TempDir dir;
  std::filesystem::create_directory(dir / "locked");
  ::chmod((dir / "locked").c_str(), 0555);
  const RunResult r = run_linkage(
      {"render", "--quiet", "--size", "64x36", "--duration", "0.2", "--out", (dir / "locked" / "clip.mp4").string()});
  ::chmod((dir / "locked").c_str(), 0755);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is not writable"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir / "locked"));
}

}  // namespace
}  // namespace linkage::test
