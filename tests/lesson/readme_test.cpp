// lessons/README.md documents the format completely: every key the parser accepts, every
// quantity, series and compare column, and its complete example is a valid lesson.
#include <gtest/gtest.h>

#include <filesystem>

#include "lesson/homework_names.hpp"
#include "lesson/lesson.hpp"
#include "lesson/schema.hpp"
#include "pipeline/run.hpp"
#include "support/test_support.hpp"

namespace linkage::lesson {
namespace {

namespace fs = std::filesystem;

const std::string& readme() {
  static const std::string text = test::read_text(fs::path(LINKAGE_SOURCE_DIR) / "lessons/README.md");
  return text;
}

/// "`name`", built by appending ("literal" + std::string trips GCC 12's -Wrestrict).
std::string code(std::string_view name) {
  std::string out(1, '`');
  out += name;
  out += '`';
  return out;
}

// A row "| `name` | type | default | meaning |" for every key, the default as the README
// writes it with its code marks (`"dop853"`) left out.
void expect_documented(std::span<const KeySpec> keys, const std::string& where) {
  for (const KeySpec& k : keys) {
    std::string lead = "| ";
    lead += code(k.name);
    lead += " | ";
    lead += k.type;
    lead += " | ";
    bool found = false;
    for (std::size_t at = readme().find(lead); at != std::string::npos && !found; at = readme().find(lead, at + 1)) {
      const std::size_t start = at + lead.size();
      std::string cell = readme().substr(start, readme().find(" | ", start) - start);
      std::erase(cell, '`');
      found = cell == k.default_text;
    }
    EXPECT_TRUE(found) << "key '" << k.name << "' (" << where << ") is missing from lessons/README.md with its type '"
                       << k.type << "' and default '" << k.default_text << "'";
  }
}

TEST(LessonReadme, DocumentsEveryKey) {
  expect_documented(lesson_keys(), "top level");
  expect_documented(common_step_keys(), "every step");
  expect_documented(run_keys(), "run keys");
  expect_documented(run_entry_keys(), "runs entries");
  for (std::string_view kind : kStepKindNames) {
    expect_documented(step_keys(kind), std::string(kind));
    std::string section = "### ";
    section += kind;
    section += '\n';
    EXPECT_NE(readme().find(section), std::string::npos) << kind;
  }
}

TEST(LessonReadme, DocumentsEveryNameAndColumn) {
  // Every name a homework lesson may quote but a point's, body's or joint's (those by example).
  for (const std::string& name : homework_names().names())
    if (name.find('.') == std::string::npos) {
      EXPECT_NE(readme().find(code(name)), std::string::npos) << name;
    }
  EXPECT_NE(readme().find(code("pi")), std::string::npos);
  // The homework's columns a plot names, but each point's (the table gives their range).
  const auto homework = build_mechanism(kDefaultMechanism, {}, "test", true);
  for (const MechanismColumn& c : homework->named_columns()) {
    if (c.quantity == MechanismQuantity::point) continue;
    EXPECT_NE(readme().find(code(c.name)), std::string::npos) << c.name;
  }
  for (std::string_view c : kCompareColumnNames) EXPECT_NE(readme().find(code(c)), std::string::npos) << c;
  for (std::string_view p : kSolvePartNames) EXPECT_NE(readme().find(code(p)), std::string::npos) << p;
}

TEST(LessonReadme, TheCompleteExampleIsAValidLesson) {
  const std::string start = "## A complete small lesson\n\n```toml\n";
  const std::size_t begin = readme().find(start);
  ASSERT_NE(begin, std::string::npos);
  const std::size_t body = begin + start.size();
  const std::string example = readme().substr(body, readme().find("```\n", body) - body);
  test::TempDir dir;
  test::write_text(dir / "example.toml", example);
  const Lesson lesson = parse_lesson(dir / "example.toml");
  EXPECT_EQ(lesson.title, "The pin force");
  std::vector<std::string_view> kinds;
  for (const Step& s : lesson.steps) kinds.push_back(name(s.kind));
  EXPECT_EQ(kinds, (std::vector<std::string_view>{"say", "solve", "exercise", "pause", "set", "render", "compare"}));
}

}  // namespace
}  // namespace linkage::lesson
