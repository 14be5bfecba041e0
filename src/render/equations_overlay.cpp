#include "render/equations_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/overlays.hpp"
#include "render/text.hpp"

namespace linkage {
namespace {

constexpr double kMeasure = 100;      // font size the widths are measured at, then scaled
constexpr double kHeadingGap = 0.35;  // lines between the heading and the equations
constexpr double kLeading = 1.15;     // line height over the font's ascent + descent: room for raised dots

// Combining marks (the dots of θ̇, θ̈) take no column: they sit on the character before.
bool combining(char32_t c) {
  return (c >= 0x0300 && c <= 0x036F) || (c >= 0x1AB0 && c <= 0x1AFF) || (c >= 0x1DC0 && c <= 0x1DFF) ||
         (c >= 0x20D0 && c <= 0x20FF) || (c >= 0xFE20 && c <= 0xFE2F);
}

struct CodePoint {
  std::size_t start = 0, length = 1;
  char32_t value = 0;
};

CodePoint next_code_point(const std::string& s, std::size_t i) {
  const auto lead = static_cast<unsigned char>(s[i]);
  CodePoint p;
  p.start = i;
  p.length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
  p.value = p.length == 1 ? lead : p.length == 2 ? (lead & 0x1Fu) : p.length == 3 ? (lead & 0x0Fu) : (lead & 0x07u);
  for (std::size_t k = 1; k < p.length && i + k < s.size(); ++k)
    p.value = (p.value << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3Fu);
  p.length = std::min(p.length, s.size() - i);
  return p;
}

std::size_t columns(const std::string& line) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < line.size();) {
    const CodePoint p = next_code_point(line, i);
    if (!combining(p.value)) ++n;
    i += p.length;
  }
  return n;
}

struct Measures {
  double column = 0;   // a column's advance per pixel of font size
  double line = 0;     // a line's height per pixel of font size
  double ascent = 0;   // per pixel of font size
  double heading = 0;  // the heading's advance per pixel of font size
  double pad = 0, margin = 0;
  std::size_t widest = 0;  // columns
};

Measures measure(cairo_t* cr, const DrawStyle& style, const EquationsText& text,
                 const std::vector<std::string>& lines) {
  Measures m;
  const text::Font mono{kMeasure, false, true};
  m.column = text::width(cr, mono, "0") / kMeasure;
  const text::Metrics metrics = text::metrics(cr, mono);
  m.line = kLeading * (metrics.ascent + metrics.descent) / kMeasure;
  m.ascent = metrics.ascent / kMeasure;
  m.heading = text::width(cr, {kMeasure, true, false}, text.heading.c_str()) / kMeasure;
  m.pad = 0.6 * style.padding();
  m.margin = 0.5 * style.padding();
  for (const std::string& line : lines) m.widest = std::max(m.widest, columns(line));
  return m;
}

double rows(const std::vector<std::string>& lines, const EquationsText& text) {
  return static_cast<double>(lines.size()) + (text.heading.empty() ? 0.0 : 1 + kHeadingGap);
}

// How far `mark`, placed by the font over a lowercase letter, must rise to sit as
// closely over `base` (θ is taller than x): zero over a short base.
double mark_raise(cairo_t* cr, const std::string& base, const std::string& mark) {
  cairo_text_extents_t x, b, m;
  cairo_text_extents(cr, "x", &x);
  cairo_text_extents(cr, base.c_str(), &b);
  cairo_text_extents(cr, mark.c_str(), &m);
  const double mark_bottom = -(m.y_bearing + m.height), gap = mark_bottom + x.y_bearing;  // above the x-height
  return std::max(0.0, -b.y_bearing + 0.3 * gap - mark_bottom);
}

