#include "render/vector_still.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "render/cairo_util.hpp"
#include "support/test_support.hpp"
#include "xml_check.hpp"

namespace linkage {
namespace {

// A figure of lines, fills and text, as a still's painter draws one.
void paint(cairo_t* cr) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0.2, 0.4, 0.8);
  cairo_rectangle(cr, 100, 100, 300, 40);
  cairo_fill(cr);
  cairo_move_to(cr, 100, 300);
  cairo_line_to(cr, 600, 200);
  cairo_stroke(cr);
  cairo_move_to(cr, 100, 400);
  cairo_show_text(cr, "F on 1");
}

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(VectorStill, SvgIsWellFormedAndAllVector) {
  test::TempDir dir;
  write_vector_still(paint, OutputKind::svg, 1280, 720, dir / "fig.svg", "--out");
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
  test::TempDir dir;
  write_vector_still(paint, OutputKind::pdf, 1280, 720, dir / "a.pdf", "--out");
  write_vector_still(paint, OutputKind::pdf, 1280, 720, dir / "b.pdf", "--out");
  const std::string pdf = contents(dir / "a.pdf");
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("%%EOF", pdf.size() - 8), std::string::npos);
  EXPECT_EQ(pdf, contents(dir / "b.pdf"));
}

TEST(VectorStill, MissingFolderIsAnInputErrorAndLeavesNothing) {
  test::TempDir dir;
  try {
    write_vector_still(paint, OutputKind::svg, 64, 64, dir / "no/such/fig.svg", "--out");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_NE(std::string(e.what()).find("--out"), std::string::npos);
  }
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace linkage
