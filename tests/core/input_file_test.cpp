#include "core/input_file.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace linkage
