#include "render/vector_still.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "render_test_support.hpp"
#include "support/test_support.hpp"
#include "xml_check.hpp"

namespace linkage {
namespace {

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(VectorStill, SvgIsWellFormedAndAllVector) {
  const Params p;
  const Motion motion = test::closed_form_motion(p, State{}, 16, 1.0 / 30, true);
  RenderSettings settings;
  ClipRenderer renderer(p, motion, settings, load_theme("light", {}, "--theme"), "Case 3");
  test::TempDir dir;
  write_vector_still(renderer, 15, OutputKind::svg, settings.width, settings.height, dir / "fig.svg", "--out");
  const std::string svg = contents(dir / "fig.svg");
  EXPECT_EQ(test::xml_error(svg), "");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("width=\"1280px\""), std::string::npos) << svg.substr(0, 300);
  EXPECT_EQ(svg.find("<image"), std::string::npos) << "a vector figure holds no bitmaps";
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"fig.svg"});  // no temporary left
  // The checker does catch mistakes.
  EXPECT_NE(test::xml_error("<svg><g></svg>"), "");
  EXPECT_NE(test::xml_error("<svg a=\"1\" a=\"2\"/>"), "");
  EXPECT_NE(test::xml_error("<svg>&nbsp;</svg>"), "");
}

TEST(VectorStill, PdfIsCompleteAndRepeatable) {
  const Params p;
  const Motion motion = test::still_motion(p, State{}, true, 0.5);
  RenderSettings settings;
  ClipRenderer renderer(p, motion, settings, load_theme("print", {}, "--theme"), "Case 3");
  test::TempDir dir;
  write_vector_still(renderer, 0, OutputKind::pdf, settings.width, settings.height, dir / "a.pdf", "--out");
  write_vector_still(renderer, 0, OutputKind::pdf, settings.width, settings.height, dir / "b.pdf", "--out");
  const std::string pdf = contents(dir / "a.pdf");
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("%%EOF", pdf.size() - 8), std::string::npos);
  EXPECT_EQ(pdf, contents(dir / "b.pdf"));
}

TEST(VectorStill, MissingFolderIsAnInputErrorAndLeavesNothing) {
  const Params p;
  const Motion motion = test::still_motion(p, State{}, false);
  RenderSettings settings;
  ClipRenderer renderer(p, motion, settings, load_theme("light", {}, "--theme"), "Case 3");
  test::TempDir dir;
  try {
    write_vector_still(renderer, 0, OutputKind::svg, 64, 64, dir / "no/such/fig.svg", "--out");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_NE(std::string(e.what()).find("--out"), std::string::npos);
  }
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace linkage
