// The page's frames (frame_canvas_ops): Cairo's SVG of each layer read back as the canvas
// operations the page paints. Painted again by Cairo from those operations alone, a frame
// is the frame Cairo paints directly: the reading keeps every path, glyph, style, clip and
// gradient, moved by no more than its hundredth-of-a-pixel rounding.
#include "pipeline/clip_page.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "model/mechanism_toml.hpp"
#include "pipeline/clip_support.hpp"
#include "render/cairo_util.hpp"
#include "render/paint_layer.hpp"
#include "render/theme.hpp"
#include "support/test_support.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

/// Path data as the page has it ("M x y @N ...", the book's entries relative) onto `cr`.
void add_path(cairo_t* cr, const std::string& data, const std::vector<std::string>& book) {
  std::string text;
  for (std::size_t i = 0; i < data.size();) {  // the book's entries put back
    if (data[i] == '@') {
      std::size_t end = i + 1;
      while (end < data.size() && data[end] >= '0' && data[end] <= '9') ++end;
      text += book.at(std::stoul(data.substr(i + 1, end - i - 1)));
      i = end;
    } else {
      text += data[i++];
    }
  }
  std::istringstream in(text);
  std::string command;
  while (in >> command) {
    double v[6] = {};
    if (command == "M") {
      in >> v[0] >> v[1];
      cairo_move_to(cr, v[0], v[1]);
    } else if (command == "l") {
      in >> v[0] >> v[1];
      cairo_rel_line_to(cr, v[0], v[1]);
    } else if (command == "c") {
      for (double& x : v) in >> x;
      cairo_rel_curve_to(cr, v[0], v[1], v[2], v[3], v[4], v[5]);
    } else if (command == "z") {
      cairo_close_path(cr);
    } else {
      FAIL() << "path command " << command << " in " << data;
    }
  }
}

void set_colour(cairo_t* cr, const std::string& css) {  // "rgba(r,g,b,a)"
  double c[4] = {};
  ASSERT_EQ(std::sscanf(css.c_str(), "rgba(%lf,%lf,%lf,%lf)", &c[0], &c[1], &c[2], &c[3]), 4) << css;
  cairo_set_source_rgba(cr, c[0] / 255, c[1] / 255, c[2] / 255, c[3]);
}

