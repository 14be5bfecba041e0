// A signal at any moment of a long chain's run ends it within a second (issue 22, Deliver
// 2 and Done when: "SIGTERM at any moment ends a run within a second with no leftover"),
// for every command that derives: simulate, solve (the derivation of its printed forms
// too), render (its derivation, sampling, drawing and encoding) and lesson (reading it
// derives; a solve step prints). Each run is measured once unsignalled; the moments are
// fractions of that time, so that they fall at the same stages on any machine (late ones
// only where the last stage is long: a loaded machine's runs vary by a quarter), or the
// moments progress lines mark. A run
// that takes more than the second counts as a failure: the bound is the test's,
// with no second try.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "support/long_chain.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

struct Moment {
  double fraction;  // of the unsignalled run's time; or, when `after` is set, once stderr holds it
  int signal;
  std::string after;
};

/// Every entry of `dir`, recursively, relative to it ("out/run.csv").
std::vector<std::string> all_entries(const TempDir& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir.path()))
    names.push_back(std::filesystem::relative(entry.path(), dir.path()).string());
  std::sort(names.begin(), names.end());
  return names;
}

/// What a signalled run may leave besides `kept` (`dir`'s entries, recursively): `folder`,
/// if the run made it, empty; stdout and outputs only as the unsignalled run made them
/// whole, when the signal came as the run was ending (freeing a long chain's expressions
/// takes a while after its output is whole; it still ends with 128 + the signal), and
/// stdout cut short (a signal while the text is written); unless the command prints as it
/// goes (a lesson).
struct Leftover {
  std::vector<std::string> kept;
  std::string folder;
  bool prints_as_it_goes = false;
};

/// Runs `args` once unsignalled (it must succeed) to time it and keep what it made, then
/// removes that; then once per moment, the signal sent at that fraction of the time: each
/// run must end with 128 + the signal within a second of it and leave only what
/// `expected` allows.
void expect_each_signal_ends_the_run_within_a_second(const std::vector<std::string>& args, const TempDir& dir,
                                                     const Leftover& expected, const std::vector<Moment>& moments) {
  const std::vector<std::string>& kept = expected.kept;
  const auto begun = std::chrono::steady_clock::now();
  const RunResult whole = run_linkage(args);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  double run = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
  std::map<std::string, std::string> made;  // the whole run's output files
  for (const std::string& name : dir.entries())
    if (std::find(kept.begin(), kept.end(), name) == kept.end() && std::filesystem::is_regular_file(dir / name))
      made[name] = read_text(dir / name);
  auto clean = [&] {
    for (const std::string& name : dir.entries())
      if (std::find(kept.begin(), kept.end(), name) == kept.end()) std::filesystem::remove_all(dir / name);
  };
  clean();
  const auto moment_text = [&run](const Moment& m) {
    return "signal " + std::to_string(m.signal) + " at " +
           (m.after.empty() ? std::to_string(m.fraction) + " of " + std::to_string(run) + " s"
                            : "'" + m.after + "' on stderr");
  };
  for (const Moment& m : moments) {
    RunResult r;
    // A loaded machine's runs vary by half: a run that ends before its moment re-aims the
    // moment at its own time, once (no signal was measured, so nothing is repeated).
    for (int aim = 0; aim < 2; ++aim) {
      SCOPED_TRACE(moment_text(m));
      RunOptions options;
      options.args = args;
      options.signal = m.signal;
      options.timeout_seconds = 10 * run + 30;
      const auto start = std::chrono::steady_clock::now();
      options.ready = [&](const std::string&, const std::string& err) {
        if (!m.after.empty()) return err.find(m.after) != std::string::npos;
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > m.fraction * run;
      };
      r = run_linkage(options);
      if (!r.signal_sent && aim == 0 && m.after.empty() && r.exit_code == 0) {
        run = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        clean();
        continue;
      }
      ASSERT_TRUE(r.signal_sent) << "it ended before the signal: " << r.err;
      break;
    }
    SCOPED_TRACE(moment_text(m));
    EXPECT_FALSE(r.timed_out);
    EXPECT_EQ(r.exit_code, 128 + m.signal) << r.err;
    EXPECT_LT(r.seconds_after_signal, 1.0);
    if (!expected.prints_as_it_goes) {
      EXPECT_TRUE(whole.out.compare(0, r.out.size(), r.out) == 0 && r.out.size() <= whole.out.size())
          << r.out.size() << " bytes on stdout, not the start of the whole run's";
    }
    std::vector<std::string> left = all_entries(dir);
    if (!expected.folder.empty()) std::erase(left, expected.folder);
    std::erase_if(left, [&](const std::string& name) {
      const auto it = made.find(name);
      return it != made.end() && read_text(dir / name) == it->second;
    });
    EXPECT_EQ(left, kept);
    clean();
  }
}

