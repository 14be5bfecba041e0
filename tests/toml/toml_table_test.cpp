// The located TOML table reader: every error one line "FILE:LINE:COLUMN: CONTEXT: problem"
// at the offending key, value or entry; and the canonical text content hashes are built on.
#include "toml/toml_table.hpp"

#include <gtest/gtest.h>

#include <array>
#include <limits>

#include "core/error.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

constexpr std::array<KeySpec, 5> kKeys{{
    {"fps", "integer", "30"},
    {"duration", "number", "10"},
    {"show", "list of strings", "none"},
    {"loop", "boolean", "false"},
    {"runs", "list of tables", "none"},
}};

// Reads `text` and calls `use` with a reader of its top level named "step 2 (render)".
std::string error_of(const std::string& text, const std::function<void(const TableReader&)>& use) {
  const toml::table table = toml::parse(text);
  const TableReader r(table, "f.toml", "step 2 (render)", kKeys, {"theta1"});
  return test::input_error_of([&] { use(r); });
}

TEST(TomlTable, AnUnknownKeyIsNamedAtItsPositionWithTheNearestOne) {
  // The first unknown key in file order, though toml++ sorts them by name.
  EXPECT_EQ(error_of("fps = 30\nzebra = 1\n  fsp = 24\n", [](const TableReader& t) { t.reject_unknown_keys(); }),
            "f.toml:2:1: step 2 (render): unknown key 'zebra'; valid keys: fps, duration, show, loop, runs, theta1");
  EXPECT_EQ(error_of("fps = 30\n  fsp = 24\n", [](const TableReader& t) { t.reject_unknown_keys(); }),
            "f.toml:2:3: step 2 (render): unknown key 'fsp' (did you mean 'fps'?); valid keys: fps, duration, show, "
            "loop, runs, theta1");
  EXPECT_EQ(error_of("theta1 = 0.5\nloop = true\n", [](const TableReader& t) { t.reject_unknown_keys(); }), "");
}

TEST(TomlTable, TypedValuesAndTheirErrors) {
  const toml::table table = toml::parse("fps = 24\nduration = 2.5\nloop = true\nshow = \"hud\"\n");
  const TableReader r(table, "f.toml", "step 1", kKeys);
  EXPECT_EQ(*r.integer("fps", 1, 240), 24);
  EXPECT_EQ(*r.number("duration", 0, 60, ""), 2.5);
  EXPECT_EQ(*r.number("fps", 0, 60, ""), 24.0);  // an integer is a number
  EXPECT_TRUE(*r.boolean("loop"));
  EXPECT_EQ(*r.strings("show"), std::vector<std::string>{"hud"});  // one string is a list of one
  EXPECT_FALSE(r.number("missing", 0, 1, "").has_value());
  EXPECT_EQ(r.where("duration"), "f.toml:2:12");
  EXPECT_EQ(r.where("missing"), "f.toml:1:1");  // absent: the table itself

  EXPECT_EQ(error_of("\nduration = \"2\"", [](const TableReader& t) { (void)t.number("duration", 0, 60, ""); }),
            "f.toml:2:12: step 2 (render): 'duration' must be a number, got a string");
  EXPECT_EQ(error_of("fps = 2.5", [](const TableReader& t) { (void)t.integer("fps", 1, 240); }),
            "f.toml:1:7: step 2 (render): 'fps' must be an integer, got a float");
  EXPECT_EQ(error_of("loop = 1", [](const TableReader& t) { (void)t.boolean("loop"); }),
            "f.toml:1:8: step 2 (render): 'loop' must be true or false, got an integer");
  EXPECT_EQ(error_of("show = 3", [](const TableReader& t) { (void)t.strings("show"); }),
            "f.toml:1:8: step 2 (render): 'show' must be a string or a list of strings, got an integer");
}

TEST(TomlTable, OutOfRangeAndNonFiniteValuesNameTheValue) {
  EXPECT_EQ(error_of("fps = 500", [](const TableReader& t) { (void)t.integer("fps", 1, 240); }),
            "f.toml:1:7: step 2 (render): 'fps' = 500 is out of range; valid: 1 to 240");
  EXPECT_EQ(
      error_of("duration = -0.5", [](const TableReader& t) { (void)t.number("duration", 0, 60, "valid: 0 to 60 s"); }),
      "f.toml:1:12: step 2 (render): 'duration' = -0.5 is out of range; valid: 0 to 60 s");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of("duration = inf", [&](const TableReader& t) { (void)t.number("duration", -inf, inf, ""); }),
            "f.toml:1:12: step 2 (render): 'duration' = inf is not a finite number");
}

TEST(TomlTable, RequiredKeysAreMissedAtTheTable) {
  EXPECT_EQ(error_of("fps = 1", [](const TableReader& t) { t.require("duration"); }),
            "f.toml:1:1: step 2 (render): the key 'duration' is required");
  EXPECT_EQ(error_of("fps = 1", [](const TableReader& t) { t.require("show", "[\"hud\"]"); }),
            "f.toml:1:1: step 2 (render): the key 'show' is required, e.g. [\"hud\"]");
}

