// Outputs of `linkage render` appear whole or not at all: a failed run or Ctrl-C leaves
// no partial file and keeps an earlier file of the same name as it was.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "support/test_support.hpp"

extern char** environ;

namespace linkage::test {
namespace {

TEST(RenderSafety, FailedRunKeepsTheEarlierFile) {
  TempDir dir;
  write_text(dir / "clip.mp4", "an earlier clip");
  // The simulation diverges after the output was checked: exit 3, nothing replaced.
  const RunResult r = run_linkage({"render",
                                   "--quiet",
                                   "--size",
                                   "64x36",
                                   "--out",
                                   (dir / "clip.mp4").string(),
                                   "--case",
                                   "1",
                                   "--integrator",
                                   "rk4",
                                   "--dt",
                                   "0.01",
                                   "--stabilize",
                                   "baumgarte",
                                   "--baumgarte-alpha",
                                   "1e6",
                                   "--baumgarte-beta",
                                   "1e6",
                                   "--duration",
                                   "5"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.mp4"});
  EXPECT_EQ(read_text(dir / "clip.mp4"), "an earlier clip");
}

// Starts `linkage args...` with its output discarded; returns its process id.
pid_t start(const std::vector<std::string>& args) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  std::vector<std::string> storage{LINKAGE_BINARY};
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, LINKAGE_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " LINKAGE_BINARY);
  return pid;
}

// Waits until something besides `keep` appears in `folder` (the run's temporary output).
bool wait_for_work(const TempDir& dir, std::size_t entries_before) {
  for (int i = 0; i < 3000; ++i) {
    if (dir.entries().size() > entries_before) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

// SIGINT (Ctrl-C), SIGTERM (timeout, a job runner, container stop) and SIGHUP (a closed
// terminal) all end a render the same way: exit 128 + signal, no temporary left, the
// earlier file kept.
class RenderSignal : public ::testing::TestWithParam<int> {};

TEST_P(RenderSignal, IsExit128PlusSignalAndLeavesNoPartialFile) {
  const int signal = GetParam();
  TempDir dir;
  write_text(dir / "clip.mp4", "an earlier clip");
  std::filesystem::create_directory(dir / "frames");
  // A long clip, interrupted as soon as its temporary file exists.
  const pid_t pid = start({"render", "--quiet", "--size", "320x180", "--duration", "600", "--out",
                           (dir / "clip.mp4").string(), "--frames", (dir / "frames").string()});
  ASSERT_TRUE(wait_for_work(dir, 2)) << "the render never started writing";
  ::kill(pid, signal);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"clip.mp4", "frames"}));
  EXPECT_EQ(read_text(dir / "clip.mp4"), "an earlier clip");
  EXPECT_TRUE(std::filesystem::is_empty(dir / "frames"));
}

INSTANTIATE_TEST_SUITE_P(
    Signals, RenderSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP), [](const ::testing::TestParamInfo<int>& param) {
      return std::string(param.param == SIGINT ? "SIGINT" : param.param == SIGTERM ? "SIGTERM" : "SIGHUP");
    });

// SIGKILL cannot be handled: the temporary stays, and the next run that writes the same
// target removes it (its process is gone).
TEST(RenderSafety, NextRunRemovesWhatAKilledRunLeft) {
  TempDir dir;
  const pid_t pid =
      start({"render", "--quiet", "--size", "320x180", "--duration", "600", "--out", (dir / "clip.mp4").string()});
  ASSERT_TRUE(wait_for_work(dir, 0)) << "the render never started writing";
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_EQ(dir.entries().size(), 1u);
  EXPECT_NE(dir.entries().front().find("clip.mp4.tmp-" + std::to_string(pid) + "-"), std::string::npos);
  // Another file's temporary of a live process (this test) is left alone.
  const std::string live = "clip.mp4.tmp-" + std::to_string(::getpid()) + "-0.mp4";
  write_text(dir / live, "in progress");

  const RunResult r =
      run_linkage({"render", "--quiet", "--size", "64x36", "--duration", "0.2", "--out", (dir / "clip.mp4").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"clip.mp4", live}));
}

}  // namespace
}  // namespace linkage::test
