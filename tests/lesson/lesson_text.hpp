#pragma once
// Lessons written inline in a test: the text saved as a lesson file in a temporary folder
// and read, or the one-line error it gets.
#include <string>

#include "lesson/lesson.hpp"
#include "support/test_support.hpp"

namespace linkage::lesson::test_text {

inline Lesson parse_text(const test::TempDir& dir, const std::string& text) {
  const std::filesystem::path file = dir / "lesson.toml";
  test::write_text(file, text);
  return parse_lesson(file);
}

/// The bad-input error reading `text` gives ("" when it reads).
inline std::string error_of(const std::string& text) {
  test::TempDir dir;
  return test::input_error_of([&] { (void)parse_text(dir, text); });
}

}  // namespace linkage::lesson::test_text
