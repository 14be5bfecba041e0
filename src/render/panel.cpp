#include "render/panel.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "render/overlays.hpp"
#include "render/text.hpp"

namespace linkage {
namespace {

constexpr double kPanelShare = 0.4;     // of the frame's width (beside) or height (below)
constexpr double kLandscape = 4.0 / 3;  // wider than this: the panel goes beside
constexpr double kSmallestPart = 120;   // device units: the least height of one of stacked plots

std::string with_unit(const std::string& label, const std::string& unit) {
  return unit.empty() ? label : label + " (" + unit + ")";
}

/// Fixed limits over every value of the curves `which`, padded by 6 % (or by 1 when the
/// data is flat).
std::pair<double, double> value_limits(const PanelData& data, const std::vector<std::size_t>& which) {
  double lo = 1e300, hi = -1e300;
  for (const std::size_t k : which)
    for (double v : data.curves[k].values)
      if (std::isfinite(v)) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
  if (lo > hi) return {-1, 1};
  const double pad = hi > lo ? 0.06 * (hi - lo) : std::max(1e-12, 0.5 * std::fabs(hi));
  return {lo - pad, hi + pad};
}

}  // namespace

std::string shared_axis_label(const std::vector<std::string>& labels, const std::vector<std::string>& units) {
  constexpr std::size_t kLongest = 48;  // characters of markup that still fit beside a plot
  if (labels.empty()) return "value";
  const bool same_unit = std::all_of(units.begin(), units.end(), [&](const std::string& u) { return u == units[0]; });
  const std::string unit = same_unit && !units.empty() ? units[0] : "";
  // The whole words every label begins with.
  std::size_t common = labels[0].size();
  for (const std::string& label : labels) {
    std::size_t n = 0;
    while (n < common && n < label.size() && label[n] == labels[0][n]) ++n;
    common = n;
  }
  std::string words;
  if (common == labels[0].size() && labels.size() > 1 &&
      std::all_of(labels.begin(), labels.end(), [&](const std::string& l) { return l.size() == common; }))
    words = labels[0];  // all the same
  else if (const std::size_t space = labels[0].rfind(' ', common); space != std::string::npos && space > 0)
    words = labels[0].substr(0, space);
  // Words that end in a comma name parts after it ("force of joint B on body 3, x"):
  // name them all ("..., x and y"), never leave the comma dangling.
  if (!words.empty() && words.back() == ',') {
    std::string parts;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (i > 0) parts += i + 1 == labels.size() ? " and " : ", ";
      const std::size_t part = labels[i].find_first_not_of(' ', words.size());
      if (part != std::string::npos) parts += labels[i].substr(part);
    }
    words.pop_back();
    if (words.size() + parts.size() + 2 <= kLongest) {
      words += ", ";
      words += parts;
    }
  }
  if (words.empty()) {
    for (const std::string& label : labels) {
      if (!words.empty()) words += ", ";
      words += label;
    }
    if (words.size() > kLongest) words = "value";
  }
  return with_unit(words, unit);
}

PanelLayout panel_layout(int width, int height, bool with_panel) {
  const double w = width, h = height;
  if (!with_panel) return {{0, 0, w, h}, {}};
  if (w > kLandscape * h) {
    const double side = std::round(kPanelShare * w);
    return {{0, 0, w - side, h}, {w - side, 0, side, h}};
  }
  const double below = std::round(kPanelShare * h);
  return {{0, 0, w, h - below}, {0, h - below, w, below}};
}

