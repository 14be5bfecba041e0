// mechanisms/README.md documents the format completely: every key the reader accepts, in
// its table's section with its type and default, every shipped mechanism, and a complete
// example that reads.
#include <gtest/gtest.h>

#include <filesystem>

#include "model/mechanism_toml.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

const std::string& readme() {
  static const std::string text =
      test::read_text(std::filesystem::path(LINKAGE_SOURCE_DIR) / "mechanisms" / "README.md");
  return text;
}

// The text of the "### " section whose heading starts with `heading`, up to the next heading.
std::string section(const std::string& heading) {
  const std::size_t begin = readme().find("\n### " + heading);
  if (begin == std::string::npos) return {};
  const std::size_t end = readme().find("\n#", begin + 1);
  return readme().substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

TEST(MechanismReadme, DocumentsEveryKeyInItsTable) {
  ASSERT_FALSE(mechanism_keys().empty());
  for (const MechanismKey& key : mechanism_keys()) {
    std::string heading = key.table == "top level" ? "Top level" : "`";
    if (key.table != "top level") {
      heading += key.table;
      heading += '`';
    }
    std::string row = "| `";
    row += key.name;
    row += "` | ";
    row += key.type;
    row += " | ";
    row += key.default_text;
    row += " |";
    const std::string text = section(heading);
    ASSERT_FALSE(text.empty()) << "no section '### " << heading << "' in mechanisms/README.md";
    EXPECT_NE(text.find(row), std::string::npos) << "'" << row << "' is not in the section " << heading;
  }
}

TEST(MechanismReadme, NamesEveryShippedMechanism) {
  for (const std::string& name : shipped_mechanism_names())
    EXPECT_NE(readme().find("| `" + name + "` |"), std::string::npos) << name;
}

TEST(MechanismReadme, TheCompleteExampleReads) {
  const std::string start = "## A complete example\n";
  const std::size_t at = readme().find(start);
  ASSERT_NE(at, std::string::npos);
  const std::size_t body = readme().find("```toml\n", at) + 8;
  const std::string example = readme().substr(body, readme().find("```\n", body) - body);
  const Mechanism m = read_mechanism(example, "example.toml");
  EXPECT_EQ(m.title, "Two blocks on a spring, driven");
  EXPECT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.springs.size(), 1u);
  EXPECT_EQ(m.forces.size(), 1u);
  EXPECT_EQ(m.torques.size(), 1u);
  EXPECT_EQ(m.initial.size(), 8u);
}

}  // namespace
}  // namespace linkage
