#include "core/input_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

TEST(InputFile, ReadsWholeFilesByteForByte) {
  test::TempDir dir;
  const std::string text = std::string("first line\r\nsecond\0with a zero\n", 31) + std::string(70000, 'x');
  test::write_text(dir / "text.md", text);
  EXPECT_EQ(read_file_text(dir / "text.md"), text);
  test::write_text(dir / "empty.md", "");
  EXPECT_EQ(read_file_text(dir / "empty.md"), std::string());
  EXPECT_EQ(read_file_text(dir / "missing.md"), std::nullopt);
}

TEST(InputFile, RefusesFoldersAndMissingFiles) {
  test::TempDir dir;
  EXPECT_NE(test::input_error_of([&] { require_regular_file(dir.path(), "file"); }).find("is a folder"),
            std::string::npos);
  EXPECT_NE(test::input_error_of([&] { require_regular_file(dir / "none", "file"); }).find("does not exist"),
            std::string::npos);
}

// Each reason a path cannot be looked at is said: a loop of links once "did not exist".
TEST(InputFile, SaysWhyAPathCannotBeLookedAt) {
  test::TempDir dir;
  std::filesystem::create_symlink("loop.toml", dir / "loop.toml");
  EXPECT_NE(
      test::input_error_of([&] { require_regular_file(dir / "loop.toml", "file"); }).find("is a symbolic link loop"),
      std::string::npos);
  test::write_text(dir / "plain.toml", "");
  EXPECT_NE(test::input_error_of([&] {
              require_regular_file(dir / "plain.toml" / "inner.toml", "file");
            }).find("a part of the path before the file name is a file, not a folder"),
            std::string::npos);
  require_regular_file(dir / "plain.toml", "file");  // readable: no error
}

}  // namespace
}  // namespace linkage
