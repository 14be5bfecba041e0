#pragma once
// Everything drawn in frame coordinates rather than world ones: the background grid and
// axis ticks, the title, the legend (with each arrow scale), the scale bar and the HUD.
// All but the HUD are the same in every frame, so the raster renderer draws them once.
#include <cairo.h>

#include <array>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/style.hpp"
#include "scene/arrow_scale.hpp"

namespace linkage {

/// A rectangle in pixels; x, y is the top-left corner.
struct Rect {
  double x = 0, y = 0, width = 0, height = 0;
  [[nodiscard]] bool empty() const { return width <= 0 || height <= 0; }
};

/// A metric grid: lines every `spacing` through `anchor` (world point).
struct GridSpec {
  RoundLength spacing;
  Vec2 anchor = Vec2::Zero();
  bool relative = false;    // ticks count from the anchor (a camera falling with G)
  bool name_every = false;  // every horizontal line named "y = −44.2 m" (a camera following a fall)
  bool x_ticks = true;      // ticks along the bottom edge too
};
/// Grid lines about every `lines`-th of the frame's smaller side, at a round spacing.
[[nodiscard]] RoundLength grid_spacing_for(const Camera& camera, int width, int height, double lines = 10);

void paint_background(cairo_t* cr, const DrawStyle& style, int width, int height);
/// A box in the theme's panel colours: `r` with corners of `radius`, filled, its edge
/// stroked `edge` wide (legend, HUD, caption and equation boxes alike).
void paint_box(cairo_t* cr, const DrawStyle& style, const Rect& r, double radius, double edge);
/// With `earlier` (the camera at the start of the frame's shutter interval, for a camera
/// that moves), each line is drawn motion-blurred: a band from where it was then to where
/// it is now, most opaque at now, as much ink as the still line and no less than
/// kGridStreakOpacity spread over a spacing, so lines that move more than half a spacing
/// a frame do not appear to jump (temporal aliasing) but streak the way they move.
void paint_grid(cairo_t* cr, const DrawStyle& style, const Camera& camera, const GridSpec& grid, int width, int height,
                const Camera* earlier = nullptr);
/// The opacity a streaking grid line keeps at its newest end while its band is shorter
/// than a spacing (it falls as spacing / band beyond).
inline constexpr double kGridStreakOpacity = 0.5;
/// A still line's opacity at the newest end of a band `band` px long (width `line` px),
/// `spacing` px between lines: the line's ink spread over the band, at least
/// kGridStreakOpacity x min(1, spacing / band); 1 when the band is under a pixel.
[[nodiscard]] double grid_streak_opacity(double band, double line, double spacing);
/// Coordinate ticks in metres along the bottom and left edges, at the grid lines, except
/// where a label would touch one of the `avoid` rectangles (the panels). One tick per
/// axis names it: "x = 1.2 m" (or "Δx = 0.1 m" counted from G for a following camera).
void paint_axes(cairo_t* cr, const DrawStyle& style, const Camera& camera, const GridSpec& grid, int width, int height,
                const std::vector<Rect>& avoid);

/// A corner box (top right, from `top` down): a panel with a caption over a plot area.
struct Inset {
  Rect rect;  // the panel
  Rect plot;  // inside it, under the caption
  std::string caption;
};
[[nodiscard]] Inset inset_layout(cairo_t* cr, const DrawStyle& style, std::string caption, double top, int width);
/// The panel and its caption.
void paint_inset_frame(cairo_t* cr, const DrawStyle& style, const Inset& inset);

/// The lab-frame inset of a following camera: the whole path of G over the clip, the
/// part travelled drawn strong, and G now marked on it.
struct PathInset {
  Inset inset;
  Camera camera;           // world to pixels of a plot-sized frame
  std::vector<Vec2> path;  // G at even times over the clip, oldest first
  [[nodiscard]] Vec2 to_pixels(const Vec2& world) const {
    return camera.to_pixels(world) + Vec2(inset.plot.x, inset.plot.y);
  }
};
/// Fits `path` (at least two points) into `inset`'s plot area at one scale.
[[nodiscard]] PathInset path_inset(Inset inset, std::vector<Vec2> path);
/// `travelled`: how many points of the path are behind G now.
void paint_path_inset(cairo_t* cr, const DrawStyle& style, const PathInset& inset, const Vec2& now,
                      std::size_t travelled);

/// Where the title goes (top left) and its font size, shrunk to fit the frame's width.
struct TitleLayout {
  Rect rect;
  double font_size = 0;
};
[[nodiscard]] TitleLayout title_layout(cairo_t* cr, const DrawStyle& style, const std::string& title, int width);
void paint_title(cairo_t* cr, const DrawStyle& style, const std::string& title, const TitleLayout& layout);
/// The box, in user space, of every pixel paint_title may touch (its halo's stroke and its fill).
[[nodiscard]] Rect title_ink(cairo_t* cr, const DrawStyle& style, const std::string& title, const TitleLayout& layout);
/// The state paint_title leaves (font, colour, pen), set without drawing: for a title copied from a cache.
void title_pen(cairo_t* cr, const DrawStyle& style, const TitleLayout& layout);

/// A legend row: a glyph in a colour, a name, and a note (an arrow scale).
struct LegendRow {
  enum class Glyph { arrow, stretched_arrow, line, com, outline, dashed_outline, none };
  Glyph glyph = Glyph::none;
  Rgba colour;
  std::string name;
  std::string note;
};
/// The legend, bottom left.
[[nodiscard]] Rect legend_rect(cairo_t* cr, const DrawStyle& style, const std::vector<LegendRow>& rows, int height);
void paint_legend(cairo_t* cr, const DrawStyle& style, const std::vector<LegendRow>& rows, const Rect& rect);

/// The scale bar, bottom right: `length_px` pixels labelled `label` ("10 cm").
[[nodiscard]] Rect scale_bar_rect(cairo_t* cr, const DrawStyle& style, const std::string& label, double length_px,
                                  int width, int height);
void paint_scale_bar(cairo_t* cr, const DrawStyle& style, const std::string& label, double length_px, const Rect& rect);

/// The HUD's text for one frame: fixed buffers, so a frame allocates nothing.
struct HudText {
  std::array<char, 32> time{};        // "t = 1.23 s"
  std::array<char, 64> run{};         // "Case 3 · dop853"
  std::array<char, 32> energy{};      // "+1.2e−13"; empty: no energy row
  std::array<char, 32> constraint{};  // "3.4e−16 m"; empty: no constraint row
};
/// Fills the time and error fields.
void format_hud(HudText& hud, double t, double energy_error, double constraint_error);
/// The HUD panel, top right, wide enough for any values.
[[nodiscard]] Rect hud_rect(cairo_t* cr, const DrawStyle& style, const HudText& hud, int width);
void paint_hud(cairo_t* cr, const DrawStyle& style, const HudText& hud, const Rect& rect);

}  // namespace linkage
