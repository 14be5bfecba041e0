#include "render/theme.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>

#include "core/error.hpp"
#include "linkage/embedded_themes.hpp"

namespace linkage {
namespace {

std::string error_of(std::string_view toml) {
  try {
    (void)parse_theme(toml, "t", "t.toml");
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    return e.what();
  }
  return "";
}

TEST(Theme, ShippedThemesLoadAndMatchTheAssets) {
  const std::filesystem::path assets = std::filesystem::path(LINKAGE_SOURCE_DIR) / "assets";
  for (const char* name : {"light", "dark", "print"}) {
    const Theme embedded = load_theme(name, {}, "--theme");
    const Theme from_file = load_theme(name, assets, "--theme");
    EXPECT_EQ(embedded.background, from_file.background) << name;
    EXPECT_EQ(embedded.block_fill, from_file.block_fill) << name;
    // The embedded copy is the file's text as of the last configure.
    std::ifstream in(assets / "themes" / (std::string(name) + ".toml"));
    std::ostringstream text;
    text << in.rdbuf();
    bool found = false;
    for (const EmbeddedTheme& e : kEmbeddedThemes)
      if (e.name == name) {
        found = true;
        EXPECT_EQ(e.toml, text.str()) << name << ": re-run cmake to embed the edited palette";
      }
    EXPECT_TRUE(found) << name;
  }
  EXPECT_EQ(theme_name_list(), "dark, light, print");
}

TEST(Theme, LightThemeColours) {
  const Theme light = load_theme("light", {}, "--theme");
  EXPECT_EQ(light.background, (Rgba{1, 1, 1, 1}));
  EXPECT_NEAR(light.pin_force.r, 0xD5 / 255.0, 1e-15);      // Okabe-Ito vermillion
  EXPECT_NEAR(light.block_fill[0].a, 0x4D / 255.0, 1e-15);  // translucent
}

TEST(Theme, UnknownThemeNamesTheChoices) {
  try {
    (void)load_theme("neon", {}, "--theme");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "--theme: 'neon' is not a theme; valid: dark, light, print");
  }
  // The render option's check (flag or lesson key) and load_theme give the same words.
  for (const auto& check : {std::function<void()>([] { check_theme_name("lihgt", "theme"); }),
                            std::function<void()>([] { (void)load_theme("lihgt", {}, "theme"); })}) {
    try {
      check();
      FAIL();
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()),
                "theme: 'lihgt' is not a theme (did you mean 'light'?); valid: dark, light, print");
    }
  }
  EXPECT_THROW(check_theme_name("", "theme"), Error);
  EXPECT_THROW(check_theme_name("dark,light", "theme"), Error);
  EXPECT_NO_THROW(check_theme_name("print", "theme"));
}

TEST(Theme, BadPalettesNameFileLineAndColumn) {
  std::string light(kEmbeddedThemes[1].toml);
  EXPECT_EQ(error_of(light), "");
  // Read by TableReader: "file:line:column: context: problem; valid ...".
  EXPECT_EQ(error_of("[colors]\nbackground = \"#FFFFFF\"\nvelocty = \"#000000\"\n"),
            "t.toml:3:1: [colors]: unknown key 'velocty' (did you mean 'velocity'?); valid keys: background, grid, "
            "text, text_muted, panel, panel_edge, block1_fill, block1_edge, block2_fill, block2_edge, pin_fill, "
            "pin_edge, pin_force, gravity, velocity, trail, com, motor");
  EXPECT_EQ(error_of("[colors]\nbackground = \"#FFF\"\n"),
            "t.toml:2:14: [colors]: 'background' = '#FFF' is not a colour; valid: \"#RRGGBB\" or \"#RRGGBBAA\"");
  EXPECT_EQ(error_of("[colors]\nbackground = 3\n"),
            "t.toml:2:14: [colors]: 'background' must be a colour \"#RRGGBB\" or \"#RRGGBBAA\", got an integer");
  EXPECT_EQ(error_of("[colors]\nbackground = \"#FFFFFF\"\n"),
            "t.toml:1:1: [colors]: missing grid, text, text_muted, panel, panel_edge, block1_fill, block1_edge, "
            "block2_fill, block2_edge, pin_fill, pin_edge, pin_force, gravity, velocity, trail, com, motor; a theme "
            "sets every colour");
  EXPECT_NE(error_of("[colors\n").find("t.toml:1:"), std::string::npos);
  EXPECT_EQ(error_of("[fonts]\n"), "t.toml:1:2: theme: unknown key 'fonts'; valid keys: colors");
  EXPECT_EQ(error_of("[colours]\n"),
            "t.toml:1:2: theme: unknown key 'colours' (did you mean 'colors'?); valid keys: colors");
  EXPECT_EQ(error_of("# nothing\n"),
            "t.toml:1:1: theme: the key 'colors' is required, e.g. [colors] with background = \"#FFFFFF\"");
  EXPECT_EQ(error_of("colors = 3\n"), "t.toml:1:10: theme: 'colors' must be a table, got an integer");
}

}  // namespace
}  // namespace linkage
