// A lesson's handout builds both ways: `linkage lesson --pdf` writes lesson.tex and
// compiles it to lesson.pdf with pdflatex, and, as the README says, `pandoc lesson.md -o lesson.pdf` in the
// lesson's folder (pdflatex, the default engine; rsvg-convert for its SVG still). The
// numerical-example lesson has them all: Unicode symbols in prose and captions, matrices,
// a table, a clip and a vector still. Every caption shows once. The test command installs
// pandoc and TeX; without them the test is skipped, except in CI, where that is a failure.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/program_path.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(LessonHandout, BuildsThePdfBothWaysAndEachCaptionShowsOnce) {
  for (const char* tool : {"pandoc", "pdflatex", "rsvg-convert"}) {
    if (on_path(tool)) continue;
    if (std::getenv("CI") != nullptr) FAIL() << tool << " is missing: ./scripts/install-deps --tests installs it";
    GTEST_SKIP() << tool << " is not installed";
  }
  test::TempDir dir;
  const std::filesystem::path lesson =
      std::filesystem::path(LINKAGE_SOURCE_DIR) / "lessons" / "06-numerical-example.toml";
  const test::RunResult r =
      test::run_linkage({"lesson", lesson.string(), "--out", dir.path().string(), "--quality", "draft", "--pdf"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // linkage lesson made the LaTeX handout itself: lesson.tex, compiled to lesson.pdf.
  EXPECT_NE(r.err.find("handout " + (dir / "lesson.tex").string() + " and " + (dir / "lesson.pdf").string()),
            std::string::npos)
      << r.err;
  EXPECT_EQ(test::read_text(dir / "lesson.pdf").rfind("%PDF", 0), 0u);
  EXPECT_NE(test::read_text(dir / "lesson.tex").find("\\begin{document}"), std::string::npos);
  for (const char* leftover : {"lesson-pdf-partial.aux", "lesson-pdf-partial.log", "lesson.log"})
    EXPECT_FALSE(std::filesystem::exists(dir / leftover)) << leftover;

  const std::string cd = "cd '" + dir.path().string() + "' && ";
  ASSERT_EQ(std::system((cd + "pandoc lesson.md -o pandoc.pdf > pandoc.log 2>&1").c_str()), 0)
      << test::read_text(dir / "pandoc.log");
  EXPECT_EQ(test::read_text(dir / "pandoc.pdf").rfind("%PDF", 0), 0u);

  // What a reader sees: each caption once (pandoc would caption a lone image with its alt text too).
  ASSERT_EQ(std::system((cd + "pandoc lesson.md -t plain -o lesson.txt").c_str()), 0);
  const std::string seen = test::read_text(dir / "lesson.txt");
  for (const char* caption : {"The instant section 6 solves for, as a vector figure for handouts."})
    EXPECT_EQ(count(seen, caption), 1) << caption << "\n" << seen;
}

// The handout is compiled with no shell and no shell escape: a lesson named with quotes,
// ';', $(...) and backquotes makes its PDF in the folder named after it, and TeX in the
// lesson's text cannot run a program (makeindex is on TeX Live's list of commands a
// restricted \write18 may run; touch is not).
TEST(LessonHandout, NeitherTheFileNameNorTheTextRunsAnything) {
  if (!on_path("pdflatex")) {
    if (std::getenv("CI") != nullptr) FAIL() << "pdflatex is missing: ./scripts/install-deps --tests installs it";
    GTEST_SKIP() << "pdflatex is not installed";
  }
  test::TempDir dir;
  const std::string name = "it's \"q\"; $(touch pwned) `touch pwned`";
  test::write_text(dir / (name + ".toml"), R"(title = "Handout"
[[step]]
kind = "say"
text = '''
TeX would run programs: $\immediate\openout15=pwned3.idx \immediate\write15{\string\indexentry{a}{1}}\immediate\closeout15 \immediate\write18{makeindex pwned3}\immediate\write18{touch pwned2}$.
'''
)");
  test::RunOptions run;
  run.args = {"lesson", name + ".toml", "--pdf"};
  run.cwd = dir.path();
  const test::RunResult r = test::run_linkage(run);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::filesystem::path out = dir / name;
  EXPECT_EQ(test::read_text(out / "lesson.pdf").rfind("%PDF", 0), 0u);
  EXPECT_NE(test::read_text(out / "lesson.tex").find("\\write18{makeindex pwned3}"), std::string::npos);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{name, name + ".toml"}));  // no pwned
  // TeX itself may write pwned3.idx in its folder; no program read it.
  for (const char* made : {"pwned", "pwned2", "pwned3.ind", "pwned3.ilg"})
    EXPECT_FALSE(std::filesystem::exists(out / made)) << made;
}

}  // namespace
}  // namespace linkage
