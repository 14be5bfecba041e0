#pragma once
// Plot text with Cairo's toy text API in DejaVu Sans (no Pango here). A small markup
// gives superscripts and subscripts, drawn smaller and raised or lowered:
//   "10^{-8}", "a (m s^{-2})", "θ_{1} (rad)".
// Only "^{" and "_{" with a matching "}" are markup; everything else is literal. A '-'
// inside a script is drawn as a minus sign (U+2212).
#include <cairo.h>

#include <string>
#include <string_view>
#include <vector>

namespace linkage::plot {

/// A stretch of text on one baseline.
struct TextRun {
  enum class Shift { none, superscript, subscript };
  std::string text;
  Shift shift = Shift::none;
};

/// The runs of `markup`, in order; empty runs are left out.
[[nodiscard]] std::vector<TextRun> parse_markup(std::string_view markup);

/// Font of a piece of plot text; size in device units (pixels or points).
struct Font {
  double size = 14;
  bool bold = false;
};

/// Extent of a text around its baseline. Heights come from the font (cap height and
/// descent), not from the glyphs' ink, so labels line up whatever letters they hold.
struct TextExtent {
  double width = 0;
  double ascent = 0;   ///< Above the baseline.
  double descent = 0;  ///< Below the baseline.
  [[nodiscard]] double height() const { return ascent + descent; }
};

/// Horizontal placement of text relative to its anchor x.
enum class Align { start, center, end };

/// Grey-scale antialiasing without hinting, so text lays out identically on PNG, SVG
/// and PDF surfaces and renders the same bytes every time.
void set_plot_font_options(cairo_t* cr);

/// Height of a capital letter (and of digits) in `font`.
[[nodiscard]] double cap_height(cairo_t* cr, const Font& font);

/// Measures `markup` set in `font`.
[[nodiscard]] TextExtent measure_text(cairo_t* cr, std::string_view markup, const Font& font);

/// Draws `markup` in the current source colour with its baseline at `baseline`.
void draw_text(cairo_t* cr, std::string_view markup, const Font& font, double x, double baseline, Align align);

}  // namespace linkage::plot
