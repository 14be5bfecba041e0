#include "render/settings.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <vector>

#include "core/character_text.hpp"
#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"
#include "render/frame_layout.hpp"

namespace linkage {
namespace {

constexpr double kMaxViewCoordinate = 1e9;  // m (the message says -1e9 .. 1e9)

// A whole-string finite double, or Error::input.
double parse_double(std::string_view text, const std::string& origin, std::string_view whole) {
  double value = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (text.empty() || ec != std::errc() || ptr != last || !std::isfinite(value))
    throw Error::invalid(origin, "'" + std::string(whole) + "': '" + std::string(text) + "' is not a finite number" +
                                     lookalike_advice(text));
  return value;
}

void check_size(int width, int height, const std::string& origin) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width <= 0 || height <= 0) throw Error::invalid(origin, "size " + size + " must be positive");
  if (width % 2 != 0 || height % 2 != 0)
    throw Error::invalid(
        origin, "size " + size + " must have an even width and height (yuv420p video halves the colour resolution)");
  if (width > kMaxWidth || height > kMaxHeight)
    throw Error::invalid(origin, "size " + size + " is above the largest, " + std::to_string(kMaxWidth) + "x" +
                                     std::to_string(kMaxHeight));
}

}  // namespace

long RenderSettings::frame_count() const { return std::lround(duration / speed * fps); }

double RenderSettings::frame_time(long k) const { return static_cast<double>(k) * speed / fps; }

std::vector<double> RenderSettings::still_times(double look_back) const {
  const double step = speed / fps;
  const auto back = static_cast<long>(std::floor(look_back / step));
  std::vector<double> times;
  for (long j = back; j > 0; --j) times.push_back(at - static_cast<double>(j) * step);
  times.push_back(at);
  return times;
}

void RenderSettings::validate() const {
  check_size(width, height, "size");
  if (fps < 1 || fps > kMaxFps)
    throw Error::invalid("fps", std::to_string(fps) + " is outside 1 .. " + std::to_string(kMaxFps));
  if (!(speed > 0) || !std::isfinite(speed))
    throw Error::invalid(
        "speed", format_roundtrip(speed) + " must be a positive number (simulated seconds per second of video)");
  if (!(duration > 0) || !std::isfinite(duration))
    throw Error::invalid("duration", format_roundtrip(duration) + " s must be positive");
  if (duration / speed > kMaxVideoSeconds)
    throw Error::invalid("duration", format_roundtrip(duration) + " s at speed " + format_roundtrip(speed) + " makes " +
                                         format_significant(duration / speed, 6) + " s of video; at most " +
                                         format_significant(kMaxVideoSeconds, 6) + " s (an hour)");
  if (frame_count() < 1)
    throw Error::invalid("duration", format_significant(duration, 6) + " s at speed " + format_significant(speed, 6) +
                                         " and " + std::to_string(fps) + " fps is less than one frame");
  if (!(at >= 0) || at > kMaxStillTime)
    throw Error::invalid("at",
                         format_roundtrip(at) + " s is outside 0 .. " + format_significant(kMaxStillTime, 6) + " s");
  if (camera == CameraMode::fixed && !(view.xmax > view.xmin && view.ymax > view.ymin))
    throw Error::invalid("view", "the fixed camera needs a view with positive width and height");
  for (std::size_t i = 0; i < captions.size(); ++i) {
    const Caption& c = captions[i];
    const std::string which = "caption " + std::to_string(i + 1);
    if (!(c.at >= 0) || c.at > kMaxStillTime)
      throw Error::invalid("captions", which + " at " + format_roundtrip(c.at) + " s is outside 0 .. " +
                                           format_significant(kMaxStillTime, 6) + " s");
    if (i > 0 && !(c.at > captions[i - 1].at))
      throw Error::invalid("captions", which + " at " + format_roundtrip(c.at) + " s must come after the one before (" +
                                           format_roundtrip(captions[i - 1].at) + " s)");
    if (c.text.find_first_not_of(" \t\n") == std::string::npos)
      throw Error::invalid("captions", which + " has no text");
    if (!(c.until > c.at))
      throw Error::invalid("captions", which + " ends at " + format_roundtrip(c.until) + " s, not after its start " +
                                           format_roundtrip(c.at) + " s");
    if (i + 1 < captions.size() && std::isfinite(c.until) && c.until > captions[i + 1].at)
      throw Error::invalid("captions", which + " ends at " + format_roundtrip(c.until) + " s, after caption " +
                                           std::to_string(i + 2) + " starts (" + format_roundtrip(captions[i + 1].at) +
                                           " s)");
  }
  (void)frame_bands(*this);  // the equations shown fit the frame
}

