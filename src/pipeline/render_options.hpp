#pragma once
// The options of a picture, in one table for `linkage render`'s flags, a lesson's render
// step keys and the lesson format's key list: each option's name, value type, default and
// meaning, and how its value, as text, is checked and applied to the RenderSettings and
// the clip's overlays. A flag's text is its value; a lesson's TOML value becomes the same
// text (a list joined by commas, a number in round-trip form). Errors are
// Error::invalid(NAME, ...) for the caller to place: the CLI as --flag, a lesson at the
// key's FILE:LINE:COLUMN.
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/parse_text.hpp"
#include "render/settings.hpp"

namespace linkage {

/// How a lesson writes an option's value.
enum class RenderValue { string, integer, number, list };

struct RenderDraft;  // the options read so far (render_options.cpp)

struct RenderOption {
  std::string_view name;          // the lesson key; the flag is --name with '-' for '_'
  RenderValue value;              // the lesson's TOML type
  std::string_view type;          // as the lesson format documents it: "integer", "list of strings"
  std::string_view placeholder;   // the flag's value in --help: "N", "WxH"
  std::string_view default_text;  // "30", "none"
  std::string doc;                // one line: what it does (the flag's help)
  void (*apply)(RenderDraft& draft, const std::string& text);
};

/// Every option, in the order they are applied (quality before size and fps, ensemble
/// before spread).
[[nodiscard]] std::span<const RenderOption> render_options();

/// The picture the options are for, and how its reader spells things in messages.
struct RenderTarget {
  bool still = false;  // the output is one still
  bool page = false;   // the output is an interactive page (.html): every time on its slider
  /// How the reader names an option when a message points to another: "--view" or "view".
  std::function<std::string(std::string_view name)> spell;
};

/// The options resolved: the picture's settings and the overlays asked for.
struct RenderRequest {
  RenderSettings settings;
  std::vector<std::string> trails;  // BODY.POINT (a mechanism's)
  std::string trail_length;         // seconds as given, "cycle", or empty (the default 2 s)
  std::vector<std::string> points;  // BODY.POINT: velocity and acceleration arrows there
  int ensemble = 0;                 // 0, or 2 .. 200 runs
  double spread = 1e-6;
  std::string compare;  // as given: NAME=VALUE,..., a trajectory FILE.csv or a mechanism
  bool titled = false;  // the title was given: a mechanism's own is not the default
};

/// Applies the `given` options (name, text) over `base` (its duration is the run's),
/// then checks that they fit together and validates the settings (the caller adds the
/// equations shown and validates again). Error::invalid naming the option at fault.
[[nodiscard]] RenderRequest resolve_render_options(const std::vector<std::pair<std::string, std::string>>& given,
                                                   const RenderTarget& target, RenderSettings base = {});

}  // namespace linkage