/// Paints `ops` as the page's painter does, with Cairo.
void replay(cairo_t* cr, const nlohmann::json& ops, const CanvasOps& canvas) {
  for (const nlohmann::json& op : ops) {
    const std::string kind = op[0];
    if (kind == "c") {
      cairo_save(cr);
      cairo_new_path(cr);
      add_path(cr, op[1], canvas.paths());
      cairo_set_fill_rule(cr, op[2] == "evenodd" ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
      cairo_clip(cr);
      replay(cr, op[3], canvas);
      cairo_restore(cr);
      continue;
    }
    const nlohmann::json& style = canvas.styles().at(op[1].get<std::size_t>());
    cairo_set_fill_rule(cr, style.value("rule", "") == "evenodd" ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
    std::unique_ptr<cairo_pattern_t, decltype(&cairo_pattern_destroy)> gradient(nullptr, cairo_pattern_destroy);
    const auto set_fill = [&] {
      if (!style.contains("gradient")) return set_colour(cr, style["fill"]);
      const nlohmann::json& g = canvas.gradients().at(style["gradient"].get<std::size_t>());
      gradient.reset(cairo_pattern_create_linear(g["line"][0], g["line"][1], g["line"][2], g["line"][3]));
      for (const nlohmann::json& stop : g["stops"]) {
        double c[4] = {};
        ASSERT_EQ(std::sscanf(stop[1].get<std::string>().c_str(), "rgba(%lf,%lf,%lf,%lf)", &c[0], &c[1], &c[2], &c[3]),
                  4);
        cairo_pattern_add_color_stop_rgba(gradient.get(), stop[0], c[0] / 255, c[1] / 255, c[2] / 255, c[3]);
      }
      cairo_set_source(cr, gradient.get());
    };
    if (kind == "g") {
      set_fill();
      const nlohmann::json& run = op[2];
      for (std::size_t i = 0; i + 2 < run.size(); i += 3) {
        cairo_save(cr);
        cairo_translate(cr, run[i + 1], run[i + 2]);
        cairo_new_path(cr);
        add_path(cr, canvas.glyphs().at(run[i].get<std::size_t>()), canvas.paths());
        cairo_fill(cr);
        cairo_restore(cr);
      }
      continue;
    }
    ASSERT_EQ(kind, "p");
    cairo_save(cr);
    if (op.size() > 3) {
      cairo_matrix_t m;
      cairo_matrix_init(&m, op[3][0], op[3][1], op[3][2], op[3][3], op[3][4], op[3][5]);
      cairo_transform(cr, &m);
    }
    cairo_new_path(cr);
    add_path(cr, op[2], canvas.paths());
    if (style.contains("fill") || style.contains("gradient")) {
      set_fill();
      cairo_fill_preserve(cr);
    }
    if (style.contains("stroke")) {
      set_colour(cr, style["stroke"]);
      cairo_set_line_width(cr, style["width"]);
      const std::string cap = style["cap"], join = style["join"];
      cairo_set_line_cap(cr, cap == "round"    ? CAIRO_LINE_CAP_ROUND
                             : cap == "square" ? CAIRO_LINE_CAP_SQUARE
                                               : CAIRO_LINE_CAP_BUTT);
      cairo_set_line_join(cr, join == "round"   ? CAIRO_LINE_JOIN_ROUND
                              : join == "bevel" ? CAIRO_LINE_JOIN_BEVEL
                                                : CAIRO_LINE_JOIN_MITER);
      cairo_set_miter_limit(cr, style["miter"]);
      std::vector<double> dash;
      if (style.contains("dash")) dash = style["dash"].get<std::vector<double>>();
      cairo_set_dash(cr, dash.data(), static_cast<int>(dash.size()), style.value("offset", 0.0));
      cairo_stroke_preserve(cr);
    }
    cairo_new_path(cr);
    cairo_restore(cr);
  }
}

struct Seen {  // which kinds of operation a frame used
  bool glyphs = false, clip = false, gradient = false, transform = false, dash = false;
};

void note(const nlohmann::json& ops, const CanvasOps& canvas, Seen& seen) {
  for (const nlohmann::json& op : ops) {
    if (op[0] == "c") {
      seen.clip = true;
      note(op[3], canvas, seen);
      continue;
    }
    const nlohmann::json& style = canvas.styles().at(op[1].get<std::size_t>());
    seen.glyphs |= op[0] == "g";
    seen.gradient |= style.contains("gradient");
    seen.dash |= style.contains("dash");
    seen.transform |= op.size() > 3;
  }
}

bool has_glyphs(const nlohmann::json& ops) {
  return std::any_of(ops.begin(), ops.end(),
                     [](const nlohmann::json& op) { return op[0] == "g" || (op[0] == "c" && has_glyphs(op[3])); });
}

/// A layer's coverage (its pixels' alpha summed) and darkness (alpha less the mean of its
/// premultiplied colour, summed: 0 for white or nothing, 1 for opaque black), in pixels.
std::array<double, 2> ink(const Frame& f) {
  std::array<double, 2> sum{};
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const std::uint32_t p = f.pixel(x, y);
      const double a = (p >> 24) / 255.0, rgb = (((p >> 16) & 0xff) + ((p >> 8) & 0xff) + (p & 0xff)) / 765.0;
      sum[0] += a;
      sum[1] += a - rgb;
    }
  return sum;
}

/// Pixels where any channel (premultiplied) differs by more than 64 of 255.
long pixels_apart(const Frame& a, const Frame& b) {
  long over = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::uint32_t p = a.pixel(x, y), q = b.pixel(x, y);
      for (int shift = 0; shift < 32; shift += 8)
        if (std::abs(static_cast<int>((p >> shift) & 0xff) - static_cast<int>((q >> shift) & 0xff)) > 64) {
          ++over;
          break;
        }
    }
  return over;
}

