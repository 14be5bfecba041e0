// The artifact cache.
#include "lesson/cache.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "support/test_support.hpp"

namespace linkage::lesson {
namespace {

TEST(ArtifactCache, HitsOnlyWithTheSameHashAndIntactFiles) {
  test::TempDir dir;
  const std::vector<std::string> artifacts{"a.png", "a.svg"};
  std::ostringstream notes;
  ArtifactCache cache(dir.path(), false, notes);
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
  test::write_text(dir / "a.png", "png");
  test::write_text(dir / "a.svg", "<svg/>");
  cache.store(artifacts, "h1", {{"k", 1}});
  ASSERT_TRUE(cache.lookup(artifacts, "h1"));
  EXPECT_EQ((*cache.lookup(artifacts, "h1"))["k"], 1);
  EXPECT_FALSE(cache.lookup(artifacts, "h2"));
  EXPECT_FALSE(ArtifactCache(dir.path(), true, notes).lookup(artifacts, "h1"));  // --force
  test::write_text(dir / "a.svg", "<svg></svg>");                                // changed behind our back
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
  cache.store(artifacts, "h1", {});
  std::filesystem::remove(dir / "a.png");
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
  test::write_text(dir / "a.png", "png");
  cache.store(artifacts, "h1", {});
  cache.invalidate(artifacts);  // a step about to write
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
  EXPECT_EQ(notes.str(), "");  // misses of intact records go without a word
}

// Whatever is in the record's place, a lookup misses with one note naming it, and the
// record the step then stores is used next time.
TEST(ArtifactCache, AnUnreadableRecordIsAMissWithANote) {
  test::TempDir dir;
  const std::vector<std::string> artifacts{"a.csv"};
  test::write_text(dir / "a.csv", "t\n0\n");
  const std::string record = (dir / ".a.csv.cache.json").string();
  const std::string good = R"({"hash": "h1", "artifacts": {"a.csv": 4}, "results": {"k": 1}})";
  const std::vector<std::pair<std::string, std::string>> cases{
      {R"({"hash": 5})", "no \"hash\" string"},
      {"", "it is empty"},
      {good.substr(0, 30), "not JSON: a syntax error at byte 31"},
      {"\x7f\x45\x4c\x46 garbage", "not JSON: a syntax error at byte 1"},
      {"[1, 2]", "not a JSON object"},
      {std::string(100000, '[') + std::string(100000, ']'), "not a JSON object"},
      {R"({"hash": "h1", "results": {}})", "no \"artifacts\" object"},
      {R"({"hash": "h1", "artifacts": {"a.csv": -4}})", "the size of \"a.csv\" is not a whole number"},
      {R"({"hash": "h1", "artifacts": {"a.csv": 4}, "results": [1]})", "\"results\" is not an object"},
  };
  for (const auto& [content, reason] : cases) {
    SCOPED_TRACE(reason);
    test::write_text(record, content);
    std::ostringstream notes;
    const ArtifactCache cache(dir.path(), false, notes);
    EXPECT_FALSE(cache.lookup(artifacts, "h1"));
    EXPECT_EQ(notes.str(),
              "linkage: note: cache record '" + record + "' is unreadable (" + reason + "); making it again\n");
    cache.invalidate(artifacts);
    cache.store(artifacts, "h1", {{"k", 2}});
    ASSERT_TRUE(cache.lookup(artifacts, "h1"));
    EXPECT_EQ((*cache.lookup(artifacts, "h1"))["k"], 2);
  }
  // The well-formed record it stands for is read.
  test::write_text(record, good);
  std::ostringstream notes;
  ASSERT_TRUE(ArtifactCache(dir.path(), false, notes).lookup(artifacts, "h1"));
  EXPECT_EQ(notes.str(), "");
}

TEST(ArtifactCache, AFolderInTheRecordsPlaceIsRemovedWhenEmptyAndLeftOtherwise) {
  test::TempDir dir;
  const std::vector<std::string> artifacts{"a.csv"};
  test::write_text(dir / "a.csv", "t\n");
  const std::filesystem::path record = dir / ".a.csv.cache.json";
  for (const bool force : {false, true}) {
    std::filesystem::create_directory(record);
    std::ostringstream notes;
    const ArtifactCache cache(dir.path(), force, notes);
    EXPECT_FALSE(cache.lookup(artifacts, "h1"));
    cache.invalidate(artifacts);
    EXPECT_EQ(notes.str(),
              "linkage: note: cache record '" + record.string() + "' was an empty folder, not a file; removed it\n");
    cache.store(artifacts, "h1", {});
    EXPECT_TRUE(std::filesystem::is_regular_file(record));
    std::filesystem::remove(record);
  }
  // A folder with something in it is not ours to delete: the step goes unrecorded.
  std::filesystem::create_directory(record);
  test::write_text(record / "keep.txt", "mine");
  std::ostringstream notes;
  const ArtifactCache cache(dir.path(), false, notes);
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
  cache.invalidate(artifacts);
  EXPECT_NO_THROW(cache.store(artifacts, "h1", {}));
  EXPECT_FALSE(cache.lookup(artifacts, "h1"));
  EXPECT_EQ(notes.str(),
            "linkage: note: cache record '" + record.string() +
                "' is a folder with files in it, not a file; left it as it is, so this step is not cached\n");
  EXPECT_EQ(test::read_text(record / "keep.txt"), "mine");
}

}  // namespace
}  // namespace linkage::lesson
