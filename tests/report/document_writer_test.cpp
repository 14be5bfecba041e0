// The Markdown document writer (a lesson's lesson.md) keeps Markdown as written.
#include "report/document_writer.hpp"

#include <gtest/gtest.h>

#include "support/commonmark_sample.hpp"

namespace linkage {
namespace {

// lesson.md keeps the Markdown as written, for any CommonMark reader.
TEST(CommonMark, TheLessonDocumentKeepsTheText) {
  const auto writer = make_markdown_writer();
  writer->markdown(test::kCommonMarkSample);
  EXPECT_EQ(writer->take(), "\n" + std::string(test::kCommonMarkSample) + "\n");
}

}  // namespace
}  // namespace linkage
