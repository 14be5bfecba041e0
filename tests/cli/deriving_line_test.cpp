// "A progress line when the derivation takes over a second" (issue 22, Deliver 2), for
// every command that derives: on a terminal, "linkage: deriving the equations: 1 s" once
// the derivation of a 100-link chain has lasted a second, erased when the run ends; off a
// terminal, nothing. Each run is ended by a signal once the line shows (or after 1.5 s).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <string>
#include <vector>

#include "support/long_chain.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

constexpr const char* kLine = "\r\033[Klinkage: deriving the equations: 1 s";

RunResult derive_then_signal(const std::vector<std::string>& args, bool terminal) {
  RunOptions options;
  options.args = args;
  options.stderr_terminal = terminal;
  options.signal = SIGTERM;
  options.timeout_seconds = 120;
  const auto start = std::chrono::steady_clock::now();
  options.ready = [&](const std::string&, const std::string& err) {
    return terminal ? err.find(kLine) != std::string::npos
                    : std::chrono::steady_clock::now() - start > std::chrono::milliseconds(1500);
  };
  return run_linkage(options);
}

class DerivingLine : public ::testing::TestWithParam<const char*> {};

std::vector<std::string> command_args(const std::string& command, const TempDir& dir) {
  const std::string chain = write_chain(dir.path(), 100);
  if (command == "lesson") {
    test::write_text(dir / "l.toml",
                     "title = \"Chain\"\nmechanism = \"chain100.toml\"\n[[step]]\nkind = \"say\"\ntext = \"hi\"\n");
    return {"lesson", (dir / "l.toml").string(), "--out", (dir / "out").string()};
  }
  if (command == "render") return {"render", "--mechanism", chain, "--out", (dir / "a.png").string()};
  if (command == "simulate") return {"simulate", "--mechanism", chain, "--out", (dir / "a.csv").string()};
  return {"solve", "--mechanism", chain};
}

TEST_P(DerivingLine, ShowsOnATerminalAndIsErased) {
  const TempDir dir;
  const RunResult r = derive_then_signal(command_args(GetParam(), dir), true);
  ASSERT_TRUE(r.signal_sent) << r.err;
  EXPECT_EQ(r.exit_code, 128 + SIGTERM) << r.err;
  // The line, then erased before the error (a terminal writes \n as \r\n).
  const std::size_t line = r.err.find(kLine);
  ASSERT_NE(line, std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\r\033[Klinkage: error: interrupted by SIGTERM\r\n", line), std::string::npos) << r.err;
}

TEST_P(DerivingLine, IsQuietOffATerminal) {
  const TempDir dir;
  const RunResult r = derive_then_signal(command_args(GetParam(), dir), false);
  ASSERT_TRUE(r.signal_sent) << r.err;
  EXPECT_EQ(r.exit_code, 128 + SIGTERM) << r.err;
  EXPECT_EQ(r.err, "linkage: error: interrupted by SIGTERM\n");
}

INSTANTIATE_TEST_SUITE_P(Commands, DerivingLine, ::testing::Values("solve", "simulate", "render", "lesson"),
                         [](const ::testing::TestParamInfo<const char*>& command) {
                           return std::string(command.param);
                         });

}  // namespace
}  // namespace linkage::test
