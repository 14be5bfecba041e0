// The plot's public entry points other than draw(): palette, axis mapping, validation
// and the PNG / SVG / PDF writers.
#include "render/plot.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <string_view>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"

namespace linkage::plot {
namespace {

constexpr Rgb rgb(int r, int g, int b) { return {r / 255.0, g / 255.0, b / 255.0}; }

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

std::string number(double value) { return format_significant(value, 6); }

void validate_axis(const Axis& axis, const std::string& where) {
  for (const auto& [limit, name] : {std::pair{axis.min, "min"}, std::pair{axis.max, "max"}}) {
    if (!limit) continue;
    if (!std::isfinite(*limit))
      throw Error::input(where + " " + name + " must be a finite number, got " + number(*limit));
    if (axis.scale == Scale::log && !(*limit > 0))
      throw Error::input(where + " " + name + " " + number(*limit) + " must be > 0 on a log axis");
  }
  if (axis.min && axis.max && !(*axis.min < *axis.max))
    throw Error::input(where + " min " + number(*axis.min) + " must be below max " + number(*axis.max));
}

void check(cairo_status_t status, const std::string& what) {
  if (status != CAIRO_STATUS_SUCCESS) throw Error::failure(what + ": " + cairo_status_to_string(status));
}

/// Cairo's write callback: appends to the AtomicFile's stream.
cairo_status_t append_to_stream(void* closure, const unsigned char* data, unsigned int length) {
  auto& out = *static_cast<std::ostream*>(closure);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
  return out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

Report draw_on(cairo_surface_t* surface, const Plot& plot, const Canvas& canvas, const std::string& origin,
               const std::string& what) {
  check(cairo_surface_status(surface), what);
  const ContextPtr cr(cairo_create(surface), &cairo_destroy);
  check(cairo_status(cr.get()), what);
  return draw(cr.get(), plot, canvas, origin);
}

Report write_png(const Plot& plot, const Canvas& canvas, std::ostream& out, const std::string& origin,
                 const std::string& what) {
  const Canvas pixels{std::round(canvas.width), std::round(canvas.height), canvas.font_size};
  const SurfacePtr surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(pixels.width), static_cast<int>(pixels.height)),
      &cairo_surface_destroy);
  const Report report = draw_on(surface.get(), plot, pixels, origin, what);
  cairo_surface_flush(surface.get());
  check(cairo_surface_write_to_png_stream(surface.get(), &append_to_stream, &out), what);
  return report;
}

/// Cairo names each SVG surface "surface<N>" with a process-wide counter; number them
/// from 1 in order of appearance (ids and references alike) so the bytes repeat.
std::string renumber_svg_surfaces(const std::string& svg) {
  static constexpr std::string_view token = "surface";
  std::string out;
  out.reserve(svg.size());
  std::map<std::string, std::string, std::less<>> renamed;
  std::size_t done = 0;
  for (std::size_t at = svg.find(token); at != std::string::npos; at = svg.find(token, at + 1)) {
    const bool named = at > 0 && (svg[at - 1] == '"' || svg[at - 1] == '#');
    std::size_t end = at + token.size();
    while (end < svg.size() && std::isdigit(static_cast<unsigned char>(svg[end]))) ++end;
    if (!named || end == at + token.size()) continue;
    const std::string number = svg.substr(at + token.size(), end - at - token.size());
    const auto [entry, added] = renamed.try_emplace(number, std::to_string(renamed.size() + 1));
    out.append(svg, done, at + token.size() - done);
    out += entry->second;
    done = end;
  }
  out.append(svg, done);
  return out;
}

Report write_vector(Format format, const Plot& plot, const Canvas& canvas, std::ostream& out, const std::string& origin,
                    const std::string& what) {
  std::ostringstream buffer;
  const SurfacePtr surface(
      format == Format::svg
          ? cairo_svg_surface_create_for_stream(&append_to_stream, &buffer, canvas.width, canvas.height)
          : cairo_pdf_surface_create_for_stream(&append_to_stream, &buffer, canvas.width, canvas.height),
      &cairo_surface_destroy);
  check(cairo_surface_status(surface.get()), what);
  if (format == Format::svg) {
    cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PT);
  } else {
    // A fixed date keeps the PDF's bytes the same from run to run.
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "linkage");
  }
  const Report report = draw_on(surface.get(), plot, canvas, origin, what);
  cairo_surface_finish(surface.get());
  check(cairo_surface_status(surface.get()), what);
  out << (format == Format::svg ? renumber_svg_surfaces(buffer.str()) : buffer.str());
  return report;
}

}  // namespace

