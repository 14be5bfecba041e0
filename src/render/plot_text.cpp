#include "render/plot_text.hpp"

#include <algorithm>
#include <memory>

namespace linkage::plot {
namespace {

constexpr const char* font_family = "DejaVu Sans";
constexpr double script_scale = 0.7;
constexpr double superscript_rise = 0.42;  // baseline shift as a fraction of the main size
constexpr double subscript_drop = 0.18;

void select_font(cairo_t* cr, const Font& font, double size) {
  cairo_select_font_face(cr, font_family, CAIRO_FONT_SLANT_NORMAL,
                         font.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double run_size(const TextRun& run, const Font& font) {
  return run.shift == TextRun::Shift::none ? font.size : font.size * script_scale;
}

/// Baseline offset of a run, positive upwards.
double run_rise(const TextRun& run, const Font& font) {
  switch (run.shift) {
    case TextRun::Shift::superscript:
      return superscript_rise * font.size;
    case TextRun::Shift::subscript:
      return -subscript_drop * font.size;
    case TextRun::Shift::none:
      break;
  }
  return 0.0;
}

std::string with_minus_signs(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '-')
      out += "\u2212";
    else
      out += c;
  }
  return out;
}

}  // namespace

std::vector<TextRun> parse_markup(std::string_view markup) {
  std::vector<TextRun> runs;
  std::string plain;
  const auto flush_plain = [&] {
    if (!plain.empty()) runs.push_back({plain, TextRun::Shift::none});
    plain.clear();
  };
  std::size_t i = 0;
  while (i < markup.size()) {
    const char c = markup[i];
    const bool opens = (c == '^' || c == '_') && i + 1 < markup.size() && markup[i + 1] == '{';
    const std::size_t close = opens ? markup.find('}', i + 2) : std::string_view::npos;
    if (close == std::string_view::npos) {
      plain += c;
      ++i;
      continue;
    }
    flush_plain();
    const std::string_view script = markup.substr(i + 2, close - (i + 2));
    if (!script.empty())
      runs.push_back({with_minus_signs(script), c == '^' ? TextRun::Shift::superscript : TextRun::Shift::subscript});
    i = close + 1;
  }
  flush_plain();
  return runs;
}

void set_plot_font_options(cairo_t* cr) {
  const std::unique_ptr<cairo_font_options_t, decltype(&cairo_font_options_destroy)> options(
      cairo_font_options_create(), &cairo_font_options_destroy);
  cairo_font_options_set_antialias(options.get(), CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_hint_style(options.get(), CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options.get(), CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, options.get());
}

double cap_height(cairo_t* cr, const Font& font) {
  select_font(cr, font, font.size);
  cairo_text_extents_t extents{};
  cairo_text_extents(cr, "H", &extents);
  return -extents.y_bearing;
}

TextExtent measure_text(cairo_t* cr, std::string_view markup, const Font& font) {
  TextExtent extent;
  for (const TextRun& run : parse_markup(markup)) {
    const double size = run_size(run, font);
    select_font(cr, font, size);
    cairo_text_extents_t text{};
    cairo_text_extents(cr, run.text.c_str(), &text);
    cairo_font_extents_t face{};
    cairo_font_extents(cr, &face);
    cairo_text_extents_t capital{};
    cairo_text_extents(cr, "H", &capital);
    const double rise = run_rise(run, font);
    extent.width += text.x_advance;
    extent.ascent = std::max(extent.ascent, rise - capital.y_bearing);
    extent.descent = std::max(extent.descent, face.descent - rise);
  }
  return extent;
}

void draw_text(cairo_t* cr, std::string_view markup, const Font& font, double x, double baseline, Align align) {
  if (align != Align::start) {
    const double width = measure_text(cr, markup, font).width;
    x -= align == Align::center ? width / 2 : width;
  }
  for (const TextRun& run : parse_markup(markup)) {
    select_font(cr, font, run_size(run, font));
    cairo_move_to(cr, x, baseline - run_rise(run, font));
    cairo_show_text(cr, run.text.c_str());
    cairo_text_extents_t text{};
    cairo_text_extents(cr, run.text.c_str(), &text);
    x += text.x_advance;
  }
}

}  // namespace linkage::plot