// Draws one line in the mono font from x: each character in its column, a combining
// mark drawn in its base's column (DejaVu Sans Mono gives marks a column of their own
// and Cairo's toy API does not position them), raised over a tall base.
void draw_line(cairo_t* cr, const text::Font& font, double x, double baseline, double column, const std::string& line,
               const Rgba& colour) {
  text::use(cr, font);
  set_colour(cr, colour);
  std::size_t col = 0, run_start = 0, run_col = 0, base_start = 0, base_length = 0;
  auto flush = [&](std::size_t end) {
    if (end > run_start) {
      const std::string run = line.substr(run_start, end - run_start);
      cairo_move_to(cr, x + static_cast<double>(run_col) * column, baseline);
      cairo_show_text(cr, run.c_str());
    }
  };
  for (std::size_t i = 0; i < line.size();) {
    const CodePoint p = next_code_point(line, i);
    if (combining(p.value) && col > 0) {
      flush(i);
      const std::string mark = line.substr(i, p.length);
      cairo_move_to(cr, x + static_cast<double>(col - 1) * column,
                    baseline - mark_raise(cr, line.substr(base_start, base_length), mark));
      cairo_show_text(cr, mark.c_str());
      run_start = i + p.length;
      run_col = col;
    } else {
      ++col;
      base_start = i;
      base_length = p.length;
    }
    i += p.length;
  }
  flush(line.size());
}

}  // namespace

std::vector<std::string> equation_lines_drawn(const EquationsText& text) {
  std::size_t indent = std::string::npos;
  for (const std::string& line : text.lines) {
    const std::size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos) indent = std::min(indent, first);
  }
  if (indent == std::string::npos) indent = 0;
  std::vector<std::string> lines;
  for (const std::string& line : text.lines) lines.push_back(line.size() > indent ? line.substr(indent) : "");
  return lines;
}

EquationsFit fit_equations(cairo_t* cr, const DrawStyle& style, const EquationsText& text, double width,
                           double max_height) {
  const std::vector<std::string> lines = equation_lines_drawn(text);
  if (lines.empty()) return {};
  const Measures m = measure(cr, style, text, lines);
  const double inset = 2 * (m.pad + m.margin);
  const double content = std::max(m.column * static_cast<double>(m.widest), m.heading);
  const double per_font = m.line * rows(lines, text);
  EquationsFit fit;
  // The frame's text size, but never below the legible minimum where there is room for it.
  fit.font_size = std::min(
      {std::max(style.text_size(), kMinEquationFont), (width - inset) / content, (max_height - inset) / per_font});
  fit.height = fit.fits() ? std::ceil(fit.font_size * per_font + inset) : 0.0;
  return fit;
}

void paint_equations(cairo_t* cr, const DrawStyle& style, const EquationsText& text, const EquationsFit& fit,
                     const Rect& area) {
  cairo_save(cr);
  cairo_rectangle(cr, area.x, area.y, area.width, area.height);
  set_colour(cr, style.theme->background);
  cairo_fill(cr);
  const std::vector<std::string> lines = equation_lines_drawn(text);
  const Measures m = measure(cr, style, text, lines);
  const double f = fit.font_size;
  const double w = std::max(m.column * static_cast<double>(m.widest), m.heading) * f + 2 * m.pad;
  const double h = m.line * rows(lines, text) * f + 2 * m.pad;
  const double x = area.x + 0.5 * (area.width - w), y = area.y + 0.5 * (area.height - h), r = 0.5 * m.pad;
  paint_box(cr, style, {x, y, w, h}, r, std::max(1.0, 0.8 * style.u));
  double baseline = y + m.pad + m.ascent * f;
  if (!text.heading.empty()) {
    text::draw(cr, {f, true, false}, x + m.pad, baseline, text.heading.c_str(), style.theme->text);
    baseline += (1 + kHeadingGap) * m.line * f;
  }
  const text::Font mono{f, false, true};
  for (const std::string& line : lines) {
    draw_line(cr, mono, x + m.pad, baseline, m.column * f, line, style.theme->text);
    baseline += m.line * f;
  }
  cairo_restore(cr);
}

}  // namespace linkage
