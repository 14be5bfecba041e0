// Lessons built to exhaust the stack (math, expressions, lists and TOML keys nested tens
// of thousands of levels deep) get one line naming the file, line and column, exit code
// 2 and no output folder, from `lesson --check` and from a run alike. Each lesson is
// generated here rather than kept as a large file.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/limits.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

namespace fs = std::filesystem;

using test::repeat;

const std::string kTooDeep = "nested more than " + std::to_string(kMaxNesting) + " levels deep";

// A lesson whose step 1 has `body` (lines after kind = ...).
std::string lesson(const std::string& kind, const std::string& body) {
  return "title = \"Deep\"\n[[step]]\nkind = \"" + kind + "\"\n" + body + "\n";
}

struct Hostile {
  std::string name;
  std::string text;      // the lesson file
  std::string position;  // ":LINE:COLUMN: ..." expected right after the file name
};

std::vector<Hostile> hostile_lessons() {
  const std::string math = " the math is " + kTooDeep;
  const std::string expression = " the expression is " + kTooDeep;
  return {
      // 20,000 nested \sqrt{: the 65th level is the 65th brace, the math starting at column 8.
      {"sqrt", lesson("say", "text = 'Look: $" + repeat("\\sqrt{", 20000) + "x$'"),
       ":4:8: step 1 (say): text: line 1, column " + std::to_string(8 + 6 * kMaxNesting + 5) + ":" + math},
      {"carets", lesson("say", "text = \"\"\"\nSee\n$x" + repeat("^", 50000) + "2$\"\"\""),
       ":4:8: step 1 (say): text: line 2, column " + std::to_string(kMaxNesting + 4) + ":" + math},
      {"braces", lesson("render", "out = \"a.png\"\ncaption = '$" + repeat("{", 100000) + "$'"),
       ":5:11: step 1 (render): caption: line 1, column " + std::to_string(kMaxNesting + 2) + ":" + math},
      {"unit", lesson("exercise", "question = 'Q'\nanswer = 'm'\nunit = '$" + repeat("\\sqrt", 30000) + " x$'"),
       ":6:8: step 1 (exercise): unit: line 1, column " + std::to_string(2 + 5 * (kMaxNesting + 1)) + ":" + math},
      {"parentheses", lesson("exercise", "question = 'Q'\nanswer = '" + repeat("(", 100000) + "1'"),
       ":5:10: step 1 (exercise): answer:" + expression},
      {"signs", lesson("exercise", "question = 'Q'\nanswer = '" + repeat("-", 100000) + "1'"),
       ":5:10: step 1 (exercise): answer:" + expression},
      {"calls", lesson("exercise", "question = 'Q'\nanswer = '" + repeat("sqrt(", 100000) + "1'"),
       ":5:10: step 1 (exercise): answer:" + expression},
      {"placeholder", lesson("say", "text = 'I = {{" + repeat("(", 100000) + "I_zz_P}}'"),
       ":4:8: step 1 (say): text: {{"},
      // 100,000 lists and quotes, one in the other: refused at the text inside them.
      {"list", lesson("say", "text = '''\n- top\n" + repeat("- ", 100000) + "deep'''"),
       ":4:8: step 1 (say): text: line 2, column 200001: lists and quotes are " + kTooDeep},
      {"quote", lesson("say", "text = '''\n" + repeat(">", 100000) + " deep'''"),
       ":4:8: step 1 (say): text: line 1, column 100002: lists and quotes are " + kTooDeep},
      // toml++ recurses once per part of a dotted key or table name.
      {"key", lesson("say", "text = 'hi'") + "[[step" + repeat(".a", 100000) + "]]\n", ":5:3: the key is " + kTooDeep},
  };
}

TEST(LessonHostile, DeepNestingIsOneLineAndExitCodeTwoNeverACrash) {
  TempDir dir;
  for (const Hostile& h : hostile_lessons()) {
    SCOPED_TRACE(h.name);
    const fs::path file = dir / (h.name + ".toml");
    write_text(file, h.text);
    const fs::path out = dir / (h.name + "-out");
    for (const std::vector<std::string>& args : {std::vector<std::string>{"lesson", file.string(), "--check"},
                                                 {"lesson", file.string(), "--out", out.string()}}) {
      const RunResult r = run_linkage(args);
      EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 500);
      EXPECT_EQ(r.out, "");
      const std::string head = "linkage: error: " + file.string() + h.position;
      EXPECT_EQ(r.err.rfind(head, 0), 0u) << r.err.substr(0, 500) << "\nexpected it to start with\n" << head;
      EXPECT_NE(r.err.find(kTooDeep), std::string::npos) << r.err.substr(0, 500);
      EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line";
      EXPECT_LT(r.err.size(), 400u) << "a short line";
      EXPECT_FALSE(fs::exists(out));
    }
  }
}

// Text in a file of its own: the position is the file's line and column.
TEST(LessonHostile, DeepMathInASayFileNamesThatFile) {
  TempDir dir;
  write_text(dir / "deep.md", "# Heading\n\nSome text, then\n  $$" + repeat("\\frac{", 5000) + "$$\n");
  const fs::path file = dir / "lesson.toml";
  write_text(file, lesson("say", "file = \"deep.md\""));
  const RunResult r = run_linkage({"lesson", file.string(), "--check"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "linkage: error: " + file.string() + ":4:8: step 1 (say): " + (dir / "deep.md").string() +
                       ": line 4, column " + std::to_string(5 + 6 * kMaxNesting + 5) + ": the math is " + kTooDeep +
                       " (each {...} and each argument of \\sqrt, \\frac, ^ or _ is a level)\n");
}

// As deep as allowed still runs: math, lists, quotes, a placeholder and an answer.
TEST(LessonHostile, NestingWithinTheBoundRuns) {
  TempDir dir;
  const int n = kMaxNesting;
  std::string list;  // n levels, each two spaces further in
  for (int i = 1; i < n; ++i) list += std::string(2 * i - 2, ' ') + "- level " + std::to_string(i) + "\n";
  list += std::string(2 * n - 2, ' ') + "- deepest\n";
  const fs::path file = dir / "ok.toml";
  write_text(file, lesson("say", "text = '''\n$" + repeat("\\sqrt{", n) + "x" + repeat("}", n) + "$\n\n" + list + "\n" +
                                     repeat(">", n) + " quoted\n'''") +
                       "[[step]]\nkind = \"exercise\"\nquestion = \"{{" + repeat("(", n) + "m" + repeat(")", n) +
                       "}}\"\nanswer = \"" + repeat("-", n) + "m\"\n");
  const RunResult r = run_linkage({"lesson", file.string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err.substr(0, 500);
  EXPECT_NE(r.out.find(repeat("√(", n - 1) + "√x" + repeat(")", n - 1)), std::string::npos);
  EXPECT_NE(r.out.find("\n" + std::string(2 * n, ' ') + "- deepest\n"), std::string::npos);
  EXPECT_NE(r.out.find("\n  " + repeat("| ", n) + "quoted\n"), std::string::npos);
  EXPECT_NE(r.out.find("Exercise. 0.1\n"), std::string::npos) << r.out.substr(r.out.size() - 300);
  EXPECT_NE(r.out.find("Answer: 0.1 kg"), std::string::npos);  // - - m is m, with its unit
}

}  // namespace
}  // namespace linkage::test
