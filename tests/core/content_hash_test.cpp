#include "core/content_hash.hpp"

#include <gtest/gtest.h>

namespace linkage {
namespace {

TEST(ContentHash, IsSixteenHexDigitsOfFnv1a) {
  EXPECT_EQ(content_hash(""), "cbf29ce484222325");  // FNV-1a 64 offset basis
  EXPECT_EQ(content_hash("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(content_hash("foobar"), "85944171f73967e8");  // the published test vector
  EXPECT_NE(content_hash("ab"), content_hash("ba"));
}

}  // namespace
}  // namespace linkage
