// `linkage bench render --quick`: the report is produced for the homework's clip and the
// four-bar's, both drawn through the one path, and its numbers hang together (not the
// timings themselves); the frame store gives back the frames it was given; bad
// flags are one-line errors, exit 2.
#include "bench/render_bench.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <random>
#include <thread>

#include "bench/frame_store.hpp"
#include "bench/tests/csv_reader.hpp"
#include "core/error.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

using test::read_csv;
using test::run_linkage;
using test::TempDir;

double number(const std::map<std::string, std::string>& row, const std::string& column) {
  const std::string& text = row.at(column);
  EXPECT_FALSE(text.empty()) << column;
  return text.empty() ? std::nan("") : std::stod(text);
}

void expect_positive(const std::map<std::string, std::string>& row, const std::string& column) {
  const double v = number(row, column);
  EXPECT_TRUE(std::isfinite(v) && v > 0) << row.at("format") << " " << row.at("width") << ": " << column << " = " << v;
}

TEST(BenchRender, QuickRunWritesASaneReportAndCleansUp) {
  TempDir dir;
  const auto out = dir / "render";
  // Not --quiet: stderr is not a terminal here, so it must stay empty all the same.
  const test::RunResult r = run_linkage({"bench", "render", "--quick", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  std::vector<std::string> entries;
  for (const auto& e : std::filesystem::directory_iterator(out)) entries.push_back(e.path().filename().string());
  std::sort(entries.begin(), entries.end());
  EXPECT_EQ(entries, (std::vector<std::string>{"render.csv", "render.md"}));  // no scratch files left

  const auto rows = read_csv(out / "render.csv");
  ASSERT_EQ(rows.size(), 8u);
  std::vector<std::string> kinds;
  for (const auto& row : rows)
    kinds.push_back(row.at("format") + " " + row.at("clip") + " " + row.at("width") + "x" + row.at("height"));
  EXPECT_EQ(kinds, (std::vector<std::string>{"mp4 two-blocks 320x180", "mp4 four-bar 320x180", "mp4 two-blocks 640x360",
                                             "mp4 four-bar 640x360", "png two-blocks 320x180", "png four-bar 320x180",
                                             "png two-blocks 640x360", "png four-bar 640x360"}));
  for (const auto& row : rows) {
    const bool mp4 = row.at("format") == "mp4";
    EXPECT_EQ(row.at("frames"), mp4 ? "60" : "10");  // 2 s at 30 fps; 10 of those frames as PNG
    for (const char* column :
         {"wall_s", "frames_per_s", "convert_s", "encode_s", "baseline_wall_s", "baseline_frames_per_s", "ratio",
          "unpack_s", "bytes_per_frame", "baseline_bytes_per_frame"})
      expect_positive(row, column);
    const double frames = number(row, "frames"), wall = number(row, "wall_s"), base = number(row, "baseline_wall_s");
    EXPECT_NEAR(number(row, "frames_per_s"), frames / wall, 1e-9 * frames / wall);
    EXPECT_NEAR(number(row, "baseline_frames_per_s"), frames / base, 1e-9 * frames / base);
    // MP4: pipeline time over encoding alone; PNG: our frame rate over Cairo's.
    const double ratio = mp4 ? wall / base : base / wall;
    EXPECT_NEAR(number(row, "ratio"), ratio, 1e-9 * ratio);
    if (mp4) {
      for (const char* column : {"simulate_s", "draw_s", "cpu_s", "baseline_cpu_s", "cpu_ratio", "stored_bytes"})
        expect_positive(row, column);
      const double cpu_ratio = number(row, "cpu_s") / number(row, "baseline_cpu_s");
      EXPECT_NEAR(number(row, "cpu_ratio"), cpu_ratio, 1e-9 * cpu_ratio);
      // Frames kept run-length coded take far less than raw (4 bytes a pixel).
      EXPECT_LT(number(row, "stored_bytes"), 0.5 * frames * 4 * number(row, "width") * number(row, "height"));
      EXPECT_EQ(row.at("baseline"), "encode alone");
      EXPECT_EQ(row.at("same_output"), "yes");  // the encoder got the very frames the pipeline drew
    } else {
      EXPECT_EQ(row.at("baseline"), "cairo");
    }
  }
  // The report's structure, never its speed: times are only checked to be there and
  // consistent with the ratios computed from them. A bigger frame of the same clip makes
  // bigger files, and the two clips' files differ (sizes are deterministic).
  for (const std::size_t first : {0u, 1u, 4u, 5u})
    EXPECT_GT(number(rows[first + 2], "bytes_per_frame"), number(rows[first], "bytes_per_frame")) << first;
  EXPECT_NE(number(rows[0], "bytes_per_frame"), number(rows[1], "bytes_per_frame"));
  EXPECT_EQ(test::read_text(out / "render.csv").find("nan"), std::string::npos);

  const std::string md = test::read_text(out / "render.md");
  for (const char* text : {"## Targets", "## MP4", "## PNG sequence", "| two-blocks | 640x360 | 60 |",
                           "| four-bar | 640x360 | 60 |", "not measured (--quick)", "linkage bench render --out"})
    EXPECT_NE(md.find(text), std::string::npos) << text;
  for (const char* text :
       {"MP4 two-blocks 320x180: 60 frames", "MP4 four-bar 320x180: 60 frames", "PNG four-bar 640x360: ours",
        "target: MP4 two-blocks 1280x720", "target: MP4 four-bar 1280x720", "wrote "})
    EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
}

TEST(BenchRender, BadFlagsAreOneLineErrors) {
  TempDir dir;
  test::write_text(dir / "file", "x");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--size", "640x360", "--out", (dir / "o").string()}, "--size"},
      {{"--out", (dir / "file").string()}, "exists and is not a folder"},
      {{"--out", (dir / "file" / "sub").string()}, "exists and is not a folder"},
      {{"--out"}, "--out"},
  };
  for (const auto& [args, message] : cases) {
    std::vector<std::string> argv{"bench", "render", "--quick"};
    argv.insert(argv.end(), args.begin(), args.end());
    const test::RunResult r = run_linkage(argv);
    EXPECT_EQ(r.exit_code, 2) << args[0];
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.out, "") << args[0];
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "o"));  // a bad flag makes no folder
}

