// on_path finds executables in $PATH's folders and nothing else.
#include "core/program_path.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <string>

#include "support/test_support.hpp"

namespace linkage {
namespace {

TEST(ProgramPath, FindsExecutablesOnlyInPathFolders) {
  test::TempDir dir;
  test::write_text(dir / "tool", "#!/bin/sh\n");
  test::write_text(dir / "plain", "not a program\n");
  ASSERT_EQ(::chmod((dir / "tool").c_str(), 0755), 0);
  const char* saved = std::getenv("PATH");
  const std::string old = saved != nullptr ? saved : "";
  ::setenv("PATH", ("/nonexistent::" + dir.path().string()).c_str(), 1);
  EXPECT_TRUE(on_path("tool"));
  EXPECT_FALSE(on_path("plain"));  // there, but not executable
  EXPECT_FALSE(on_path("no-such-program"));
  ::setenv("PATH", "", 1);
  EXPECT_FALSE(on_path("tool"));
  ::setenv("PATH", old.c_str(), 1);
}

}  // namespace
}  // namespace linkage