const std::array<Rgb, palette_size>& palette(Theme theme) {
  // Okabe & Ito (2008). On white, yellow comes last; on dark grey, black becomes light
  // grey and the dark blue comes last.
  static const std::array<Rgb, palette_size> light{rgb(0, 114, 178),   rgb(213, 94, 0),  rgb(0, 158, 115),
                                                   rgb(204, 121, 167), rgb(230, 159, 0), rgb(86, 180, 233),
                                                   rgb(0, 0, 0),       rgb(240, 228, 66)};
  static const std::array<Rgb, palette_size> dark{rgb(86, 180, 233),  rgb(230, 159, 0),   rgb(0, 158, 115),
                                                  rgb(240, 228, 66),  rgb(204, 121, 167), rgb(213, 94, 0),
                                                  rgb(224, 224, 224), rgb(0, 114, 178)};
  return theme == Theme::dark ? dark : light;
}

double AxisMap::operator()(double value) const {
  const double fraction =
      scale == Scale::log ? std::log10(value / min) / std::log10(max / min) : (value - min) / (max - min);
  return from + fraction * (to - from);
}

std::string Report::warning() const {
  std::string text;
  if (dropped_nonpositive > 0)
    text = "dropped " + std::to_string(dropped_nonpositive) + " point(s) with a value <= 0 on a log axis";
  if (skipped_nonfinite > 0)
    text += (text.empty() ? "skipped " : "; skipped ") + std::to_string(skipped_nonfinite) +
            " point(s) that are not finite numbers";
  return text;
}

std::optional<Format> format_of(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".png") return Format::png;
  if (extension == ".svg") return Format::svg;
  if (extension == ".pdf") return Format::pdf;
  return std::nullopt;
}

void validate(const Plot& plot, const Canvas& canvas, const std::string& origin) {
  for (const auto& [size, name] : {std::pair{canvas.width, "width"}, std::pair{canvas.height, "height"}})
    if (!(size >= 100 && size <= 20000))
      throw Error::invalid(origin, "plot " + std::string(name) + " " + number(size) + " is outside 100..20000");
  if (!(canvas.font_size >= 4 && canvas.font_size <= 200))
    throw Error::invalid(origin, "plot font size " + number(canvas.font_size) + " is outside 4..200");
  validate_axis(plot.x, origin + ": x axis");
  validate_axis(plot.y, origin + ": y axis");
  if (plot.equal_scale && (plot.x.scale == Scale::log || plot.y.scale == Scale::log))
    throw Error::invalid(origin, "axes at one scale must both be linear, not logarithmic");
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const Series& series = plot.series[i];
    if (series.color && *series.color >= palette_size)
      throw Error::invalid(origin, "series " + std::to_string(i + 1) + " '" + series.name + "': colour slot " +
                                       std::to_string(*series.color) + " is outside the palette 0.." +
                                       std::to_string(palette_size - 1));
  }
}

Report write(const Plot& plot, const std::filesystem::path& target, const Canvas& canvas, const std::string& origin) {
  const std::optional<Format> format = format_of(target);
  if (!format)
    throw Error::invalid(origin, "'" + target.string() + "' has an unknown plot format '" +
                                     target.extension().string() + "' (valid: .png, .svg, .pdf)");
  validate(plot, canvas, origin);
  AtomicFile file(target, origin, /*binary=*/true);
  const std::string what = origin + ": cannot write plot '" + target.string() + "'";
  const Report report = *format == Format::png ? write_png(plot, canvas, file.stream(), origin, what)
                                               : write_vector(*format, plot, canvas, file.stream(), origin, what);
  file.commit();
  return report;
}

}  // namespace linkage::plot