/// Each layer of frame k of `clip` painted by Cairo directly and from the page's operations.
/// Glyphs differ by design: Cairo's image surface draws a glyph from FreeType's bitmap at
/// a whole pixel, the page fills its outline where it is (as the browser does); so a layer
/// with glyphs is held to its coverage (a glyph left out of 60 moves it 1.5%), the others
/// to their pixels.
Seen expect_same_frame(const std::string& mechanism, MechanismClip clip, std::size_t k) {
  const sym::System system(load_mechanism(mechanism));
  ClipResult result;
  MechanismClipFrames frames(system, sym::checked_initial_state(system).state, clip, result);
  const int w = clip.settings.width, h = clip.settings.height;
  std::vector<Frame> direct(kPaintLayers, Frame(w, h));
  {
    std::vector<cairo::SurfacePtr> surfaces;
    std::vector<cairo::ContextPtr> contexts;
    for (Frame& f : direct) {
      surfaces.push_back(cairo::surface_for(f));
      contexts.push_back(cairo::context(surfaces.back().get()));
    }
    frames.draw_layers(k, [&](PaintLayer layer) { return contexts[static_cast<std::size_t>(layer)].get(); });
  }
  CanvasOps canvas;
  const std::array<nlohmann::json, kPaintLayers> layers = frame_canvas_ops(frames, k, clip.settings, canvas);
  Seen seen;
  for (std::size_t i = 0; i < kPaintLayers; ++i) {
    SCOPED_TRACE(mechanism + " frame " + std::to_string(k) + " layer " + std::string(name(static_cast<PaintLayer>(i))));
    note(layers[i], canvas, seen);
    Frame replayed(w, h);
    {
      cairo::SurfacePtr surface = cairo::surface_for(replayed);
      cairo::ContextPtr cr = cairo::context(surface.get());
      replay(cr.get(), layers[i], canvas);
    }
    const std::array<double, 2> a = ink(direct[i]), b = ink(replayed);
    EXPECT_EQ(layers[i].empty(), a[0] == 0);  // a layer with ink has operations, one without none
    // Measured: coverage and darkness within 0.3 px + 0.1% with glyphs; without, no pixel
    // 64 apart but 3 of 58,000 in a grid fading out in a gradient.
    if (has_glyphs(layers[i])) {
      EXPECT_NEAR(b[0], a[0], 0.002 * a[0] + 2) << "coverage";
      EXPECT_NEAR(b[1], a[1], 0.002 * a[1] + 2) << "darkness";
    } else {
      EXPECT_LE(pixels_apart(direct[i], replayed), 10 + static_cast<long>(0.002 * a[0])) << "pixels apart of " << a[0];
    }
  }
  return seen;
}

MechanismClip small_clip(const std::string& mechanism) {
  return test::small_clip(sym::System(load_mechanism(mechanism)));
}

TEST(ClipPage, TheFourBarsOperationsPaintItsFrameWithItsPanel) {
  MechanismClip clip = small_clip("four-bar");
  clip.settings.panel = {"2.theta", "B.force_x"};
  clip.settings.elements.show(Element::velocity);
  const Seen seen = expect_same_frame("four-bar", clip, 20);
  EXPECT_TRUE(seen.glyphs);
  EXPECT_TRUE(seen.clip);  // the panel's plots
  EXPECT_TRUE(seen.dash);  // the legend's dashed arrow
}

TEST(ClipPage, TheHomeworksOperationsPaintItsFrameWithItsGradients) {
  MechanismClip clip = small_clip("two-blocks");
  clip.settings.theme = "dark";
  clip.theme = load_theme("dark", {}, "theme");
  const Seen seen = expect_same_frame("two-blocks", clip, 25);
  EXPECT_TRUE(seen.gradient);  // a following camera's grid fades out at its edges
  EXPECT_TRUE(seen.glyphs);
}

TEST(ClipPage, AnEnsemblesOperationsPaintItsFrameWithAPanelBesideIt) {
  MechanismClip clip = small_clip("cart-pendulum");
  clip.settings.width = 1280;
  clip.settings.height = 720;
  clip.settings.panel = {"cart.x"};
  clip.settings.elements.show(Element::acceleration);
  clip.ensemble = 5;
  clip.spread = 0.1;
  const Seen seen = expect_same_frame("cart-pendulum", clip, 10);
  EXPECT_TRUE(seen.transform);  // the panel's axes, stroked in its own coordinates
}

}  // namespace
}  // namespace linkage