TEST(BenchRender, CtrlCIsExit130AndLeavesNothingBehind) {
  TempDir dir;
  const auto out = dir / "o";
  std::filesystem::create_directory(out);
  test::write_text(out / "render.md", "an earlier report");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::execl(LINKAGE_BINARY, LINKAGE_BINARY, "bench", "render", "--quiet", "--out", out.c_str(), nullptr);
    ::_exit(127);
  }
  // Interrupted once the first MP4 is being written into the scratch folder.
  bool writing = false;
  for (int i = 0; i < 6000 && !writing; ++i) {
    std::error_code ec;  // the scratch folder may vanish while it is listed
    for (std::filesystem::recursive_directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
      if (it->path().filename().string().find(".mp4") != std::string::npos) writing = true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(writing) << "the benchmark never started an MP4";
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::vector<std::string> entries;
  for (const auto& e : std::filesystem::directory_iterator(out)) entries.push_back(e.path().filename().string());
  EXPECT_EQ(entries, std::vector<std::string>{"render.md"});
  EXPECT_EQ(test::read_text(out / "render.md"), "an earlier report");
}

TEST(BenchRender, BusyMachineJudgesTheMp4TargetByCpuTime) {
  bench::MovieRow row;
  row.wall_seconds = 14, row.alone_wall_seconds = 10;  // wall ratio 1.4
  row.cpu_seconds = 11, row.alone_cpu_seconds = 10;    // CPU ratio 1.1
  bench::RenderBenchResult result;
  result.cores = 2;
  result.load_average = 0.5, result.load_average_end = 1.9;
  EXPECT_FALSE(result.busy());
  EXPECT_DOUBLE_EQ(bench::judged_ratio(row, result), 1.4);
  result.load_average_end = 2.5;  // busy by the end
  EXPECT_TRUE(result.busy());
  EXPECT_DOUBLE_EQ(bench::judged_ratio(row, result), 1.1);
}

TEST(FrameStore, GivesBackEveryFrameByteForByte) {
  std::mt19937 random(7);
  bench::FrameStore store(37, 11);
  std::vector<Frame> frames;
  for (int f = 0; f < 4; ++f) {
    Frame frame(37, 11);
    // Runs of one colour broken by noise, and a frame of pure noise.
    for (std::size_t i = 0; i < frame.pixels.size(); ++i)
      frame.pixels[i] =
          static_cast<std::uint8_t>(f == 3 || random() % 50 == 0 ? random() : 17U * static_cast<unsigned>(f));
    store.add(frame);
    frames.push_back(frame);
  }
  ASSERT_EQ(store.size(), 4u);
  bench::FrameStore flat(37, 11);
  flat.add(frames[0]);
  EXPECT_LT(flat.bytes(), frames[0].pixels.size() / 2);  // mostly flat frames code small
  Frame out(37, 11);
  for (std::size_t k : {2u, 0u, 3u, 1u}) {
    store.unpack(k, out);
    EXPECT_EQ(out.pixels, frames[k].pixels) << k;
  }
  Frame wrong(36, 11);
  EXPECT_THROW(store.unpack(0, wrong), Error);
  EXPECT_THROW(store.add(wrong), Error);
  EXPECT_THROW(store.unpack(4, out), Error);
}

}  // namespace
}  // namespace linkage
