#pragma once
// What `linkage render` is asked to draw, validated: frame size and rate, the clip's
// simulated duration and playback speed, the shown elements, camera, theme and title.
// Frame timing: with duration D, speed S (simulated seconds per video second) and F
// frames per second, a clip has exactly round(D / S x F) frames and frame k shows the
// motion at t = k S / F.
#include <array>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/angle_unit.hpp"
#include "render/camera.hpp"
#include "scene/arrow_scale.hpp"
#include "scene/elements.hpp"

namespace linkage {

struct Quality {
  std::string_view name;
  int width, height, fps;
};
/// --quality presets.
inline constexpr std::array<Quality, 4> kQualities{{
    {"low", 854, 480, 30},
    {"medium", 1280, 720, 30},
    {"high", 1920, 1080, 60},
    {"4k", 3840, 2160, 60},
}};

inline constexpr int kMaxWidth = 7680, kMaxHeight = 4320, kMaxFps = 240;
inline constexpr double kMaxVideoSeconds = 3600;  // an hour of video
inline constexpr double kMaxStillTime = 3600;     // s of simulated time before a still

enum class OutputKind { mp4, gif, webm, png, svg, pdf, html };  // html: an interactive page of the clip

/// A case's equations as the text report prints them (report/mechanism_text's
/// case_equations), drawn in a band under the motion with Element::equations.
struct EquationsText {
  std::string heading;             // "Case 3: four equations in generalized coordinates, no pin force"
  std::vector<std::string> lines;  // as printed, indentation included
  [[nodiscard]] bool empty() const { return lines.empty(); }
};

/// Words drawn along the bottom of the frame from time `at` until `until`, or until the
/// next caption's `at` when `until` is infinite: a caption about a moment ends with it.
struct Caption {
  double at = 0;  // s of simulated time
  std::string text;
  double until = std::numeric_limits<double>::infinity();  // s; > at, <= the next caption's at
};

struct RenderSettings {
  int width = 1280, height = 720, fps = 30;  // the "medium" preset
  double duration = 10;                      // s of simulated time
  double speed = 1;                          // simulated seconds per video second
  double at = 0;                             // s, the time a still shows
  ElementSet elements = ElementSet::defaults();
  CameraMode camera = CameraMode::follow;
  bool camera_chosen = false;  // camera (or a view) given: a mechanism's default depends on it
  View view;                   // for CameraMode::fixed
  std::string theme = "light";
  std::string title = "Two blocks joined by a pin, falling freely";
  std::vector<std::string> panel;     // quantities plotted beside the motion (column names)
  std::vector<Caption> captions;      // by increasing `at`
  ArrowScaleRequest arrow_scale;      // --arrow-scale
  bool free_body = false;             // --view fbd: the blocks drawn apart, each with its loads
  EquationsText equations;            // drawn when elements has Element::equations (filled by the caller)
  AngleUnit angles = AngleUnit::rad;  // the panel's angles and rates (--angles)

  /// round(duration / speed x fps).
  [[nodiscard]] long frame_count() const;
  /// k x speed / fps.
  [[nodiscard]] double frame_time(long k) const;
  /// The times a still samples: every frame step over the `look_back` seconds before
  /// `at` (what its trail or panel shows), then `at`.
  [[nodiscard]] std::vector<double> still_times(double look_back) const;
  /// Throws Error::input naming the flag (--size, --fps, --duration, --speed, --at,
  /// --view, captions) and the valid range for the first bad value; Error::invalid("show",
  /// ...) when the equations shown do not fit the frame at a legible size.
  void validate() const;
};

/// A --quality preset by name; Error::input naming `origin` and the presets otherwise.
[[nodiscard]] const Quality& parse_quality(std::string_view name, const std::string& origin);
/// "WxH" (e.g. "1280x720"), each positive, even and within 7680x4320.
void parse_size(std::string_view text, const std::string& origin, int& width, int& height);
[[nodiscard]] CameraMode parse_camera(std::string_view name, const std::string& origin);
/// "xmin,ymin,xmax,ymax" in metres with xmin < xmax and ymin < ymax, each within ±1e9 m.
[[nodiscard]] View parse_view(std::string_view text, const std::string& origin);
/// The output kind from a file's extension (.mp4, .gif, .webm, .png, .svg, .pdf, .html).
[[nodiscard]] OutputKind output_kind(const std::filesystem::path& file, const std::string& origin);
/// A moving picture: .mp4, .gif or .webm.
[[nodiscard]] bool is_video(OutputKind kind);
/// One picture: .png, .svg or .pdf.
[[nodiscard]] bool is_still(OutputKind kind);

}  // namespace linkage
