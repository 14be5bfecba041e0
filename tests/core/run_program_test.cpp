// run_program starts a program from an argument vector: no shell reads the arguments;
// it runs in the given folder with /dev/null for input, its output captured or dropped,
// stopped at its timeout, and killed and reaped when this process is interrupted.
#include "core/run_program.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

TEST(RunProgram, ArgumentsReachTheProgramAsTheyAreAndNoShellReadsThem) {
  test::TempDir dir;
  ProgramRun run;
  run.argv = {"printf", "[%s]", "it's", "a; touch pwned", "$(touch pwned)", "`touch pwned`", "\"q\" > out"};
  run.directory = dir.path();
  run.capture_output = true;
  const ProgramResult result = run_program(run);
  EXPECT_TRUE(result.succeeded());
  EXPECT_EQ(result.output, "[it's][a; touch pwned][$(touch pwned)][`touch pwned`][\"q\" > out]");
  EXPECT_TRUE(dir.entries().empty());  // no pwned, no out
}

TEST(RunProgram, RunsInItsFolderWithNullInput) {
  test::TempDir dir;
  ProgramRun pwd;
  pwd.argv = {"pwd", "-P"};
  pwd.directory = dir.path();
  pwd.capture_output = true;
  EXPECT_EQ(run_program(pwd).output, std::filesystem::canonical(dir.path()).string() + "\n");
  ProgramRun cat;  // reads /dev/null: ends at once, with nothing
  cat.argv = {"cat"};
  cat.capture_output = true;
  const ProgramResult read = run_program(cat);
  EXPECT_TRUE(read.succeeded());
  EXPECT_EQ(read.output, "");
}

TEST(RunProgram, ReportsExitCodesSignalsAndTheTimeout) {
  ProgramRun fails;
  fails.argv = {"sh", "-c", "echo why >&2; exit 3"};
  fails.capture_output = true;
  const ProgramResult failed = run_program(fails);
  EXPECT_EQ(failed.exit_code, 3);
  EXPECT_EQ(failed.output, "why\n");  // standard error captured too
  EXPECT_FALSE(failed.succeeded());

  ProgramRun killed;
  killed.argv = {"sh", "-c", "kill -KILL $$"};
  const ProgramResult died = run_program(killed);
  EXPECT_EQ(died.exit_code, -1);
  EXPECT_EQ(died.signal, SIGKILL);

  ProgramRun slow;
  slow.argv = {"sleep", "30"};
  slow.timeout = std::chrono::milliseconds(200);
  const ProgramResult stopped = run_program(slow);
  EXPECT_TRUE(stopped.timed_out);
  EXPECT_FALSE(stopped.succeeded());
}

TEST(RunProgram, AProgramThatCannotStartIsAFailureNamingIt) {
  ProgramRun missing;
  missing.argv = {"no-such-program-linkage"};
  try {
    (void)run_program(missing);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::failure);
    EXPECT_NE(std::string(e.what()).find("no-such-program-linkage"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
  ProgramRun nowhere;
  nowhere.argv = {"true"};
  nowhere.directory = "/nonexistent/folder";
  EXPECT_THROW((void)run_program(nowhere), Error);
}

// In a child process (the interrupt flag, once set, stays set): the program sends this
// process SIGTERM and sleeps; run_program must kill and reap it and throw the interruption.
TEST(RunProgramDeathTest, AnInterruptKillsAndReapsTheProgram) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  test::TempDir dir;
  const auto interrupted = [&] {
    install_interrupt_handler();
    ProgramRun run;
    run.argv = {"sh", "-c", "echo $$ > pid; kill -TERM $PPID; exec sleep 30"};
    run.directory = dir.path();
    int status = 1;
    try {
      (void)run_program(run);
    } catch (const Error& e) {
      const pid_t child = std::stoi(test::read_text(dir / "pid"));
      // Reaped: no such process (a zombie would still answer kill(pid, 0)).
      if (e.exit_status() == 128 + SIGTERM && ::kill(child, 0) != 0 && errno == ESRCH) status = 0;
    }
    std::_Exit(status);
  };
  EXPECT_EXIT(interrupted(), ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace linkage
