// The one table of render options: each value as text, checked and applied once for the
// render command's flags and a lesson's render step keys.
#include "pipeline/render_options.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/error.hpp"

namespace linkage {
namespace {

using Given = std::vector<std::pair<std::string, std::string>>;

RenderTarget flags(bool still = false) {
  RenderTarget t;
  t.still = still;
  t.spell = [](std::string_view name) {
    std::string flag = "--" + std::string(name);
    std::replace(flag.begin(), flag.end(), '_', '-');
    return flag;
  };
  return t;
}

/// The error `given` makes: "SETTING|DETAIL", or "" when there is none.
std::string error_of(const Given& given, const RenderTarget& target = flags()) {
  try {
    (void)resolve_render_options(given, target);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    return e.setting() + "|" + e.detail();
  }
  return "";
}

TEST(RenderOptions, NamesAreUniqueAndEachIsDocumented) {
  std::set<std::string_view> names;
  for (const RenderOption& o : render_options()) {
    EXPECT_TRUE(names.insert(o.name).second) << o.name;
    EXPECT_FALSE(o.doc.empty()) << o.name;
    EXPECT_FALSE(o.placeholder.empty()) << o.name;
    EXPECT_NE(o.apply, nullptr) << o.name;
  }
  EXPECT_EQ(names.size(), 20U);
}

TEST(RenderOptions, APlainDefaultGivenAsTextChangesNothing) {
  const RenderSettings defaults = resolve_render_options({}, flags()).settings;
  int plain = 0;
  for (const RenderOption& o : render_options()) {
    std::string text(o.default_text);
    std::erase(text, '"');
    if (text == "none" || text.find(' ') != std::string::npos || o.name == "spread") continue;
    ++plain;
    const RenderSettings s = resolve_render_options({{std::string(o.name), text}}, flags(true)).settings;
    EXPECT_EQ(s.width, defaults.width) << o.name;
    EXPECT_EQ(s.height, defaults.height) << o.name;
    EXPECT_EQ(s.fps, defaults.fps) << o.name;
    EXPECT_EQ(s.speed, defaults.speed) << o.name;
    EXPECT_EQ(s.at, defaults.at) << o.name;
    EXPECT_EQ(s.theme, defaults.theme) << o.name;
    EXPECT_EQ(s.angles, defaults.angles) << o.name;
  }
  EXPECT_EQ(plain, 8);  // quality, size, fps, speed, at, theme, angles, trail_length
  const RenderRequest fan = resolve_render_options({{"ensemble", "3"}, {"spread", "1e-6"}}, flags());
  EXPECT_EQ(fan.spread, RenderRequest{}.spread);
}

TEST(RenderOptions, AppliedInTheTablesOrderWhateverTheOrderGiven) {
  const RenderSettings s = resolve_render_options({{"size", "640x360"}, {"quality", "high"}}, flags()).settings;
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 360);
  EXPECT_EQ(s.fps, 60);  // the preset's, size overriding only the frame
  const RenderRequest fan = resolve_render_options({{"spread", "0.25"}, {"ensemble", "7"}}, flags());
  EXPECT_EQ(fan.ensemble, 7);
  EXPECT_EQ(fan.spread, 0.25);
}

TEST(RenderOptions, ListsAreCommaJoinedText) {
  const RenderRequest r = resolve_render_options(
      {{"show", "velocity,axes"}, {"hide", "grid"}, {"panel", "theta1,theta2"}, {"compare", "theta1=0.2,case=1"}},
      flags());
  EXPECT_TRUE(r.settings.elements.has(Element::velocity));
  EXPECT_TRUE(r.settings.elements.has(Element::axes));
  EXPECT_FALSE(r.settings.elements.has(Element::grid));
  EXPECT_EQ(r.settings.panel, (std::vector<std::string>{"theta1", "theta2"}));
  EXPECT_EQ(r.compare, "theta1=0.2,case=1");
  const RenderRequest m = resolve_render_options({{"trail", "3.B,2.A"}}, flags());
  EXPECT_EQ(m.trails, (std::vector<std::string>{"3.B", "2.A"}));
}

TEST(RenderOptions, CameraAndView) {
  EXPECT_EQ(resolve_render_options({}, flags()).settings.camera, CameraMode::follow);
  const RenderSettings fixed = resolve_render_options({{"view", "-1,-2,1,0.5"}}, flags()).settings;
  EXPECT_EQ(fixed.camera, CameraMode::fixed);
  EXPECT_EQ(fixed.view.xmin, -1);
  EXPECT_EQ(fixed.view.ymax, 0.5);
  const RenderSettings fbd = resolve_render_options({{"view", "fbd"}, {"camera", "fit"}}, flags()).settings;
  EXPECT_TRUE(fbd.free_body);
  EXPECT_EQ(fbd.camera, CameraMode::fit);
  EXPECT_EQ(error_of({{"camera", "fit"}, {"view", "0,0,1,1"}}),
            "view|applies only to --camera fixed (the fit camera chooses its own view)");
  EXPECT_EQ(error_of({{"camera", "fixed"}}), "camera|fixed needs --view xmin,ymin,xmax,ymax (metres)");
  EXPECT_EQ(error_of({{"camera", "orbit"}}), "camera|'orbit' is not a camera; valid: follow, fixed, fit");
}

// A lesson's render keys and the CLI's flags read through these: a typo gets the nearest name.
TEST(RenderOptions, MisspeltWordsSuggestTheNearestValidOne) {
  EXPECT_EQ(error_of({{"camera", "folow"}}),
            "camera|'folow' is not a camera (did you mean 'follow'?); valid: follow, "
            "fixed, fit");
  EXPECT_EQ(error_of({{"quality", "hgh"}}),
            "quality|'hgh' is not a quality (did you mean 'high'?); valid: low "
            "(854x480@30), medium (1280x720@30), high (1920x1080@60), 4k (3840x2160@60)");
  EXPECT_EQ(error_of({{"angles", "degs"}}),
            "angles|'degs' is not an angle unit (did you mean 'deg'?); valid: rad, deg");
  EXPECT_EQ(error_of({{"theme", "drak"}}),
            "theme|'drak' is not a theme (did you mean 'dark'?); valid: dark, light, "
            "print");
  EXPECT_EQ(error_of({{"show", "velocty"}}).rfind("show|'velocty' is not an element (did you mean 'velocity'?)", 0),
            0U);
}

TEST(RenderOptions, BadValuesNameTheirOptionAndTheRange) {
  EXPECT_EQ(error_of({{"fps", "29.97"}}), "fps|'29.97' is not a whole number");
  EXPECT_EQ(error_of({{"fps", "500"}}), "fps|500 is outside 1 .. 240");
  EXPECT_EQ(error_of({{"speed", "fast"}}), "speed|'fast' is not a number (simulated s per video s)");
  EXPECT_EQ(error_of({{"theme", "neon"}}), "theme|'neon' is not a theme; valid: dark, light, print");
  EXPECT_EQ(error_of({{"theme", "dark,light"}}), "theme|'dark,light' is not a theme; valid: dark, light, print");
  EXPECT_EQ(error_of({{"angles", "grad"}}),
            "angles|'grad' is not an angle unit (did you mean 'rad'?); valid: rad, deg");
  EXPECT_EQ(error_of({{"ensemble", "201"}}), "ensemble|'201' is not a whole number of runs in 2 .. 200");
  EXPECT_EQ(error_of({{"ensemble", "4"}, {"spread", "0"}}),
            "spread|'0' is out of range; valid: 0 < spread <= 1000 (rad or m)");
  // Issue 22 F05: 1e308 passed here (and a lesson's --check) and overflowed in the run.
  EXPECT_EQ(error_of({{"ensemble", "4"}, {"spread", "1e308"}}),
            "spread|'1e308' is out of range; valid: 0 < spread <= 1000 (rad or m)");
  EXPECT_EQ(error_of({{"spread", "1e-3"}}), "spread|applies only with --ensemble N");
  EXPECT_EQ(error_of({{"panel", ""}}), "panel|the list is empty; give at least one quantity");
  // An unknown panel name is refused against the mechanism's columns: mechanism_clip_test, render_output_test.
  EXPECT_EQ(error_of({{"arrow_scale", "pin=0"}}).rfind("arrow_scale|'pin=0' has no positive number", 0), 0U);
  EXPECT_EQ(error_of({{"size", "65x36"}}).rfind("size|size 65x36 must have an even width and height", 0), 0U);
}

TEST(RenderOptions, AtIsAStillsAndEveryPictureOptionIsAMechanismsToo) {
  EXPECT_EQ(error_of({{"at", "1"}}),
            "at|applies to a still (--out FILE.png, .svg or .pdf); a clip shows 0 .. --duration");
  EXPECT_EQ(resolve_render_options({{"at", "1.5"}}, flags(true)).settings.at, 1.5);
  // Issue 23: the camera, a view (a rectangle or fbd), --show and --hide apply to a mechanism too.
  const RenderSettings fit = resolve_render_options({{"camera", "fit"}}, flags()).settings;
  EXPECT_EQ(fit.camera, CameraMode::fit);
  EXPECT_TRUE(fit.camera_chosen);
  EXPECT_FALSE(resolve_render_options({}, flags()).settings.camera_chosen);
  const RenderSettings fixed = resolve_render_options({{"view", "-1,-2,3,4"}}, flags()).settings;
  EXPECT_EQ(fixed.camera, CameraMode::fixed);
  EXPECT_EQ(fixed.view.ymax, 4.0);
  EXPECT_TRUE(resolve_render_options({{"view", "fbd"}}, flags()).settings.free_body);
  const ElementSet shown =
      resolve_render_options({{"show", "velocity,gravity"}, {"hide", "legend,labels,joint-force"}}, flags())
          .settings.elements;
  EXPECT_TRUE(shown.has(Element::velocity));
  EXPECT_TRUE(shown.has(Element::gravity));
  EXPECT_FALSE(shown.has(Element::legend));
  EXPECT_FALSE(shown.has(Element::labels));
  EXPECT_FALSE(shown.has(Element::pin_force));  // "joint-force" is pin-force's other name
  EXPECT_TRUE(resolve_render_options({{"show", "equations"}}, flags()).settings.elements.has(Element::equations));
  // A mechanism's arrows are its joints', applied loads', gravity's, springs' and velocities'.
  EXPECT_EQ(error_of({{"arrow_scale", "block=2"}}).substr(0, 12), "arrow_scale|");
  EXPECT_EQ(resolve_render_options({{"arrow_scale", "joint=2"}}, flags()).settings.arrow_scale.fixed_for("joint"), 2.0);
}

}  // namespace
}  // namespace linkage
