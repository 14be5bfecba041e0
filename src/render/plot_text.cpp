#include "render/plot_text.hpp"

#include <algorithm>
#include <memory>
#include <numbers>

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

// Combining dots above (U+0307 one, U+0308 two), as in θ̇ and θ̈: Cairo's text API
// places glyphs one by one without shaping, so the mark would not sit on its letter; the
// dots are drawn over the letter instead.
constexpr unsigned char kCombiningLead = 0xCC;
int combining_dots(std::string_view text, std::size_t i) {
  if (i + 1 >= text.size() || static_cast<unsigned char>(text[i]) != kCombiningLead) return 0;
  const auto next = static_cast<unsigned char>(text[i + 1]);
  return next == 0x87 ? 1 : next == 0x88 ? 2 : 0;
}

std::string without_combining_dots(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (combining_dots(text, i) > 0) {
      ++i;
      continue;
    }
    out += text[i];
  }
  return out;
}

/// Shows `text` from the current point, each combining dot drawn over the letter before it.
void show_with_dots(cairo_t* cr, const std::string& text, double size) {
  std::string chunk;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const int dots = combining_dots(text, i);
    if (dots == 0) {
      chunk += text[i];
      continue;
    }
    ++i;
    // The letter the dots belong to: the last UTF-8 character of the chunk.
    std::size_t start = chunk.size();
    while (start > 0 && (static_cast<unsigned char>(chunk[start - 1]) & 0xC0) == 0x80) --start;
    if (start > 0) --start;
    const std::string letter = chunk.substr(start);
    cairo_show_text(cr, chunk.c_str());
    chunk.clear();
    if (letter.empty()) continue;
    double x = 0, y = 0;
    cairo_get_current_point(cr, &x, &y);
    cairo_text_extents_t e{};
    cairo_text_extents(cr, letter.c_str(), &e);
    const double r = 0.065 * size, gap = 0.22 * size;
    const double centre = x - e.x_advance + e.x_bearing + 0.5 * e.width, top = y + e.y_bearing - 0.12 * size - r;
    for (int k = 0; k < dots; ++k) {
      const double dx = dots == 1 ? 0.0 : (k == 0 ? -0.5 : 0.5) * gap;
      cairo_new_sub_path(cr);
      cairo_arc(cr, centre + dx, top, r, 0, 2 * std::numbers::pi);
    }
    cairo_fill(cr);
    cairo_move_to(cr, x, y);
  }
  cairo_show_text(cr, chunk.c_str());
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
    cairo_text_extents(cr, without_combining_dots(run.text).c_str(), &text);
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
    show_with_dots(cr, run.text, run_size(run, font));
    cairo_text_extents_t text{};
    cairo_text_extents(cr, without_combining_dots(run.text).c_str(), &text);
    x += text.x_advance;
  }
}

}  // namespace linkage::plot
