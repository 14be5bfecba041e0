#include "render/theme.hpp"

#include <gtest/gtest.h>

#include <fstream>
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
}

TEST(Theme, BadPalettesNameFileLineAndColumn) {
  std::string light(kEmbeddedThemes[1].toml);
  EXPECT_EQ(error_of(light), "");
  EXPECT_NE(error_of("[colors]\nbackground = \"#FFFFFF\"\nvelocty = \"#000000\"\n")
                .find("t.toml:3:1: unknown colour 'velocty'"),
            std::string::npos);
  EXPECT_NE(error_of("[colors]\nbackground = \"#FFF\"\n").find("t.toml:2:14: background must be a colour"),
            std::string::npos);
  EXPECT_NE(error_of("[colors]\nbackground = 3\n").find("must be a colour"), std::string::npos);
  EXPECT_NE(error_of("[colors]\nbackground = \"#FFFFFF\"\n").find("is missing grid, text"), std::string::npos);
  EXPECT_NE(error_of("[colors\n").find("t.toml:1:"), std::string::npos);
  EXPECT_NE(error_of("[fonts]\n").find("unknown key 'fonts'"), std::string::npos);
}

}  // namespace
}  // namespace linkage
