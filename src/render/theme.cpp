#include "render/theme.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "linkage/embedded_themes.hpp"
#include "model/inputs_toml.hpp"
#include "toml/toml_table.hpp"

namespace linkage {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "#RRGGBB" or "#RRGGBBAA"; false for anything else.
bool parse_colour(std::string_view text, Rgba& out) {
  if ((text.size() != 7 && text.size() != 9) || text[0] != '#') return false;
  std::array<double, 4> channels{0, 0, 0, 1};
  for (std::size_t i = 0; 1 + 2 * i < text.size(); ++i) {
    const int high = hex_digit(text[1 + 2 * i]), low = hex_digit(text[2 + 2 * i]);
    if (high < 0 || low < 0) return false;
    channels[i] = (16 * high + low) / 255.0;
  }
  out = {channels[0], channels[1], channels[2], channels[3]};
  return true;
}

// Every key of [colors] and the colour it sets.
using Accessor = Rgba& (*)(Theme&);
#define LINKAGE_COLOUR(key, member)                 \
  {                                                 \
    key, [](Theme& t) -> Rgba& { return t.member; } \
  }
constexpr std::array<std::pair<std::string_view, Accessor>, 18> kColourKeys{{
    LINKAGE_COLOUR("background", background),
    LINKAGE_COLOUR("grid", grid),
    LINKAGE_COLOUR("text", text),
    LINKAGE_COLOUR("text_muted", text_muted),
    LINKAGE_COLOUR("panel", panel),
    LINKAGE_COLOUR("panel_edge", panel_edge),
    LINKAGE_COLOUR("block1_fill", block_fill[0]),
    LINKAGE_COLOUR("block1_edge", block_edge[0]),
    LINKAGE_COLOUR("block2_fill", block_fill[1]),
    LINKAGE_COLOUR("block2_edge", block_edge[1]),
    LINKAGE_COLOUR("pin_fill", pin_fill),
    LINKAGE_COLOUR("pin_edge", pin_edge),
    LINKAGE_COLOUR("pin_force", pin_force),
    LINKAGE_COLOUR("gravity", gravity),
    LINKAGE_COLOUR("velocity", velocity),
    LINKAGE_COLOUR("trail", trail),
    LINKAGE_COLOUR("com", com),
    LINKAGE_COLOUR("motor", motor),
}};
#undef LINKAGE_COLOUR

// The [colors] keys for TableReader: every one required.
const std::array<KeySpec, kColourKeys.size()>& colour_specs() {
  static const auto specs = [] {
    std::array<KeySpec, kColourKeys.size()> out{};
    for (std::size_t i = 0; i < kColourKeys.size(); ++i) out[i] = {kColourKeys[i].first, "colour", "(required)"};
    return out;
  }();
  return specs;
}

constexpr std::array<KeySpec, 1> kTopKeys{{{"colors", "table", "(required)"}}};

std::vector<std::string> theme_names() {
  std::vector<std::string> names;
  for (const EmbeddedTheme& theme : kEmbeddedThemes) names.emplace_back(theme.name);
  return names;
}

}  // namespace

std::string theme_name_list() { return join_names(theme_names()); }

void check_theme_name(std::string_view name, const std::string& origin) {
  const std::vector<std::string> names = theme_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw Error::invalid(origin, "'" + std::string(name) + "' is not a theme" + did_you_mean(name, names) +
                                     "; valid: " + join_names(names));
}

Theme parse_theme(std::string_view toml_text, const std::string& name, const std::string& source) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    throw Error::input(position(source, e.source()) + ": " + std::string(e.description()));
  }
  const TableReader top(root, source, "theme", kTopKeys);
  top.reject_unknown_keys();
  top.require("colors", "[colors] with background = \"#FFFFFF\"");
  const TableReader colours(*top.subtable("colors"), source, "[colors]", colour_specs());
  colours.reject_unknown_keys();

  Theme theme;
  theme.name = name;
  for (const auto& [key, accessor] : kColourKeys) {
    const toml::node* node = colours.node(key);
    if (node == nullptr) continue;  // reported below, all at once
    std::string quoted(1, '\'');    // appended: "literal" + std::string trips GCC 12's -Wrestrict
    quoted += key;
    quoted += '\'';
    const auto* text = node->as_string();
    if (text == nullptr)
      colours.fail(key, quoted + " must be a colour \"#RRGGBB\" or \"#RRGGBBAA\", got " + type_phrase(*node));
    if (!parse_colour(text->get(), accessor(theme)))
      colours.fail(key, quoted + " = '" + text->get() + "' is not a colour; valid: \"#RRGGBB\" or \"#RRGGBBAA\"");
  }
  std::vector<std::string> missing;
  for (const auto& [key, accessor] : kColourKeys)
    if (!colours.has(key)) missing.emplace_back(key);
  if (!missing.empty())
    colours.fail_at(colours.table(), "missing " + join_names(missing) + "; a theme sets every colour");
  return theme;
}

std::filesystem::path assets_dir(const std::filesystem::path& built_in) {
  if (const char* from_env = std::getenv("LINKAGE_ASSETS_DIR"); from_env != nullptr && *from_env != '\0')
    return from_env;
  std::error_code ec;
  if (!built_in.empty() && std::filesystem::is_directory(built_in, ec)) return built_in;
  return {};
}

Theme load_theme(std::string_view name, const std::filesystem::path& assets, const std::string& origin) {
  check_theme_name(name, origin);
  for (const EmbeddedTheme& embedded : kEmbeddedThemes) {
    if (embedded.name != name) continue;
    const std::filesystem::path file =
        assets.empty() ? std::filesystem::path() : assets / "themes" / (std::string(name) + ".toml");
    std::error_code ec;
    if (!file.empty() && std::filesystem::is_regular_file(file, ec)) {
      std::ifstream in(file, std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      if (!in) throw Error::failure("cannot read '" + file.string() + "'");
      return parse_theme(text.str(), std::string(name), file.string());
    }
    return parse_theme(embedded.toml, std::string(name), "embedded themes/" + std::string(name) + ".toml");
  }
  throw Error::failure(origin, "theme '" + std::string(name) + "' is not embedded");  // checked above
}

}  // namespace linkage