namespace {

/// What tells each label from the others: what follows the whole words all of them begin
/// with, and the last of those words before a number ("force of joint O2 on the ground,
/// x" -> "x"; "angle θ of body 2" -> "body 2"); the labels themselves when no word is
/// shared.
std::vector<std::string> distinguishing_words(const std::vector<std::string>& labels) {
  if (labels.size() < 2) return labels;
  std::size_t common = labels[0].size();
  for (const std::string& label : labels) {
    std::size_t n = 0;
    while (n < common && n < label.size() && label[n] == labels[0][n]) ++n;
    common = n;
  }
  const std::size_t space = labels[0].rfind(' ', common);
  if (space == std::string::npos || space == 0) return labels;
  std::size_t cut = space + 1;  // after the last shared word
  const bool numbered = std::any_of(labels.begin(), labels.end(), [&](const std::string& l) {
    return cut < l.size() && std::isdigit(static_cast<unsigned char>(l[cut]));
  });
  if (numbered && labels[0][space - 1] != ',') {
    const std::size_t before = labels[0].rfind(' ', space - 1);
    cut = before == std::string::npos ? 0 : before + 1;  // keep that word
  }
  std::vector<std::string> out;
  for (const std::string& label : labels) {
    if (cut >= label.size()) return labels;
    out.push_back(label.substr(cut));
  }
  return out;
}

/// The plot of the curves `which` (all of one unit) at sample `index`; each curve keeps
/// its colour slot by its place in `data`.
plot::Plot curves_plot(const PanelData& data, const std::vector<std::size_t>& which, std::size_t index, bool dark,
                       bool time_label) {
  plot::Plot p;
  p.theme = dark ? plot::Theme::dark : plot::Theme::light;
  p.x.label = time_label ? "time t (s)" : "";
  p.x.min = data.t.empty() ? 0.0 : std::min(0.0, data.t.front());
  p.x.max = std::max(data.t_end, *p.x.min + 0.1);  // a still at t = 0 still has an axis
  const auto [lo, hi] = value_limits(data, which);
  p.y.min = lo;
  p.y.max = hi;
  // One curve: its words on the axis. Several: each in the legend, the axis names the
  // shared unit (or none when the units differ).
  const bool one = which.size() == 1;
  std::vector<std::string> labels, units;
  for (const std::size_t k : which) {
    labels.push_back(data.curves[k].label);
    units.push_back(data.curves[k].unit);
  }
  p.y.label = one ? with_unit(labels[0], units[0]) : shared_axis_label(labels, units);
  p.legend = one ? plot::LegendPlace::none : plot::LegendPlace::best;
  // The axis names the words the curves share and their unit: the legend names the rest.
  const std::vector<std::string> legend_names = distinguishing_words(labels);
  std::size_t k = 0;
  const std::size_t n = data.t.size();
  const std::size_t now = std::min(index, n == 0 ? 0 : n - 1);
  for (const std::size_t c : which) {
    const PanelCurve& curve = data.curves[c];
    plot::Series past, ahead;
    past.name = one ? "" : with_unit(legend_names[k++], curve.unit);
    past.color = ahead.color = c % plot::palette_size;
    ahead.dash = plot::Dash::dotted;
    for (std::size_t i = 0; i < n && i < curve.values.size(); ++i) {
      const plot::Point point{data.t[i], curve.values[i]};
      if (i <= now) past.points.push_back(point);
      if (i >= now) ahead.points.push_back(point);
    }
    p.series.push_back(std::move(past));
    if (ahead.points.size() > 1) p.series.push_back(std::move(ahead));
  }
  return p;
}

}  // namespace

std::vector<std::vector<std::size_t>> unit_groups(const PanelData& data) {
  std::vector<std::vector<std::size_t>> groups;
  std::vector<std::string> units;
  for (std::size_t c = 0; c < data.curves.size(); ++c) {
    const auto it = std::find(units.begin(), units.end(), data.curves[c].unit);
    if (it == units.end()) {
      units.push_back(data.curves[c].unit);
      groups.push_back({c});
    } else {
      groups[static_cast<std::size_t>(it - units.begin())].push_back(c);
    }
  }
  return groups;
}

plot::Plot panel_plot(const PanelData& data, std::size_t index, bool dark) {
  std::vector<std::size_t> all(data.curves.size());
  for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
  return curves_plot(data, all, index, dark, true);
}

std::size_t panel_index(const PanelData& data, double t) {
  const auto after = std::upper_bound(data.t.begin(), data.t.end(), t + 1e-9);
  return after == data.t.begin() ? 0 : static_cast<std::size_t>(after - data.t.begin()) - 1;
}

plot::Report paint_panel(cairo_t* cr, const DrawStyle& style, const PanelData& data, std::size_t index,
                         const Rect& rect, std::vector<PanelPart>* parts) {
  const Rgba& bg = style.theme->background;
  const bool dark = 0.2126 * bg.r + 0.7152 * bg.g + 0.0722 * bg.b < 0.5;
  // Quantities of different units never share an axis: one plot per unit, stacked, the
  // time axis named on the lowest.
  std::vector<std::vector<std::size_t>> groups = unit_groups(data);
  // A panel too small to stack (a thumbnail) keeps one axis: its label then names no unit.
  if (groups.empty() || rect.height / static_cast<double>(groups.size()) < kSmallestPart)
    groups = std::vector<std::vector<std::size_t>>(1);
  const double height = rect.height / static_cast<double>(groups.size());
  plot::Report report;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const bool lowest = g + 1 == groups.size();
    const Rect part{rect.x, rect.y + height * static_cast<double>(g), rect.width, height};
    if (groups[g].empty())
      for (std::size_t c = 0; c < data.curves.size(); ++c) groups[g].push_back(c);
    const plot::Plot p = curves_plot(data, groups[g], index, dark, lowest);
    const plot::Canvas canvas{std::max(100.0, part.width), std::max(100.0, part.height),
                              std::clamp(style.text_size(), 4.0, 200.0)};
    cairo_save(cr);
    cairo_rectangle(cr, part.x, part.y, part.width, part.height);
    cairo_clip(cr);
    cairo_translate(cr, part.x, part.y);
    report = plot::draw(cr, p, canvas, "panel");
    if (parts != nullptr) {
      const plot::Geometry& at = report.geometry;
      PanelPart drawn{
          {part.x + at.left, part.y + at.top, at.right - at.left, at.bottom - at.top}, at.x, at.y, groups[g]};
      drawn.time.from += part.x;
      drawn.time.to += part.x;
      drawn.value.from += part.y;
      drawn.value.to += part.y;
      parts->push_back(std::move(drawn));
    }
    // The cursor: a line at the frame's time and a dot on each curve there.
    if (!data.t.empty()) {
      const std::size_t now = std::min(index, data.t.size() - 1);
      const plot::Geometry& geometry = report.geometry;
      const double x = geometry.x(data.t[now]);
      set_colour(cr, with_alpha(style.theme->text, 0.55));
      cairo_set_line_width(cr, std::max(1.0, 1.2 * style.u));
      cairo_move_to(cr, x, geometry.top);
      cairo_line_to(cr, x, geometry.bottom);
      cairo_stroke(cr);
      const auto& colours = plot::palette(p.theme);
      for (const std::size_t c : groups[g]) {
        if (now >= data.curves[c].values.size() || !std::isfinite(data.curves[c].values[now])) continue;
        const plot::Rgb& colour = colours[c % plot::palette_size];
        cairo_arc(cr, x, geometry.y(data.curves[c].values[now]), 3.5 * style.u, 0, 2 * std::numbers::pi);
        cairo_set_source_rgb(cr, colour.r, colour.g, colour.b);
        cairo_fill_preserve(cr);
        set_colour(cr, style.theme->background);
        cairo_set_line_width(cr, 1.2 * style.u);
        cairo_stroke(cr);
      }
    }
    cairo_restore(cr);
  }
  return report;
}

