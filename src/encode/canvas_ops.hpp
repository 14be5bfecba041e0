#pragma once
// Cairo's SVG of a layer as the page's canvas operations (`linkage render --out clip.html`).
// The page paints them with Path2D onto its canvas: Cairo's own paths, with no SVG document
// for the browser to parse and rasterize each frame (that took 25-60 ms a frame in Chromium;
// these take a few). The operations of a layer are a JSON array of
//   ["p", style, d]            fill and/or stroke path data d (absolute M, relative l c z)
//   ["p", style, d, [a..f]]    the same under the matrix a b c d e f
//   ["g", style, [i, x, y...]] fill glyph i's outline at (x, y), for each glyph of a run
//   ["c", d, rule, ops]        ops clipped to d (rule "nonzero" or "evenodd")
// where `style` indexes styles(), glyph i indexes glyphs(), and "@N" in path data is the
// book's entry N (paths()): a subpath's commands, relative to its start, kept once.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace linkage {

/// The pieces of every path of every layer, each kept once. A subpath (a glyph's contour, a
/// pin's circle) is written as its start, absolute, and a book entry: its commands relative,
/// in whole hundredths of a pixel from that exact start, so the same shape elsewhere is the
/// same entry (a label's "0.9" in another place or frame).
class PathBook {
 public:
  /// Cairo's path data (M, L, C, Z with absolute coordinates) as "M x y @N ...", each
  /// subpath's commands replaced by its entry; data of other commands is kept as it is.
  [[nodiscard]] std::string compact(std::string_view data);
  [[nodiscard]] const std::vector<std::string>& entries() const { return entries_; }

 private:
  std::unordered_map<std::string, std::size_t> index_;
  std::vector<std::string> entries_;
};

/// Converts layers of Cairo's SVG output (the subset its SVG surface writes: path, rect,
/// glyph symbols and their uses, clip paths, linear gradients) into canvas operations,
/// keeping each style, gradient, glyph and subpath once for all of them.
class CanvasOps {
 public:
  /// The operations of one finished SVG surface; empty when it draws nothing. Anything
  /// outside the subset is an internal error (std::logic_error naming it).
  [[nodiscard]] nlohmann::json layer(std::string_view svg);

  /// Each style: "fill" (a CSS colour) or "gradient" (an index of gradients()), "rule"
  /// ("evenodd"; nonzero when absent), "stroke", "width", "cap", "join", "miter", "dash",
  /// "offset".
  [[nodiscard]] const nlohmann::json& styles() const { return styles_; }
  /// Each linear gradient: "line" [x1, y1, x2, y2] and "stops" [[offset, colour], ...].
  [[nodiscard]] const nlohmann::json& gradients() const { return gradients_; }
  /// Each glyph's outline (path data, in the book's form) at the origin of its run.
  [[nodiscard]] const std::vector<std::string>& glyphs() const { return glyphs_; }
  [[nodiscard]] const std::vector<std::string>& paths() const { return book_.entries(); }

 private:
  friend class SvgLayerReader;
  std::size_t style(const nlohmann::json& style);
  std::size_t gradient(const nlohmann::json& gradient);
  std::size_t glyph(const std::string& data);

  PathBook book_;
  nlohmann::json styles_ = nlohmann::json::array(), gradients_ = nlohmann::json::array();
  std::vector<std::string> glyphs_;
  std::unordered_map<std::string, std::size_t> style_index_, gradient_index_, glyph_index_;
};

}  // namespace linkage
