// Content hashes and the artifact cache.
#include <gtest/gtest.h>

#include "lesson/cache.hpp"
#include "lesson/canonical.hpp"
#include "support/test_support.hpp"

namespace linkage::lesson {
namespace {

TEST(ContentHash, CanonicalTextIsOrderFreeAndValueExact) {
  const toml::table a = toml::parse("b = 1\na = [0.1, \"x\"]\nc = { d = true }");
  const toml::table b = toml::parse("c = { d = true }\na = [0.1, \"x\"]\nb = 1");
  const toml::table c = toml::parse("b = 1\na = [0.10000000000000002, \"x\"]\nc = { d = true }");
  EXPECT_EQ(canonical_text(a), canonical_text(b));
  EXPECT_NE(canonical_text(a), canonical_text(c));
  EXPECT_EQ(canonical_text(a), "{\"a\"=[0.1,\"x\"],\"b\"=1,\"c\"={\"d\"=true}}");
  EXPECT_EQ(canonical_text(a, {"b"}), "{\"a\"=[0.1,\"x\"],\"c\"={\"d\"=true}}");
  EXPECT_EQ(content_hash(""), "cbf29ce484222325");  // FNV-1a 64 offset basis
  EXPECT_EQ(content_hash("a"), "af63dc4c8601ec8c");
}

TEST(ArtifactCache, HitsOnlyWithTheSameHashAndIntactFiles) {
  test::TempDir dir;
  const std::vector<std::string> artifacts{"a.png", "a.svg"};
  ArtifactCache cache(dir.path(), false);
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
  test::write_text(dir / "a.png", "png");
  test::write_text(dir / "a.svg", "<svg/>");
  cache.store(artifacts, "h1", {{"k", 1}});
  ASSERT_TRUE(cache.lookup(artifacts, "h1"));
  EXPECT_EQ((*cache.lookup(artifacts, "h1"))["k"], 1);
  EXPECT_FALSE(cache.lookup(artifacts, "h2"));
  EXPECT_FALSE(ArtifactCache(dir.path(), true).lookup(artifacts, "h1"));  // --force
  test::write_text(dir / "a.svg", "<svg></svg>");                          // changed behind our back
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
  cache.store(artifacts, "h1", {});
  std::filesystem::remove(dir / "a.png");
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
  test::write_text(dir / "a.png", "png");
  cache.store(artifacts, "h1", {});
  cache.invalidate(artifacts);  // a step about to write
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
}

}  // namespace
}  // namespace linkage::lesson
