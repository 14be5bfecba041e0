#include <gtest/gtest.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

TEST(AtomicFile, CommitRenamesAndAbandonLeavesTheOldFile) {
  test::TempDir dir;
  const auto target = dir / "out.csv";
  test::write_text(target, "old\n");
  {
    AtomicFile file(target, "--out");
    file.stream() << "new, partial";
    EXPECT_EQ(test::read_text(target), "old\n");  // nothing visible before commit
  }
  EXPECT_EQ(test::read_text(target), "old\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.csv"});  // temporary removed
  {
    AtomicFile file(target, "--out");
    file.stream() << "new\n";
    file.commit();
  }
  EXPECT_EQ(test::read_text(target), "new\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.csv"});
}

TEST(AtomicFile, MissingFolderIsAnInputError) {
  test::TempDir dir;
  try {
    AtomicFile file(dir / "nope" / "out.csv", "--out");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_NE(std::string(e.what()).find("--out: folder"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace linkage