TEST(LongChain, ASignalAtAnyMomentOfTheDerivationEndsTheRunWithinASecond) {
  const TempDir dir;
  const std::string chain = write_chain(dir.path(), 100);
  expect_each_signal_ends_the_run_within_a_second(
      {"simulate", "--mechanism", chain, "--duration", "1", "--out", (dir / "run.csv").string()}, dir,
      {{"chain100.toml"}, "", false},
      {{0.05, SIGTERM, ""},
       {0.3, SIGINT, ""},
       {0.5, SIGTERM, ""},
       {0.55, SIGTERM, ""},
       {0.65, SIGTERM, ""},
       {0.85, SIGTERM, ""}});
}

// solve derives Case 3, solves it, and prints its symbolic matrices (a few MB of text for
// 100 links, printed term by term after about half the run); nothing reaches stdout
// before the whole text is made.
TEST(LongChain, ASignalAtAnyMomentOfSolveEndsItWithinASecond) {
  const TempDir dir;
  const std::string chain = write_chain(dir.path(), 100);
  expect_each_signal_ends_the_run_within_a_second({"solve", "--mechanism", chain, "--case", "3"}, dir,
                                                  {{"chain100.toml"}, "", false},
                                                  {{0.1, SIGTERM, ""},
                                                   {0.3, SIGINT, ""},
                                                   {0.5, SIGTERM, ""},
                                                   {0.6, SIGTERM, ""},
                                                   {0.7, SIGTERM, ""},
                                                   {0.8, SIGINT, ""}});
}

// render derives, compiles the sample (the first half), then draws and encodes the frames:
// moments in time, then once the drawing has begun, half-way, and once the last frame is
// drawn, while the encoder drains the frames it delayed (a signal there was ignored: exit 0
// and a whole video). Progress lines off a terminal (LINKAGE_PROGRESS_INTERVAL) say when.
// The video appears whole or not at all.
TEST(LongChain, ASignalAtAnyMomentOfRenderEndsItWithinASecond) {
  const TempDir dir;
  const std::string chain = write_chain(dir.path(), 100);
  ::setenv("LINKAGE_PROGRESS_INTERVAL", "0.01", 1);
  expect_each_signal_ends_the_run_within_a_second(
      {"render", "--mechanism", chain, "--duration", "1", "--size", "640x360", "--out", (dir / "run.mp4").string()},
      dir, {{"chain100.toml"}, "", false},
      {{0.1, SIGTERM, ""},
       {0.3, SIGINT, ""},
       {0.5, SIGTERM, ""},
       {0.7, SIGTERM, ""},
       {0, SIGTERM, "linkage: render: "},
       {0, SIGTERM, "(15 of 30 frames)"},
       {0, SIGTERM, "(30 of 30 frames)"}});
  ::unsetenv("LINKAGE_PROGRESS_INTERVAL");
}

// Reading the lesson derives its mechanism (the first quarter); the solve step derives
// and prints Case 3 (to about 0.65); the simulate step compiles the run. The output folder may stay (empty: no step had
// written an artifact), but no document and no temporary.
TEST(LongChain, ASignalAtAnyMomentOfALessonEndsItWithinASecond) {
  const TempDir dir;
  write_chain(dir.path(), 100);
  std::ofstream(dir / "l.toml")
      << "title = \"Chain\"\nmechanism = \"chain100.toml\"\n\n[[step]]\nkind = "
         "\"solve\"\ncase = 3\nshow = [\"numeric\", \"solution\"]\n\n[[step]]\nkind = \"simulate\"\nduration = 1\n";
  expect_each_signal_ends_the_run_within_a_second(
      {"lesson", (dir / "l.toml").string(), "--out", (dir / "out").string()}, dir,
      {{"chain100.toml", "l.toml"}, "out", true},
      {{0.1, SIGTERM, ""}, {0.4, SIGINT, ""}, {0.55, SIGTERM, ""}, {0.7, SIGTERM, ""}});
}

}  // namespace
}  // namespace linkage::test
