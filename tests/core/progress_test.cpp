// Progress off a terminal: silent, or when asked plain lines at an interval, only once the
// work has lasted that long, with a clock the test controls; on a terminal, one line redrawn in place.
#include "core/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>

namespace linkage {
namespace {

using Clock = ProgressOutput::Clock;
using std::chrono::milliseconds;

/// A temporary file as the sink, and a clock moved by hand.
struct Harness {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file{std::tmpfile(), &std::fclose};
  Clock::time_point now = Clock::time_point{} + std::chrono::hours(1);

  ProgressOutput output(bool terminal, double interval_seconds) {
    ProgressOutput o;
    o.sink = file.get();
    o.terminal = terminal;
    o.plain = !terminal;
    o.interval = std::chrono::duration<double>(interval_seconds);
    o.now = [this] { return now; };
    return o;
  }

  /// Everything written so far.
  std::string text() {
    std::fflush(file.get());
    std::rewind(file.get());
    std::string out;
    for (int c = std::fgetc(file.get()); c != EOF; c = std::fgetc(file.get())) out += static_cast<char>(c);
    return out;
  }
};

TEST(Progress, PlainLinesOnlyAfterTheIntervalAndThenEveryInterval) {
  Harness h;
  Progress progress("simulate", 1e6, "s simulated", h.output(false, 5.0));
  h.now += milliseconds(4900);
  progress.update(2e5);
  EXPECT_EQ(h.text(), "") << "work shorter than the interval stays silent";
  h.now += milliseconds(200);  // 5.1 s
  progress.update(4.1e5);
  EXPECT_EQ(h.text(), "linkage: simulate: 41% (410000 of 1e+06 s simulated), 5 s so far\n");
  h.now += milliseconds(4000);  // 9.1 s: within the next interval
  progress.update(6e5);
  EXPECT_EQ(h.text(), "linkage: simulate: 41% (410000 of 1e+06 s simulated), 5 s so far\n");
  h.now += milliseconds(1500);  // 10.6 s
  progress.update(7.25e5);
  EXPECT_EQ(h.text(),
            "linkage: simulate: 41% (410000 of 1e+06 s simulated), 5 s so far\n"
            "linkage: simulate: 72% (725000 of 1e+06 s simulated), 11 s so far\n");
  progress.finish();
  h.now += milliseconds(10000);
  progress.update(1e6);
  const std::string text = h.text();
  EXPECT_EQ(text.find('\r'), std::string::npos) << "no carriage returns off a terminal";
  EXPECT_EQ(text.find("\033"), std::string::npos) << "no escape sequences off a terminal";
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << "nothing after finish(): " << text;
}

TEST(Progress, OffATerminalSilentUnlessPlainLinesAreAskedFor) {
  Harness h;
  ProgressOutput output = h.output(false, 5.0);
  output.plain = false;
  Progress progress("render", 300L, "frames", output);
  for (int k = 1; k <= 30; ++k) {
    h.now += milliseconds(1000);
    progress.update(10L * k);
  }
  progress.finish();
  EXPECT_EQ(h.text(), "") << "30 s of work off a terminal, nothing asked for";
}

TEST(Progress, CountsAreWholeNumbers) {
  Harness h;
  Progress progress("render", 300.0, "frames", h.output(false, 0.5));
  h.now += milliseconds(600);
  progress.update(123.0);
  EXPECT_EQ(h.text(), "linkage: render: 41% (123 of 300 frames), 1 s so far\n");
}

TEST(Progress, OnATerminalOneLineIsRedrawnAndErased) {
  Harness h;
  Progress progress("render", 300.0, "frames", h.output(true, 5.0));
  h.now += milliseconds(10);
  progress.update(1.0);  // shows at once
  h.now += milliseconds(50);
  progress.update(2.0);  // within a tenth of a second of the last draw: skipped
  h.now += milliseconds(100);
  progress.update(3.0);
  progress.finish();
  const std::string text = h.text();
  EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  EXPECT_NE(text.find("\r\033[Krender: 1/300 frames"), std::string::npos) << text;
  EXPECT_EQ(text.find("2/300"), std::string::npos) << text;
  EXPECT_NE(text.find("\r\033[Krender: 3/300 frames"), std::string::npos) << text;
  EXPECT_EQ(text.substr(text.size() - 4), "\r\033[K") << "erased when done";
}

TEST(Progress, QuietShowsNothing) {
  ::setenv("LINKAGE_PROGRESS_INTERVAL", "0.000001", 1);
  {
    Progress progress("simulate", 10.0, "s simulated", true);
    EXPECT_FALSE(progress.visible());
    progress.update(5.0);  // would print to the real stderr if it were not quiet
  }
  ::unsetenv("LINKAGE_PROGRESS_INTERVAL");
}

TEST(Progress, IntervalFromTheEnvironment) {
  ::setenv("LINKAGE_PROGRESS_INTERVAL", "0.25", 1);
  EXPECT_DOUBLE_EQ(ProgressOutput::from_environment().interval.count(), 0.25);
  EXPECT_TRUE(ProgressOutput::from_environment().plain);
  for (const char* bad : {"", "0", "-1", "fast", "1e400", "2 s"}) {
    ::setenv("LINKAGE_PROGRESS_INTERVAL", bad, 1);
    EXPECT_DOUBLE_EQ(ProgressOutput::from_environment().interval.count(), 5.0) << "'" << bad << "'";
    EXPECT_FALSE(ProgressOutput::from_environment().plain) << "'" << bad << "'";
  }
  ::unsetenv("LINKAGE_PROGRESS_INTERVAL");
  EXPECT_DOUBLE_EQ(ProgressOutput::from_environment().interval.count(), 5.0);
  EXPECT_FALSE(ProgressOutput::from_environment().plain) << "off a terminal, silent unless asked";
}

TEST(ElapsedLine, ShowsOnATerminalOnlyOnceTheStepLastsTheDelayAndErasesItself) {
  Harness quick, slow, plain;
  { ElapsedLine line("deriving", false, quick.output(true, 5.0), std::chrono::milliseconds(500)); }
  EXPECT_EQ(quick.text(), "") << "a step shorter than the delay shows nothing";
  {
    ElapsedLine line("deriving", false, slow.output(true, 5.0), std::chrono::milliseconds(20));
    std::this_thread::sleep_for(milliseconds(200));
  }
  EXPECT_EQ(slow.text(), "\r\033[Kderiving: 0 s\r\033[K");
  {
    ElapsedLine line("deriving", false, plain.output(false, 5.0), std::chrono::milliseconds(20));
    std::this_thread::sleep_for(milliseconds(100));
  }
  EXPECT_EQ(plain.text(), "") << "off a terminal";
}

}  // namespace
}  // namespace linkage
