// The lesson document (lesson.md) keeps a lesson's Markdown as written.
#include "lesson/output.hpp"

#include <gtest/gtest.h>

#include "support/commonmark_sample.hpp"

namespace linkage::lesson {
namespace {

// lesson.md keeps the Markdown as written, for any CommonMark reader.
TEST(CommonMark, TheLessonDocumentKeepsTheText) {
  const auto writer = make_markdown_writer();
  writer->markdown(test::kCommonMarkSample);
  EXPECT_EQ(writer->take(), "\n" + std::string(test::kCommonMarkSample) + "\n");
}

}  // namespace
}  // namespace linkage::lesson
