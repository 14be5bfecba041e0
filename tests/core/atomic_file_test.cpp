#include "core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <thread>

#include "core/error.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {
namespace fs = std::filesystem;

TEST(AtomicFile, CommitRenamesAndAbandonLeavesTheOldFile) {
  test::TempDir dir;
  const auto target = dir / "out.csv";
  test::write_text(target, "old\n");
  {
    AtomicFile file(target, "out");
    file.stream() << "new, partial";
    EXPECT_EQ(test::read_text(target), "old\n");  // nothing visible before commit
  }
  EXPECT_EQ(test::read_text(target), "old\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.csv"});  // temporary removed
  {
    AtomicFile file(target, "out");
    file.stream() << "new\n";
    file.commit();
  }
  EXPECT_EQ(test::read_text(target), "new\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.csv"});
}

TEST(AtomicFile, MissingFolderIsAnErrorAboutTheSetting) {
  test::TempDir dir;
  try {
    AtomicFile file(dir / "nope" / "out.csv", "out");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_EQ(e.setting(), "out");
    EXPECT_NE(e.detail().find("folder"), std::string::npos) << e.what();
    EXPECT_NE(e.detail().find("does not exist"), std::string::npos) << e.what();
  }
}

// A symlink stays a symlink: the file it points to is replaced.
TEST(AtomicFile, SymlinkKeepsPointingAtTheReplacedFile) {
  test::TempDir dir;
  fs::create_directory(dir / "real");
  test::write_text(dir / "real" / "data.csv", "old\n");
  fs::create_symlink(dir / "real" / "data.csv", dir / "link.csv");
  AtomicFile file(dir / "link.csv", "out");
  file.stream() << "new\n";
  file.commit();
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
  EXPECT_EQ(test::read_text(dir / "real" / "data.csv"), "new\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.csv", "real"}));
}

// A FIFO is written directly, never replaced by a regular file.
TEST(AtomicFile, FifoIsWrittenDirectly) {
  test::TempDir dir;
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo);
    received.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  });
  {
    AtomicFile file(fifo, "out");
    EXPECT_EQ(file.kind(), AtomicFile::Kind::direct);
    file.stream() << "through the pipe\n";
    file.commit();
  }
  reader.join();
  EXPECT_EQ(received, "through the pipe\n");
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"pipe"});
}

TEST(AtomicFile, DashIsStandardOutput) {
  AtomicFile file("-", "out");
  EXPECT_EQ(file.kind(), AtomicFile::Kind::standard_output);
  EXPECT_EQ(&file.stream(), &std::cout);
}

TEST(AtomicFile, KilledRunsTemporariesAreRemovedLiveOnesKept) {
  test::TempDir dir;
  // A PID that is not running: fork a child that exits at once and reap it.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  int status = 0;
  ::waitpid(child, &status, 0);
  const std::string dead = "out.csv.tmp-" + std::to_string(child) + "-3.csv";
  const std::string live = "out.csv.tmp-" + std::to_string(::getppid()) + "-0.csv";
  const std::string other = "other.csv.tmp-" + std::to_string(child) + "-0.csv";
  for (const std::string& name : {dead, live, other}) test::write_text(dir / name, "x");
  write_file_atomically(dir / "out.csv", "new\n", "out");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{other, "out.csv", live}));
}

TEST(EnsureDirectory, MakesParentsAndRefusesAFileInTheWay) {
  test::TempDir dir;
  ensure_directory(dir / "a" / "b" / "c", "frames");
  EXPECT_TRUE(fs::is_directory(dir / "a" / "b" / "c"));
  ensure_directory(dir / "a" / "b" / "c", "frames");  // exists: fine
  test::write_text(dir / "file", "x");
  try {
    ensure_directory(dir / "file" / "sub", "frames");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.setting(), "frames");
    EXPECT_NE(e.detail().find("is not a folder"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace linkage
