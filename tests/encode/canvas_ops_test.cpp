// Cairo's SVG read as the page's canvas operations: its styles, glyph runs and paths in the
// book's form; anything outside the subset Cairo writes is refused. (A whole frame read
// and painted again: tests/pipeline/clip_page_test.cpp.)
#include "encode/canvas_ops.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace linkage {
namespace {

// A layer with nothing painted has no operations: the page leaves it out of the frame.
TEST(CanvasOps, AnEmptySurfaceHasNoOperations) {
  CanvasOps canvas;
  const std::string empty =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
      "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"64px\" height=\"48px\" viewBox=\"0 0 64 48\" "
      "version=\"1.1\">\n<g id=\"surface1\">\n</g>\n</svg>\n";
  EXPECT_TRUE(canvas.layer(empty).empty());
}

// Cairo's forms read exactly: a stroked, dashed path's style; a glyph run; what is not
// Cairo's subset is an internal error naming it, never drawn wrong.
TEST(CanvasOps, ReadsCairosStylesGlyphsAndRefusesTheRest) {
  CanvasOps canvas;
  const nlohmann::json ops = canvas.layer(
      "<svg><defs><g><symbol overflow=\"visible\" id=\"glyph0-1\"><path style=\"stroke:none;\" d=\"M 1 0 L 2 0 L 2 1 "
      "Z M 1 0 \"/></symbol></g></defs><g id=\"surface1\"><path style=\"fill:none;stroke-width:2.5;stroke-linecap:"
      "round;stroke-linejoin:round;stroke:rgb(83.529412%,36.862745%,0%);stroke-opacity:0.7;stroke-dasharray:2,1;"
      "stroke-miterlimit:10;\" d=\"M 10 20 L 13.5 20 C 14 21 15 22 16 23 \"/><g style=\"fill:rgb(100%,0%,0%);"
      "fill-opacity:1;\"><use xlink:href=\"#glyph0-1\" x=\"5.123\" y=\"6\"/><use xlink:href=\"#glyph0-1\" x=\"7\" "
      "y=\"6\"/></g></g></svg>");
  ASSERT_EQ(ops.size(), 2u) << ops;
  EXPECT_EQ(ops[0][0], "p");
  EXPECT_EQ(ops[0][2], "M 10 20 @0");
  EXPECT_EQ(canvas.paths()[0], "l 3.5 0 c 0.5 1 1.5 2 2.5 3");
  EXPECT_EQ(canvas.styles()[ops[0][1].get<std::size_t>()],
            nlohmann::json::parse(R"j({"stroke": "rgba(213,94,0,0.7)", "width": 2.5, "cap": "round", "join": "round",
                                      "miter": 10, "dash": [2, 1], "offset": 0})j"));
  EXPECT_EQ(ops[1], nlohmann::json::parse(R"(["g", 1, [0, 5.12, 6, 0, 7, 6]])"));
  EXPECT_EQ(canvas.styles()[1], nlohmann::json::parse(R"j({"fill": "rgba(255,0,0,1)"})j"));
  EXPECT_EQ(canvas.glyphs()[0], "M 1 0 @1 M 1 0 @2");
  EXPECT_EQ(canvas.paths()[1], "l 1 0 l 0 1 z");
  EXPECT_THROW((void)canvas.layer("<svg><g><image width=\"2\" height=\"2\"/></g></svg>"), std::logic_error);
  EXPECT_THROW((void)canvas.layer("<svg><g><path style=\"fill:red;\" d=\"M 0 0 L 1 1\"/></g></svg>"), std::logic_error);
}

}  // namespace
}  // namespace linkage