TEST(TomlTable, ABadListEntryIsNamedAtTheEntry) {
  const std::vector<std::string_view> elements{"blocks", "pin", "hud"};
  const toml::table table = toml::parse("show = [\"hud\", \"blocks\"]");
  const TableReader r(table, "f.toml", "step 1", kKeys);
  EXPECT_EQ(r.choice_list("show", elements), (std::vector<std::size_t>{2, 0}));
  EXPECT_TRUE(r.choice_list("absent", elements).empty());
  EXPECT_EQ(error_of("show = [\"hud\",\n        \"blcks\"]",
                     [&](const TableReader& t) { (void)t.choice_list("show", elements); }),
            "f.toml:2:9: step 2 (render): 'blcks' in 'show' is not valid (did you mean 'blocks'?); valid: blocks, "
            "pin, hud");
  EXPECT_EQ(error_of("show = \"pn\"", [&](const TableReader& t) { (void)t.choice_list("show", elements); }),
            "f.toml:1:8: step 2 (render): 'pn' in 'show' is not valid (did you mean 'pin'?); valid: blocks, pin, hud");
  EXPECT_EQ(error_of("show = [\"hud\", 3]", [](const TableReader& t) { (void)t.strings("show"); }),
            "f.toml:1:16: step 2 (render): every entry of 'show' must be a string, got an integer");
  EXPECT_EQ(error_of("show = \"pn\"", [&](const TableReader& t) { (void)t.choice("show", elements); }),
            "f.toml:1:8: step 2 (render): 'show' = 'pn' is not valid (did you mean 'pin'?); valid: blocks, pin, hud");
}

TEST(TomlTable, TablesAndListsOfTables) {
  const toml::table table = toml::parse("runs = [{ fps = 1 }, { fps = 2 }]\n[[more]]\nx = 1\n[sub]\ny = 2\n");
  const TableReader r(table, "f.toml", "step 1", kKeys);
  const auto runs = r.tables("runs");
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1]->get("fps")->value<int>(), 2);
  EXPECT_EQ(r.tables("more").size(), 1u);
  EXPECT_TRUE(r.tables("absent").empty());
  ASSERT_NE(r.subtable("sub"), nullptr);
  EXPECT_EQ(r.subtable("absent"), nullptr);
  EXPECT_EQ(error_of("runs = [{ fps = 1 }, 2]", [](const TableReader& t) { (void)t.tables("runs"); }),
            "f.toml:1:22: step 2 (render): every entry of 'runs' must be a table, got an integer");
  EXPECT_EQ(error_of("body = 3", [](const TableReader& t) { (void)t.tables("body", "[[body]]"); }),
            "f.toml:1:8: step 2 (render): 'body' must be a list of tables, each written [[body]], got an integer");
  EXPECT_EQ(error_of("sub = [1]", [](const TableReader& t) { (void)t.subtable("sub"); }),
            "f.toml:1:7: step 2 (render): 'sub' must be a table, got an array");
}

TEST(TomlTable, KeysComeInFileOrder) {
  const toml::table table = toml::parse("zeta = 1\nalpha = 2\nmid = 3\nbeta = 4\n");
  const TableReader r(table, "f.toml", "step 1", kKeys);
  EXPECT_EQ(r.keys_in_file_order([](std::string_view) { return true; }),
            (std::vector<std::string>{"zeta", "alpha", "mid", "beta"}));
  EXPECT_EQ(r.keys_in_file_order([](std::string_view k) { return k != "mid"; }),
            (std::vector<std::string>{"zeta", "alpha", "beta"}));
  const auto entries = r.entries();
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries[1].first->str(), "alpha");
  EXPECT_EQ(entries[1].second->value<int>(), 2);
}

TEST(TomlTable, ARegionNotRecordedIsTheWholeFile) {
  EXPECT_EQ(position("f.toml", toml::source_region{}), "f.toml:1:1");
  EXPECT_EQ(position("f.toml", toml::source_region{{3, 7}, {3, 9}, nullptr}), "f.toml:3:7");
}

TEST(TomlTable, CanonicalTextIsOrderFreeAndValueExact) {
  const toml::table a = toml::parse("b = 1\na = [0.1, \"x\"]\nc = { d = true }");
  const toml::table b = toml::parse("c = { d = true }\na = [0.1, \"x\"]\nb = 1");
  EXPECT_EQ(canonical_text(a), canonical_text(b));
  EXPECT_EQ(canonical_text(a), "{\"a\"=[0.1,\"x\"],\"b\"=1,\"c\"={\"d\"=true}}");
  EXPECT_EQ(canonical_text(a, {"b"}), "{\"a\"=[0.1,\"x\"],\"c\"={\"d\"=true}}");
  // Any change of a value changes the text: the last bit of a float, an integer, a string,
  // a nested boolean, an entry more.
  for (const char* changed :
       {"b = 1\na = [0.10000000000000002, \"x\"]\nc = { d = true }", "b = 2\na = [0.1, \"x\"]\nc = { d = true }",
        "b = 1\na = [0.1, \"X\"]\nc = { d = true }", "b = 1\na = [0.1, \"x\"]\nc = { d = false }",
        "b = 1\na = [0.1, \"x\", 2]\nc = { d = true }", "b = 1\na = [0.1, \"x\"]\nc = { d = true, e = 0 }"})
    EXPECT_NE(canonical_text(a), canonical_text(toml::parse(changed))) << changed;
  // 1 and 1.0 mean the same and read the same.
  EXPECT_EQ(canonical_text(a), canonical_text(toml::parse("b = 1.0\na = [0.1, \"x\"]\nc = { d = true }")));
  // Skipping is for the top level only.
  EXPECT_EQ(canonical_text(toml::parse("c = { b = 2 }"), {"b"}), "{\"c\"={\"b\"=2}}");
  // Strings are quoted with escapes, so no string can pose as structure.
  EXPECT_EQ(canonical_text(toml::parse("s = \"a\\\"=1,\\n\"")), "{\"s\"=\"a\\\"=1,\\n\"}");
}

}  // namespace
}  // namespace linkage