const std::string& caption_at(const std::vector<Caption>& captions, double t) {
  static const std::string none;
  const std::string* shown = &none;
  for (const Caption& c : captions)
    if (c.at <= t + 1e-9) shown = t < c.until - 1e-9 ? &c.text : &none;
  return *shown;
}

void convert_angles(PanelData& data, AngleUnit angles) {
  for (PanelCurve& curve : data.curves) {
    const double factor = angle_factor(curve.unit, angles);
    if (factor == 1.0) continue;
    for (double& v : curve.values) v *= factor;
    curve.unit = angle_unit_text(curve.unit, angles);
  }
}

std::vector<std::string> wrap_text(cairo_t* cr, double font_size, const std::string& text, double max_width) {
  const text::Font font{font_size, false};
  std::vector<std::string> lines;
  std::string line;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t start = text.find_first_not_of(" \n", at);
    if (start == std::string::npos) break;
    const std::size_t end = std::min(text.find_first_of(" \n", start), text.size());
    const std::string word = text.substr(start, end - start);
    const bool forced = start > 0 && text.find('\n', at) < start;  // a newline in the text breaks the line
    std::string candidate = line.empty() ? word : line + " " + word;
    if (!line.empty() && (forced || text::width(cr, font, candidate.c_str()) > max_width)) {
      lines.push_back(line);
      candidate = word;
    }
    line = candidate;
    at = end;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

namespace {

struct CaptionText {
  text::Font font;
  double pad = 0, line_height = 0, ascent = 0;
  std::vector<std::string> lines;
};

CaptionText caption_text(cairo_t* cr, const DrawStyle& style, const std::string& text, double width) {
  CaptionText c;
  c.font = {1.25 * style.text_size(), false};
  c.pad = 0.6 * style.padding();
  c.lines = wrap_text(cr, c.font.size, text, 0.92 * width - 2 * c.pad);
  const text::Metrics m = text::metrics(cr, c.font);
  c.line_height = 1.2 * (m.ascent + m.descent);
  c.ascent = m.ascent;
  return c;
}

}  // namespace

double caption_band_height(cairo_t* cr, const DrawStyle& style, const std::vector<Caption>& captions, double width) {
  double tallest = 0;
  for (const Caption& caption : captions) {
    const CaptionText c = caption_text(cr, style, caption.text, width);
    tallest = std::max(tallest, c.line_height * static_cast<double>(c.lines.size()) + 2 * c.pad);
  }
  return tallest > 0 ? std::ceil(tallest + style.padding()) : 0.0;
}

void paint_caption(cairo_t* cr, const DrawStyle& style, const std::string& text, const Rect& area) {
  cairo_save(cr);
  cairo_rectangle(cr, area.x, area.y, area.width, area.height);
  set_colour(cr, style.theme->background);
  cairo_fill(cr);
  const CaptionText c = caption_text(cr, style, text, area.width);
  if (!c.lines.empty()) {
    double widest = 0;
    for (const std::string& line : c.lines) widest = std::max(widest, text::width(cr, c.font, line.c_str()));
    const double w = widest + 2 * c.pad, h = c.line_height * static_cast<double>(c.lines.size()) + 2 * c.pad;
    const double x = area.x + 0.5 * (area.width - w), y = area.y + 0.5 * (area.height - h), r = 0.5 * c.pad;
    paint_box(cr, style, {x, y, w, h}, r, std::max(1.0, 0.8 * style.u));
    double baseline = y + c.pad + 0.5 * (c.line_height - c.line_height / 1.2) + c.ascent;
    for (const std::string& line : c.lines) {
      text::draw(cr, c.font, area.x + 0.5 * area.width, baseline, line.c_str(), style.theme->text, text::Align::centre);
      baseline += c.line_height;
    }
  }
  cairo_restore(cr);
}

}  // namespace linkage
