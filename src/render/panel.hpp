#pragma once
// Words in and beside the picture: a live plot of chosen quantities next to the motion
// (the curve so far, the rest dotted, a cursor at the frame's time) and a caption
// along the bottom of the frame. Both are drawn in frame coordinates over a finished
// frame, so the homework's clips and any mechanism's share them.
#include <cairo.h>

#include <cstddef>
#include <string>
#include <vector>

#include "core/angle_unit.hpp"
#include "render/overlays.hpp"
#include "render/plot.hpp"
#include "render/settings.hpp"
#include "render/style.hpp"

namespace linkage {

/// One quantity of the panel: its words in plot markup ("θ_{1}") and unit ("rad", or
/// empty for a pure number), and its value at each sample of the motion.
struct PanelCurve {
  std::string label;
  std::string unit;
  std::vector<double> values;
};

/// What the panel plots: the sample times and one curve per chosen quantity.
struct PanelData {
  std::vector<double> t;
  std::vector<PanelCurve> curves;
  double t_end = 0;  // s, the right end of the time axis (the clip's duration, or a still's time)
  [[nodiscard]] bool empty() const { return curves.empty(); }
};

/// The curves with angular units ("rad", "rad/s", "rad/s^{2}") in `angles`: values
/// times 180/π and "deg..." units for degrees; nothing changes for radians.
void convert_angles(PanelData& data, AngleUnit angles);

/// Where the motion and the panel go in a width x height frame: the panel to the right
/// of a landscape frame (wider than 4:3), below otherwise; no panel: the whole frame.
struct PanelLayout {
  Rect scene;
  Rect panel;
};
[[nodiscard]] PanelLayout panel_layout(int width, int height, bool with_panel);

/// A y-axis label for several curves: their shared unit after the words they begin
/// with ("pin force F_{x}", "pin force F_{y}" -> "pin force (N)"; words ending in a
/// comma name the parts after it: "force of joint B on body 3, x and y (N)"), else the labels
/// joined when short ("θ_{1}, θ_{2} (rad)"), else "value"; the unit only when all share it.
[[nodiscard]] std::string shared_axis_label(const std::vector<std::string>& labels,
                                            const std::vector<std::string>& units);

/// The plot the panel shows at sample `index`: axes in words and units, limits fixed
/// over the whole data (so they do not jump from frame to frame), the curves up to
/// `index` solid and the rest dotted without a legend entry.
[[nodiscard]] plot::Plot panel_plot(const PanelData& data, std::size_t index, bool dark);

/// The curves by unit, in order of first appearance: each group shares one axis.
[[nodiscard]] std::vector<std::vector<std::size_t>> unit_groups(const PanelData& data);

/// The sample to show at time t: the last at or before it (the panel may be sampled more
/// finely than the frames).
[[nodiscard]] std::size_t panel_index(const PanelData& data, double t);

/// Where one of the panel's stacked plots put its data, in the frame's pixels (the
/// page's hover reads values there), and which curves it shows.
struct PanelPart {
  Rect area;            // the data area
  plot::AxisMap time;   // t onto x
  plot::AxisMap value;  // the curves' values onto y
  std::vector<std::size_t> curves;
};

/// Paints the panel for sample `index` into `rect`, one plot per unit stacked (each axis
/// its quantity and unit), with a cursor line at its time and a dot on each curve;
/// returns where the lowest plot put its data. `parts`: every plot's, top to bottom.
plot::Report paint_panel(cairo_t* cr, const DrawStyle& style, const PanelData& data, std::size_t index,
                         const Rect& rect, std::vector<PanelPart>* parts = nullptr);

/// The caption shown at time t: the last one that starts at or before t ("" if none).
[[nodiscard]] const std::string& caption_at(const std::vector<Caption>& captions, double t);

/// Lines of `text` in `font`, broken at spaces so none is wider than `max_width`
/// (a word wider than that stays whole on its own line).
[[nodiscard]] std::vector<std::string> wrap_text(cairo_t* cr, double font_size, const std::string& text,
                                                 double max_width);

/// Height of a band under the picture that holds the longest of `captions`, wrapped to
/// `width` (0 when there are none).
[[nodiscard]] double caption_band_height(cairo_t* cr, const DrawStyle& style, const std::vector<Caption>& captions,
                                         double width);
/// Paints the band `area` in the background colour and `text` centred in it, wrapped.
void paint_caption(cairo_t* cr, const DrawStyle& style, const std::string& text, const Rect& area);

}  // namespace linkage
