#include "pipeline/render_options.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>

#include "core/angle_unit.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "core/parse_text.hpp"
#include "pipeline/clip_result.hpp"
#include "render/theme.hpp"
#include "scene/arrow_scale.hpp"
#include "scene/elements.hpp"

namespace linkage {

struct RenderDraft {
  const RenderTarget& target;
  RenderRequest request;
  std::vector<std::string> show, hide;  // applied together at the end
  std::optional<std::string> camera, view;
  bool at = false;  // given
};

namespace {

// "pin" is the joint kind's other name, as --show's pin-force is joint-force's.
constexpr std::array<std::string_view, 8> kMechanismArrowKinds{"joint",  "pin",      "applied",      "gravity",
                                                               "spring", "velocity", "acceleration", "driver"};

/// Runs `parse`, whose errors are worded "NAME: ...", and makes them the setting's.
template <typename Parse>
auto as_setting(const std::string& name, Parse parse) {
  try {
    return parse();
  } catch (const Error& e) {
    const std::string what = e.what();
    if (!e.setting().empty() || what.rfind(name + ": ", 0) != 0) throw;
    throw Error::invalid(name, what.substr(name.size() + 2));
  }
}

void quality(RenderDraft& d, const std::string& text) {
  const Quality& q = parse_quality(text, "quality");
  d.request.settings.width = q.width;
  d.request.settings.height = q.height;
  d.request.settings.fps = q.fps;
}

void size(RenderDraft& d, const std::string& text) {
  parse_size(text, "size", d.request.settings.width, d.request.settings.height);
}

void fps(RenderDraft& d, const std::string& text) {
  const double value = parse_number(text, "fps", "");
  if (value != std::floor(value) || std::fabs(value) > 1e9)
    throw Error::invalid("fps", "'" + text + "' is not a whole number");
  d.request.settings.fps = static_cast<int>(value);  // its range checked with the others
}

void speed(RenderDraft& d, const std::string& text) {
  d.request.settings.speed = parse_number(text, "speed", "simulated s per video s");
}

void at(RenderDraft& d, const std::string& text) {
  d.request.settings.at = parse_number(text, "at", "s");
  d.at = true;
}

void camera(RenderDraft& d, const std::string& text) {
  (void)parse_camera(text, "camera");
  d.camera = text;
}

void view(RenderDraft& d, const std::string& text) { d.view = text; }

void show(RenderDraft& d, const std::string& text) { d.show.push_back(text); }

void hide(RenderDraft& d, const std::string& text) { d.hide.push_back(text); }

void theme(RenderDraft& d, const std::string& text) {
  check_theme_name(text, "theme");
  d.request.settings.theme = text;
}

void title(RenderDraft& d, const std::string& text) {
  d.request.settings.title = text;
  d.request.titled = true;
}

void arrow_scale(RenderDraft& d, const std::string& text) {
  d.request.settings.arrow_scale =
      as_setting("arrow_scale", [&] { return parse_arrow_scale_request(text, "arrow_scale", kMechanismArrowKinds); });
  for (auto& [kind, units] : d.request.settings.arrow_scale.fixed)
    if (kind == "pin") kind = "joint";
}

void panel(RenderDraft& d, const std::string& text) {
  d.request.settings.panel = split_commas(text);
  if (d.request.settings.panel.empty()) throw Error::invalid("panel", "the list is empty; give at least one quantity");
  // Each name is checked against the mechanism's columns when the clip is (mechanism_clip).
}

void angles(RenderDraft& d, const std::string& text) {
  d.request.settings.angles = as_setting("angles", [&] { return parse_angle_unit(text, "angles"); });
}

void append_items(std::vector<std::string>& to, const std::string& text) {
  for (std::string& item : split_commas(text)) to.push_back(std::move(item));
}

void trail(RenderDraft& d, const std::string& text) { append_items(d.request.trails, text); }

void trail_length(RenderDraft& d, const std::string& text) {
  if (text != "cycle") {
    const std::string valid = "; valid: seconds > 0, or cycle (one period of the driver's motion)";
    double value = 0;
    try {
      value = parse_number(text, "trail_length", "");
    } catch (const Error&) {
      throw Error::invalid("trail_length", "'" + text + "' is not a number" + valid);
    }
    if (!(value > 0) || !std::isfinite(value)) throw Error::invalid("trail_length", "'" + text + "' s" + valid);
  }
  d.request.trail_length = text;
}

void points(RenderDraft& d, const std::string& text) { append_items(d.request.points, text); }

void ensemble(RenderDraft& d, const std::string& text) {
  const bool whole = !text.empty() && text.size() < 5 && text.find_first_not_of("0123456789") == std::string::npos;
  const int n = whole ? std::stoi(text) : -1;
  if (n < 2 || n > 200) throw Error::invalid("ensemble", "'" + text + "' is not a whole number of runs in 2 .. 200");
  d.request.ensemble = n;
}

void spread(RenderDraft& d, const std::string& text) {
  if (d.request.ensemble == 0) throw Error::invalid("spread", "applies only with " + d.target.spell("ensemble") + " N");
  const std::string valid = "; valid: 0 < spread <= " + format_significant(kMaxSpread, 6) + " (rad or m)";
  double value = 0;
  try {
    value = parse_number(text, "spread", "");
  } catch (const Error&) {
    throw Error::invalid("spread", "'" + text + "' is not a finite number" + valid);
  }
  if (!(value > 0 && value <= kMaxSpread)) throw Error::invalid("spread", "'" + text + "' is out of range" + valid);
  d.request.spread = value;
}

void compare(RenderDraft& d, const std::string& text) { d.request.compare = text; }

std::vector<RenderOption> make_options() {
  std::string presets;
  for (const Quality& q : kQualities) {
    presets += presets.empty() ? "" : ", ";
    presets += std::string(q.name) + " " + std::to_string(q.width) + "x" + std::to_string(q.height) + "@" +
               std::to_string(q.fps);
  }
  using V = RenderValue;
  return {
      {"quality", V::string, "string", "NAME", "\"medium\"",
       "Size and frame rate preset: " + presets + "; size and fps override it", quality},
      {"size", V::string, "string", "WxH", "\"1280x720\"", "Frame size WIDTHxHEIGHT in pixels, even, at most 7680x4320",
       size},
      {"fps", V::integer, "integer", "N", "30", "Frames per second, 1 .. 240", fps},
      {"speed", V::number, "number", "X", "1", "Simulated seconds per second of video; below 1 is slow motion", speed},
      {"at", V::number, "number", "S", "0", "The time in s a still shows; a clip shows 0 .. duration", at},
      {"camera", V::string, "string", "MODE", "\"follow\" (\"fixed\" with a view)",
       "follow (keeps the falling centre of mass in view), fixed (shows the view) or fit (the whole motion); a "
       "mechanism's default: fit when grounded, follow when floating",
       camera},
      {"view", V::string, "string", "X0,Y0,X1,Y1|fbd", "none",
       "World rectangle xmin,ymin,xmax,ymax in metres for the fixed camera (implied by it), or fbd: the free-body "
       "view (the bodies drawn apart at their joints, each with every force on it)",
       view},
      {"show", V::list, "list of strings", "LIST", "none",
       "Elements to show (comma-separated): " + element_name_list() +
           "; equations draws the case's equations under the motion as `linkage solve` prints them; a "
           "mechanism's bodies, joints and joint-force are blocks, pin and pin-force",
       show},
      {"hide", V::list, "list of strings", "LIST", "none",
       "Elements to hide; the default shows all but velocity, axes and equations", hide},
      {"theme", V::string, "string", "NAME", "\"light\"",
       "Colours: " + theme_name_list() + " (palettes in assets/themes)", theme},
      {"title", V::string, "string", "TEXT", "the render default",
       "Title line (default \"" + RenderSettings{}.title + "\", or the mechanism's title; \"\" for none)", title},
      {"arrow_scale", V::string, "string", "SPEC", "each kind its own",
       "Arrow lengths: each kind its own scale (default); common (every force one scale, so the pin force reads "
       "against gravity; common=N_PER_CM sets it); KIND=N_PER_CM,... fixes kinds (pin, gravity, velocity; a "
       "mechanism's joint (or pin), applied, gravity, spring, velocity, acceleration, driver). Arrows too short to see "
       "are "
       "drawn dashed at a least "
       "length, labelled with "
       "their value",
       arrow_scale},
      {"panel", V::list, "list of strings", "LIST", "none",
       "Plot these quantities beside the motion, with a cursor at the frame's time: theta1,theta2 (the names a "
       "lesson's plot step takes; a mechanism's trajectory columns, e.g. 2.theta,B.force_x; or NAME=EXPRESSION "
       "over them, e.g. gamma=4.theta-3.theta)",
       panel},
      {"angles", V::string, "string", "rad|deg", "\"rad\"",
       "Unit of the panel's angles and angular rates: rad or deg (axis in deg, deg/s)", angles},
      {"trail", V::list, "list of strings", "BODY.POINT", "none",
       "Draw the path of a body's point over the last trail_length (2 s), e.g. 3.B (a four-bar's coupler curve); "
       "default: the "
       "file's [picture] trail (the homework's P)",
       trail},
      {"trail_length", V::string, "string", "S|cycle", "\"2\"",
       "How long a trail is: seconds (\"2.5\"), or cycle: one period of the driver's motion (2 pi/|omega| for a "
       "motion theta0 + omega*t), so a coupler curve closes",
       trail_length},
      {"points", V::list, "list of strings", "BODY.POINT", "none",
       "Draw the velocity and acceleration of these points (with --show velocity,acceleration), e.g. 3.P,4.B, each "
       "arrow labelled with its magnitude",
       points},
      {"ensemble", V::integer, "integer", "N", "none",
       "Draw N runs (2 .. 200) starting up to spread apart, faint in a colour ramp behind the main run (chaos "
       "fanning out): in the file's [picture] ensemble coordinate (the homework's theta1), else the first",
       ensemble},
      {"spread", V::number, "number", "X", "1e-6",
       "The ensemble's largest initial offset, rad or m; run k starts spread k/(N-1) away", spread},
      {"compare", V::list, "list of strings", "SETTINGS|FILE", "none",
       "Overlay a second run in a second colour: NAME=VALUE,... settings (the homework's input names "
       "theta1=0.1000001, L=0.4; a mechanism's set names 2.theta=-1.2000001; integrator=NAME, case=N); with "
       "`linkage render` also FILE.csv, a trajectory as linkage simulate writes it (e.g. your own integrator's), "
       "interpolated linearly in t at each frame, or another mechanism (FILE.toml or a shipped name) whose bodies "
       "have the same names, run with the same settings",
       compare},
  };
}

}  // namespace

std::span<const RenderOption> render_options() {
  static const std::vector<RenderOption> options = make_options();
  return options;
}

RenderRequest resolve_render_options(const std::vector<std::pair<std::string, std::string>>& given,
                                     const RenderTarget& target, RenderSettings base) {
  RenderDraft d{target, {}, {}, {}, {}, {}, false};
  d.request.settings = std::move(base);
  for (const RenderOption& option : render_options())
    for (const auto& [name, text] : given)
      if (name == option.name) option.apply(d, text);
  RenderSettings& s = d.request.settings;
  // A view implies the fixed camera; with another camera it is a mistake. The free-body
  // view (fbd) goes with any camera.
  s.free_body = d.view == "fbd";
  const std::string rectangle = s.free_body ? "" : d.view.value_or("");
  s.camera = d.camera ? parse_camera(*d.camera, "camera") : rectangle.empty() ? CameraMode::follow : CameraMode::fixed;
  s.camera_chosen = d.camera.has_value() || !rectangle.empty();
  if (!rectangle.empty()) {
    s.view = parse_view(rectangle, "view");
    if (s.camera != CameraMode::fixed)
      throw Error::invalid("view", "applies only to " + target.spell("camera") + " fixed (the " + *d.camera +
                                       " camera chooses its own view)");
  } else if (s.camera == CameraMode::fixed) {
    throw Error::invalid("camera", "fixed needs " + target.spell("view") + " xmin,ymin,xmax,ymax (metres)");
  }
  apply_show_hide(s.elements, d.show, d.hide);
  s.validate();
  if (d.at && target.page)
    throw Error::invalid("at", "a page shows every time 0 .. " + target.spell("duration") + " on its slider; " +
                                   target.spell("at") + " applies to a still (" + target.spell("out") +
                                   " FILE.png, .svg or .pdf)");
  if (d.at && !target.still)
    throw Error::invalid("at", "applies to a still (" + target.spell("out") + " FILE.png, .svg or .pdf" +
                                   "); a clip shows 0 .. " + target.spell("duration"));
  return std::move(d.request);
}

}  // namespace linkage