const Quality& parse_quality(std::string_view name, const std::string& origin) {
  std::string valid;
  std::vector<std::string> names;
  for (const Quality& q : kQualities) {
    if (q.name == name) return q;
    valid += std::string(valid.empty() ? "" : ", ") + std::string(q.name) + " (" + std::to_string(q.width) + "x" +
             std::to_string(q.height) + "@" + std::to_string(q.fps) + ")";
    names.emplace_back(q.name);
  }
  throw Error::invalid(
      origin, "'" + std::string(name) + "' is not a quality" + did_you_mean(name, names) + "; valid: " + valid);
}

void parse_size(std::string_view text, const std::string& origin, int& width, int& height) {
  const std::size_t x = text.find('x');
  int w = 0, h = 0;
  const auto whole_int = [](std::string_view part, int& value) {
    const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
    return !part.empty() && ec == std::errc() && ptr == part.data() + part.size();
  };
  if (x == std::string_view::npos || !whole_int(text.substr(0, x), w) || !whole_int(text.substr(x + 1), h))
    throw Error::invalid(origin, "'" + std::string(text) + "' is not a size WIDTHxHEIGHT (e.g. 1280x720)");
  check_size(w, h, origin);
  width = w;
  height = h;
}

CameraMode parse_camera(std::string_view name, const std::string& origin) {
  if (name == "follow") return CameraMode::follow;
  if (name == "fixed") return CameraMode::fixed;
  if (name == "fit") return CameraMode::fit;
  throw Error::invalid(origin, "'" + std::string(name) + "' is not a camera" +
                                   did_you_mean(name, {"follow", "fixed", "fit"}) + "; valid: follow, fixed, fit");
}

View parse_view(std::string_view text, const std::string& origin) {
  std::vector<double> values;
  std::vector<std::string_view> pieces;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    pieces.push_back(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    values.push_back(parse_double(pieces.back(), origin, text));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (values.size() != 4)
    throw Error::invalid(origin, "'" + std::string(text) + "' is not xmin,ymin,xmax,ymax (four numbers in metres)");
  // Far beyond any motion the program simulates (an hour's fall is 6e7 m), and small
  // enough that the view's width and height are finite.
  constexpr std::array<const char*, 4> kNames{"xmin", "ymin", "xmax", "ymax"};
  for (std::size_t i = 0; i < values.size(); ++i)
    if (std::fabs(values[i]) > kMaxViewCoordinate)
      throw Error::invalid(origin, "'" + std::string(text) + "': " + kNames[i] + " = " + std::string(pieces[i]) +
                                       " m is outside -1e9 .. 1e9 m");
  const View view{values[0], values[1], values[2], values[3]};
  if (!(view.xmax > view.xmin) || !(view.ymax > view.ymin))
    throw Error::invalid(origin,
                         "'" + std::string(text) + "' has zero or negative area; need xmin < xmax and ymin < ymax");
  return view;
}

OutputKind output_kind(const std::filesystem::path& file, const std::string& origin) {
  std::string extension = file.extension().string();  // matched whatever its case
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".mp4") return OutputKind::mp4;
  if (extension == ".gif") return OutputKind::gif;
  if (extension == ".webm") return OutputKind::webm;
  if (extension == ".png") return OutputKind::png;
  if (extension == ".svg") return OutputKind::svg;
  if (extension == ".pdf") return OutputKind::pdf;
  if (extension == ".html") return OutputKind::html;
  throw Error::invalid(origin,
                       "'" + file.string() + "' has " +
                           (extension.empty() ? std::string("no extension") : "extension '" + extension + "'") +
                           "; valid: .mp4, .gif or .webm (clip), .html (interactive page), .png (still), .svg or .pdf "
                           "(vector still)");
}

bool is_video(OutputKind kind) {
  return kind == OutputKind::mp4 || kind == OutputKind::gif || kind == OutputKind::webm;
}

bool is_still(OutputKind kind) { return kind == OutputKind::png || kind == OutputKind::svg || kind == OutputKind::pdf; }

}  // namespace linkage
