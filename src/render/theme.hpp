#pragma once
// Colour palettes. assets/themes/<name>.toml is the source of truth; the build embeds
// a copy of each so an installed binary works without the assets folder. At run time a
// file in the assets folder wins over the embedded copy, so a palette can be tuned
// without rebuilding.
#include <array>
#include <filesystem>
#include <string>
#include <string_view>

namespace linkage {

struct Rgba {
  double r = 0, g = 0, b = 0, a = 1;  // 0 .. 1, not premultiplied
  bool operator==(const Rgba&) const = default;
};

struct Theme {
  std::string name;
  Rgba background, grid, text, text_muted, panel, panel_edge;
  std::array<Rgba, 2> block_fill, block_edge;  // blocks 1 and 2
  Rgba pin_fill, pin_edge, pin_force, gravity, velocity, trail, com, motor;
};

/// The themes shipped: light, dark, print.
[[nodiscard]] std::string theme_name_list();

/// Throws Error::invalid naming `origin` unless `name` is a shipped theme, with the
/// nearest name for a typo.
void check_theme_name(std::string_view name, const std::string& origin);

/// Parses a palette; `source` names it in errors ("assets/themes/dark.toml"). Throws
/// Error::input "source:line:column: CONTEXT: problem" (TableReader's form) for a syntax
/// error, an unknown or missing key, or a colour that is not "#RRGGBB" / "#RRGGBBAA".
[[nodiscard]] Theme parse_theme(std::string_view toml_text, const std::string& name, const std::string& source);

/// The assets folder: $LINKAGE_ASSETS_DIR when set, else `built_in` (the source tree's
/// assets/, which the CLI knows at compile time). Empty when neither exists.
[[nodiscard]] std::filesystem::path assets_dir(const std::filesystem::path& built_in);

/// Theme `name` from `assets`/themes/<name>.toml when that file exists, else the copy
/// embedded at build time. Throws Error::input naming `origin` for an unknown name.
[[nodiscard]] Theme load_theme(std::string_view name, const std::filesystem::path& assets, const std::string& origin);

}  // namespace linkage
