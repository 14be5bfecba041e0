#include "pipeline/mechanism_clip.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <numbers>
#include <string_view>

#include "columns/mechanism_columns.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/number_format.hpp"
#include "core/parse_text.hpp"
#include "integrate/mechanism_simulation.hpp"
#include "model/mechanism_toml.hpp"
#include "pipeline/clip_page.hpp"
#include "pipeline/encode_frames.hpp"
#include "pipeline/panel_data.hpp"
#include "pipeline/simulate_rows.hpp"
#include "render/cairo_util.hpp"
#include "render/frame_layout.hpp"
#include "render/mechanism_forces.hpp"
#include "render/mechanism_painter.hpp"
#include "render/scene_painter.hpp"
#include "scene/mechanism_scene.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace fs = std::filesystem;

namespace {

// Pieces joined (report's concat is not among this module's dependencies).
[[maybe_unused]] std::string concat(std::initializer_list<std::string_view> pieces) {
  std::string out;
  for (const std::string_view piece : pieces) out.append(piece);
  return out;
}

/// The coordinate an ensemble spreads: the file's [picture] ensemble, else the first.
const sym::GeneralizedCoordinate& ensemble_coordinate(const sym::System& system) {
  for (const auto& c : system.coordinates())
    if (c.coordinate.key == system.mechanism().picture.ensemble) return c;
  return system.coordinates().front();
}

constexpr int kTrailSteps = 4;  // trail samples per frame interval, at least
// A trail's samples closer where the bodies turn fast: no body turns more than this
// between two (rad, 3 degrees: a circle drawn as a 120-gon), up to kMaxTrailSteps a frame.
constexpr double kTrailTurn = std::numbers::pi / 60;
constexpr int kMaxTrailSteps = 256;
constexpr double kPanelSamples = 4000;  // a panel's samples over the clip, at least (one per frame when fewer)
constexpr double kMargin = 0.1;         // of the view's larger side, around the whole motion
constexpr double kTitleBand = 0.1;      // of the view's height

/// What the first frame shows for `mode`: follow, the widest reach about the centroid;
/// fixed, settings.view; fit, the whole motion and its arrows with a margin, and room at
/// the top for the title and the time, which would hide what is under them.
View mechanism_view(const MechanismScene& scene, const RenderSettings& settings, CameraMode mode) {
  View view;
  switch (mode) {
    case CameraMode::follow:
      view = view_around(scene.centroid(0), (1 + kMargin) * scene.view_reach());
      break;
    case CameraMode::fixed:
      view = settings.view;
      break;
    case CameraMode::fit:
      view = view_of(scene.view_bounds(), kMargin);
      view.ymax += kTitleBand * (view.ymax - view.ymin);
      break;
  }
  return view;
}

/// Trail samples per frame interval: only when a trail is drawn.
int trail_steps(const MechanismClip& clip) {
  return clip.trails.empty() || !clip.settings.elements.has(Element::trail) ? 1 : kTrailSteps;
}

/// Trail samples over a frame interval of `span` s starting at `start`: at least
/// `minimum`, and enough that no body turns more than kTrailTurn between two at the rates
/// of `start` doubled (a body may speed up within the interval).
int trail_steps_between(const eval::MechanismSample& start, double span, int minimum) {
  double fastest = 0;
  for (std::size_t k = 2; k < start.rates.size(); k += 3) fastest = std::max(fastest, std::fabs(start.rates[k]));
  const double turns = std::ceil(2 * fastest * span / kTrailTurn);
  if (!(turns > minimum)) return minimum;  // NaN rates too
  return static_cast<int>(std::min<double>(turns, std::max(minimum, kMaxTrailSteps)));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<BodyPoint> resolve_trails(const MechanismGeometry& geometry, const std::vector<std::string>& trails,
                                      const std::string& setting = "trail") {
  std::vector<BodyPoint> points;
  for (const std::string& trail : trails) points.push_back(geometry.resolve(trail, setting));
  return points;
}

/// --points: each a point of a moving body (a ground point has no velocity to draw).
std::vector<BodyPoint> resolve_points(const MechanismGeometry& geometry, const std::vector<std::string>& names) {
  std::vector<BodyPoint> points = resolve_trails(geometry, names, "points");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].body < 0)
      throw Error::invalid(
          "points",
          "'" + names[i] + "' is a point of the ground, which does not move; give BODY.POINT of a moving body");
  return points;
}

/// The ensemble's legend row in words: "ensemble: 20 runs, angle θ of body 1 + 0 .. 1e-06 rad".
std::string ensemble_label(const sym::System& system, const MechanismClip& clip) {
  if (clip.ensemble < 2 || system.coordinates().empty()) return {};
  const std::string& key = ensemble_coordinate(system).coordinate.key;
  std::string words = key, unit;
  for (const MechanismColumn& column : mechanism_columns(system))
    if (column.name == key) {
      words = column_words(column);
      unit = column.unit;
    }
  std::string row = "ensemble: " + std::to_string(clip.ensemble) + " runs, ";
  row += words;
  row += " + 0 .. ";
  row += format_significant(clip.spread, 3);
  if (!unit.empty()) row += " " + unit;
  return row;
}

/// Another run's motion at the clip's frame times, drawn as ghosts (ensemble or compare).
struct Overlay {
  MechanismGeometry geometry;
  MechanismMotion motion;
  double ramp = 0;
  bool compare = false;
};

/// The other runs' motions with their geometry and place in the colour ramp.
std::vector<Overlay> sample_overlays(const sym::System& system, const GiNaC::exmap& initial, const MechanismClip& clip,
                                     const SimulationOptions& options, const std::vector<double>& times,
                                     ClipResult& result) {
  std::vector<MechanismMotion> motions = overlay_motions(system, initial, clip, options, times, result);
  std::vector<Overlay> overlays;
  const std::size_t members = motions.size() - (clip.compare ? 1 : 0);
  const MechanismGeometry geometry = mechanism_geometry(system);
  for (std::size_t i = 0; i < motions.size(); ++i) {
    const bool compare = i == members;
    const double ramp = members <= 1 ? 1.0 : static_cast<double>(i) / static_cast<double>(members - 1);
    overlays.push_back(
        {compare && clip.compare->system != nullptr ? mechanism_geometry(*clip.compare->system) : geometry,
         std::move(motions[i]), compare ? 0.0 : ramp, compare});
  }
  return overlays;
}

constexpr int kPathSteps = 120;  // the inset's path of the centre of mass

/// The centre of mass's path over 0 .. `duration` of a floating mechanism on which gravity
/// is the only outside force (no applied forces): a parabola through its place and
/// velocity at the first sample, exact, so a still needs no motion beyond its own time.
/// Empty when an applied force moves it (its path is not known ahead).
std::vector<Vec2> com_path(const MechanismScene& scene, const MechanismMotion& motion, double duration) {
  const MechanismGeometry& geometry = scene.geometry();
  if (!geometry.forces.empty() || motion.samples.empty() || motion.samples.front().rates.empty()) return {};
  const eval::MechanismSample& first = motion.samples.front();
  Vec2 velocity = Vec2::Zero();
  double mass = 0;
  for (std::size_t i = 0; i < geometry.bodies.size(); ++i) {
    velocity += geometry.bodies[i].mass * Vec2(first.rates[3 * i], first.rates[3 * i + 1]);
    mass += geometry.bodies[i].mass;
  }
  if (!(mass > 0)) return {};
  velocity /= mass;
  const Vec2 start = scene.centroid(0);
  std::vector<Vec2> path;
  for (int i = 0; i <= kPathSteps; ++i) {
    const double dt = duration * i / kPathSteps - motion.times.front();
    path.push_back(start + dt * velocity + Vec2(0.0, -0.5 * geometry.gravity * dt * dt));
  }
  return path;
}

/// Draws the frames of one motion: a fixed camera around the whole motion for a
/// grounded mechanism, else one following the centroid at a fixed zoom.
class MechanismFrames {
 public:
  MechanismFrames(const MechanismGeometry& geometry, const MechanismMotion& motion, const MechanismClip& clip,
                  const RenderSettings& settings, const std::vector<Overlay>& overlays, std::string ensemble_row)
      : scene_(geometry, motion, resolve_trails(geometry, clip.trails), clip.trail_seconds, clip.settings.arrow_scale,
               clip.settings.elements, clip.settings.free_body,
               mechanism_camera_mode(settings, geometry) == CameraMode::follow, resolve_points(geometry, clip.points)),
        motion_(motion),
        settings_(settings),
        labels_{clip.settings.title,
                clip.hud_run.empty() ? run_label(clip.simulation, motion.kinematic) : clip.hud_run},
        overlays_(overlays),
        shown_(clip.settings.elements) {
    labels_.ensemble = std::move(ensemble_row);
    centre_compared_ = clip.compare && clip.compare->centred;
    if (clip.compare)
      labels_.compare =
          concat({"compared: ", clip.compare->label,
                  centre_compared_ && !scene_.geometry().grounded() ? ", about this run's centroid" : ""});
    style_.theme = &clip.theme;
    style_.u = DrawStyle::unit_for(settings_.width, settings_.height);
    const CameraMode mode = mechanism_camera_mode(settings_, scene_.geometry());
    follow_ = mode == CameraMode::follow;
    camera_ = mechanism_camera(scene_, settings_, mode);
    labels_.duration = std::max({clip.settings.duration, clip.settings.at, motion.times.back()});
    labels_.follows = follow_ && !scene_.geometry().grounded();
    if (labels_.follows) labels_.com_path = com_path(scene_, motion, labels_.duration);
    // An arrow too short to carry its label is drawn dashed with its value, as the legend says.
    scene_.set_shortest_arrow(shortest_labelled_arrow_px(style_) / camera_.scale(),
                              stretched_arrow_px(style_) / camera_.scale());
    scene_.set_trail_fades(!clip.trail_cycle);
    if (mode != CameraMode::fixed) keep_legend_room(mechanism_view(scene_, settings_, mode));
  }

  void draw(std::size_t k, Frame& frame) {
    const auto start = std::chrono::steady_clock::now();
    const bool backdrop = copy_backdrop(frame);
    stats_.draw_seconds += seconds_since(start);
    const cairo::SurfacePtr surface = cairo::surface_for(frame);
    const cairo::ContextPtr cr = cairo::context(surface.get());
    paint(k, cr.get(), backdrop, &paint_cache_);
    cairo::check(cr.get(), "drawing a frame");
    cairo_surface_flush(surface.get());
  }

  /// Sample k onto any surface's context (a vector still's), at the origin; with
  /// `backdrop_painted`, over the backdrop already there; `cache`: a raster clip's, kept across frames.
  void paint(std::size_t k, cairo_t* cr, bool backdrop_painted = false, MechanismPaintCache* cache = nullptr) {
    cairo_save(cr);
    paint(
        k, [cr](PaintLayer) { return cr; }, backdrop_painted, cache);
    cairo_restore(cr);
    cairo::check(cr, "drawing a frame");
  }
  /// The same, each of the painter's steps onto its layer's context.
  void paint(std::size_t k, const LayerContexts& at, bool backdrop_painted = false,
             MechanismPaintCache* cache = nullptr) {
    const auto start = std::chrono::steady_clock::now();
    fill_list(k);
    for (const MechanismDrawList::Line& line : list_.lines)
      if (line.kind == MechanismDrawList::Line::Kind::trail)
        stats_.trail_points_drawn += static_cast<std::int64_t>(line.points.size());
    add_ghosts(k);
    const Camera camera = camera_at(k);
    // The camera a frame earlier (the samples are a frame apart): the grid streaks from there.
    const Camera earlier = k > 0 ? camera_at(k - 1) : camera;
    layout_ = paint_mechanism_frame(at, style_, camera, list_, labels_, motion_.times[k], settings_.width,
                                    settings_.height, &earlier, backdrop_painted, cache);
    ++stats_.frames_drawn;
    stats_.draw_seconds += seconds_since(start);
  }

  [[nodiscard]] const RenderStats& stats() const { return stats_; }
  [[nodiscard]] const MechanismDrawList& list() const { return list_; }
  [[nodiscard]] const ForceLayout& layout() const { return layout_; }
  [[nodiscard]] Camera camera_at(std::size_t k) const {
    return follow_ ? camera_.centred_at(scene_.centroid(k)) : camera_;
  }

 private:
  // Sample k's draw list, the legend's note included.
  void fill_list(std::size_t k) {
    scene_.frame(k, list_);
    if (labels_.follows || list_.legend.relative_velocity)  // naming G when the velocities are relative to it
      list_.legend.note = list_.legend.relative_velocity ? "the view follows the centre of mass G; the grid stays put"
                                                         : "the view follows the centre of mass; the grid stays put";
  }

  // The largest legend and scale bar over every frame under `camera`, and whether each
  // frame found both a place covering nothing drawn. Sets the scene's shortest arrows to
  // the camera's scale, as drawing with it does.
  struct LegendRoom {
    double legend_width = 0, legend_height = 0, bar_width = 0, bar_height = 0;
    bool clear = true;
  };
  LegendRoom legend_room(cairo_t* cr, const Camera& camera) {
    scene_.set_shortest_arrow(shortest_labelled_arrow_px(style_) / camera.scale(),
                              stretched_arrow_px(style_) / camera.scale());
    LegendRoom room;
    for (std::size_t k = 0; k < motion_.times.size(); ++k) {
      fill_list(k);
      const std::vector<Rect> panels = mechanism_frame_panels(cr, style_, list_, labels_, settings_.width);
      const Camera at = follow_ ? camera.centred_at(scene_.centroid(k)) : camera;
      const LegendFit fit = fit_legend(cr, style_, at, list_, settings_.width, settings_.height, panels);
      room.clear = room.clear && fit.clear;
      room.legend_width = std::max(room.legend_width, fit.legend.width);
      room.legend_height = std::max(room.legend_height, fit.legend.height);
      room.bar_width = std::max(room.bar_width, fit.scale_bar.width);
      room.bar_height = std::max(room.bar_height, fit.scale_bar.height);
    }
    return room;
  }

  // A fit or following camera under which some frame leaves the legend or its scale bar
  // no place clear of the drawing (a wide swing covering every corner in turn) shows
  // `view` beside a strip kept for them instead: at the left, the right or the bottom,
  // whichever clears every frame with the mechanism largest, then least under the title
  // and HUD. A following camera takes only a strip its frame has room for at its scale.
  void keep_legend_room(const View& view) {
    if (!shown_.has(Element::legend)) return;
    const cairo::SurfacePtr scratch = cairo::image_surface(1, 1);
    const cairo::ContextPtr cr = cairo::context(scratch.get());
    const LegendRoom needed = legend_room(cr.get(), camera_);
    if (needed.clear) return;
    fill_list(0);
    const std::vector<Rect> panels = mechanism_frame_panels(cr.get(), style_, list_, labels_, settings_.width);
    const double w = settings_.width, h = settings_.height, gap = style_.padding() + 8 * style_.u;
    enum class Side { left, right, bottom };
    const auto beside = [&](Side side, const LegendRoom& room) {
      const double across = gap + std::max(room.legend_width, room.bar_width);
      const double up = gap + std::max(room.legend_height, room.bar_height);
      Bounds area;
      area.include({side == Side::left ? across : 0.0, 0.0});
      area.include({side == Side::right ? w - across : w, side == Side::bottom ? h - up : h});
      return Camera(view, area, settings_.width, settings_.height);
    };
    const auto under_panels = [&](const Camera& camera) {  // the first frame's view, px^2
      const Vec2 low = camera.to_pixels({view.xmin, view.ymax}), high = camera.to_pixels({view.xmax, view.ymin});
      const Rect shown{low.x(), low.y(), high.x() - low.x(), high.y() - low.y()};
      double area = 0;
      for (const Rect& panel : panels) area += overlap_area(shown, panel);
      return area;
    };
    std::optional<Camera> best;
    double best_under = 0;
    for (const Side side : {Side::left, Side::right, Side::bottom}) {
      Camera camera = beside(side, needed);
      LegendRoom room = legend_room(cr.get(), camera);
      if (!room.clear) {  // a smaller scale may draw more arrows dashed: a taller legend
        room.legend_width = std::max(room.legend_width, needed.legend_width);
        room.legend_height = std::max(room.legend_height, needed.legend_height);
        room.bar_width = std::max(room.bar_width, needed.bar_width);
        room.bar_height = std::max(room.bar_height, needed.bar_height);
        camera = beside(side, room);
        room.clear = legend_room(cr.get(), camera).clear;
      }
      if (!room.clear || (follow_ && camera.scale() < camera_.scale() * (1 - 1e-12))) continue;
      const double under = under_panels(camera);
      const bool larger = best && camera.scale() > best->scale() * (1 + 1e-12);
      const bool as_large = best && camera.scale() >= best->scale() * (1 - 1e-12);
      if (!best || larger || (as_large && under < best_under)) {
        best = camera;
        best_under = under;
      }
    }
    if (best) camera_ = *best;
    scene_.set_shortest_arrow(shortest_labelled_arrow_px(style_) / camera_.scale(),
                              stretched_arrow_px(style_) / camera_.scale());
  }

  // A fixed camera's backdrop (background and grid) is the same in every frame: painted
  // once, then copied byte for byte. False (nothing copied) for a following camera.
  bool copy_backdrop(Frame& frame) {
    if (follow_ || frame.width != settings_.width || frame.height != settings_.height) return false;
    if (backdrop_.pixels.empty()) {
      backdrop_ = Frame(frame.width, frame.height);
      const cairo::SurfacePtr surface = cairo::surface_for(backdrop_);
      const cairo::ContextPtr cr = cairo::context(surface.get());
      paint_mechanism_backdrop(cr.get(), style_, camera_, shown_, labels_, frame.width, frame.height, &camera_);
      cairo::check(cr.get(), "drawing a frame's backdrop");
      cairo_surface_flush(surface.get());
    }
    if (frame.stride != backdrop_.stride) return false;
    std::copy(backdrop_.pixels.begin(), backdrop_.pixels.end(), frame.pixels.begin());
    return true;
  }

  void add_ghosts(std::size_t k) {
    for (const Overlay& overlay : overlays_) {
      MechanismDrawList::Ghost ghost;
      ghost.ramp = overlay.ramp;
      ghost.compare = overlay.compare;
      std::vector<double> pose = overlay.motion.samples[k].pose;
      if (overlay.compare && centre_compared_ && follow_) {
        // Another floating mechanism starts elsewhere and falls out of view: drawn about
        // this run's centroid instead, so the shapes and turning compare.
        Vec2 other = Vec2::Zero();
        const std::size_t bodies = overlay.geometry.bodies.size();
        for (std::size_t b = 0; b < bodies; ++b) other += Vec2(pose[3 * b], pose[3 * b + 1]);
        const Vec2 shift = scene_.centroid(k) - other / static_cast<double>(std::max<std::size_t>(bodies, 1));
        for (std::size_t b = 0; b < bodies; ++b) {
          pose[3 * b] += shift.x();
          pose[3 * b + 1] += shift.y();
        }
      }
      for (std::size_t b = 0; b < overlay.geometry.bodies.size(); ++b)
        ghost.outlines.push_back(
            {b, body_outline(overlay.geometry.bodies[b], pose, b), overlay.geometry.bodies[b].shape});
      list_.ghosts.push_back(std::move(ghost));
    }
  }

  MechanismScene scene_;
  const MechanismMotion& motion_;
  const RenderSettings& settings_;
  MechanismLabels labels_;
  DrawStyle style_;
  bool follow_ = false;
  bool centre_compared_ = false;
  Camera camera_;
  const std::vector<Overlay>& overlays_;
  MechanismDrawList list_;
  ElementSet shown_;  // the scene's elements, as its draw lists give them
  Frame backdrop_;    // a fixed camera's background and grid, once drawn
  MechanismPaintCache paint_cache_;
  ForceLayout layout_;  // the frame drawn last's
  RenderStats stats_;
};

void add_drawing(RenderStats& stats, const RenderStats& drawn) {
  stats.frames_drawn += drawn.frames_drawn;
  stats.trail_points_drawn += drawn.trail_points_drawn;
  stats.draw_seconds += drawn.draw_seconds;
}

/// One frame at `at`, sampled back over the trail's seconds (a panel's: from 0) at the
/// clip's frame rate (so the trail and the arrow scale see the same samples a clip would).
void produce_still(const sym::System& system, const GiNaC::exmap& initial, const MechanismClip& clip,
                   const ClipProgress& progress, ClipResult& result) {
  const RenderSettings& s = clip.settings;
  // Back to the trail's start, a frame interval early when it falls between frames (the
  // trail's first point is found between the two).
  const double step = s.speed / s.fps;
  const double back = (std::ceil(clip.trail_seconds / step - 1e-9) + 0.5) * step;
  const std::vector<double> times = s.still_times(s.panel.empty() ? std::min(s.at, back) : s.at);
  SimulationOptions options = clip.simulation;
  options.duration = std::max(s.at, options.dt);
  options.validate();
  PanelData panel;
  const MechanismMotion motion =
      sample_mechanism_motion(system, initial, options, times, trail_steps(clip), result, progress, s.panel, &panel,
                              clip.derived, s.elements.has(Element::acceleration), clip.prescribed);
  panel.t_end = s.at;
  const std::vector<Overlay> overlays = sample_overlays(system, initial, clip, options, times, result);
  FrameLayout layout(s, clip.theme, std::move(panel));
  MechanismFrames frames(mechanism_geometry(system), motion, clip, layout.scene_settings(), overlays,
                         ensemble_label(system, clip));
  const std::size_t last = times.size() - 1;
  write_still(
      layout, last, s.at, s, *clip.out, [&](Frame& scene) { frames.draw(last, scene); },
      [&](cairo_t* scene) { frames.paint(last, scene); }, result);
  add_drawing(result.stats, frames.stats());
}

}  // namespace

double driver_cycle_seconds(const sym::System& system) {
  const Mechanism& m = system.mechanism();
  if (m.drivers.empty())
    throw Error::invalid("trail_length", "cycle needs a [[driver]], and " + m.name + " has none; give seconds");
  const GiNaC::symbol& t = system.time();
  double period = 0;
  for (const Driver& d : m.drivers) {
    const std::string named = "driver " + d.name + "'s motion '" + d.motion.text + "'";
    const auto joint =
        std::find_if(m.joints.begin(), m.joints.end(), [&](const Joint& j) { return j.name == d.joint; });
    if (joint != m.joints.end() && joint_type_info(joint->type).motion != JointMotion::revolute)
      throw Error::invalid("trail_length", "cycle: " + named + " moves slider " + d.joint +
                                               ", whose travel does not come round; give seconds");
    const GiNaC::ex motion = system.quantity(d.motion, true)
                                 .subs(system.constants())
                                 .subs(system.constants())
                                 .subs(system.parameter_values());
    const GiNaC::ex rate = GiNaC::normal(motion.diff(t));
    if (!GiNaC::normal(rate.diff(t)).is_zero() || !GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(rate)))
      throw Error::invalid("trail_length",
                           "cycle: " + named + " does not turn at a constant rate (theta0 + omega*t); give seconds");
    const double omega = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(rate)).to_double();
    if (!(std::fabs(omega) > 0) || !std::isfinite(omega))
      throw Error::invalid("trail_length", "cycle: " + named + " does not turn (omega = 0); give seconds");
    const double own = 2 * std::numbers::pi / std::fabs(omega);
    if (period > 0 && std::fabs(own - period) > 1e-12 * period)
      throw Error::invalid("trail_length", "cycle: " + named + " has period " + format_significant(own, 6) +
                                               " s, another driver's " + format_significant(period, 6) +
                                               " s; give seconds");
    period = own;
  }
  return period;
}

double trail_seconds_of(const sym::System& system, const std::string& trail_length) {
  if (trail_length.empty()) return 2.0;
  if (trail_length == "cycle") return driver_cycle_seconds(system);
  return parse_number(trail_length, "trail_length", "");
}

CameraMode mechanism_camera_mode(const RenderSettings& settings, const MechanismGeometry& geometry) {
  if (settings.camera_chosen) return settings.camera;
  return geometry.grounded() ? CameraMode::fit : CameraMode::follow;
}

Camera mechanism_camera(const MechanismScene& scene, const RenderSettings& settings, CameraMode mode) {
  return {mechanism_view(scene, settings, mode), settings.width, settings.height};
}

MechanismMotion sample_mechanism_motion(const sym::System& system, const GiNaC::exmap& initial,
                                        const SimulationOptions& options, const std::vector<double>& frame_times,
                                        int trail_steps, ClipResult& result, const ClipProgress& progress,
                                        const std::vector<std::string>& panel_names, PanelData* panel,
                                        const std::optional<CaseSystem>& derived, bool accelerations,
                                        const PrescribedState& prescribed) {
  const auto start = std::chrono::steady_clock::now();
  const bool same_case = derived && derived->id == static_cast<CaseId>(options.case_id);
  std::vector<MechanismColumn> columns;
  if (panel != nullptr && !panel_names.empty()) {
    columns = mechanism_panel_columns(mechanism_columns(system), panel_names, &system);
    *panel = mechanism_panel(columns, frame_times.back());
  }
  const bool kinematics = accelerations || needs_kinematics(columns);
  SimulationOptions with_kinematics = options;
  with_kinematics.kinematics = kinematics;
  MechanismSimulation simulation(system, initial, with_kinematics, same_case ? derived : std::nullopt);
  MechanismMotion motion;
  motion.times = frame_times;
  motion.samples.resize(frame_times.size());
  motion.prescribed = static_cast<bool>(prescribed);
  // A prescribed motion fills Case 3's (q, q') in a copy of the initial state; nothing is integrated.
  if (prescribed && options.case_id != 3)
    throw Error::failure("a prescribed motion is in Case 3's coordinates, not Case " + std::to_string(options.case_id) +
                         "'s");
  Eigen::VectorXd given = prescribed ? simulation.state_at(0) : Eigen::VectorXd();
  const auto state_at = [&](double t) -> const Eigen::VectorXd& {
    if (!prescribed) return simulation.state_at(t);
    prescribed(t, given);
    return given;
  };
  const bool fine = trail_steps > 1;
  // The HUD's energy balance, as the energy_error column gives it; and whether the case
  // keeps a constraint whose error is worth showing (Case 1 every joint, else loops).
  MechanismColumn balance;
  balance.quantity = MechanismQuantity::energy_error;
  motion.constraints_kept = false;
  motion.kinematic = simulation.stats().kinematic;
  for (const sym::JointSystem& joint : system.joints())
    motion.constraints_kept = motion.constraints_kept || options.case_id == 1 || !joint.in_tree;
  // The panel between frames too, at least kPanelSamples over the clip: its peaks are the
  // table's, not the frames' (a force's spike lasts a few ms).
  const double panel_step = (frame_times.back() - frame_times.front()) / kPanelSamples;
  eval::MechanismSample between;
  auto add_panel = [&](double t, const Eigen::VectorXd& y, const eval::MechanismSample& sample) {
    panel->t.push_back(t);
    for (std::size_t c = 0; c < columns.size(); ++c)
      panel->curves[c].values.push_back(column_value(columns[c], t, y, sample, simulation.origin()));
  };
  const long total = static_cast<long>(frame_times.size());
  // One pass in time order: state_at only goes forward.
  for (std::size_t i = 0; i < frame_times.size(); ++i) {
    throw_if_interrupted();
    std::vector<std::pair<double, bool>> inner;  // (t, a trail's) between the frames, in time order
    const double span = i > 0 ? frame_times[i] - frame_times[i - 1] : 0;
    const int steps = i > 0 && fine ? trail_steps_between(motion.samples[i - 1], span, trail_steps) : 1;
    for (int step = 1; step < steps; ++step) inner.emplace_back(frame_times[i - 1] + span * step / steps, true);
    const int panel_steps = columns.empty() || !(panel_step > 0) ? 1 : static_cast<int>(std::ceil(span / panel_step));
    for (int step = 1; i > 0 && step < panel_steps; ++step)
      inner.emplace_back(frame_times[i - 1] + span * step / panel_steps, false);
    std::sort(inner.begin(), inner.end());
    for (const auto& [t, trail] : inner) {
      const Eigen::VectorXd& y = state_at(t);
      simulation.sample(t, y, between, !trail && kinematics);
      if (trail) {
        motion.trail_times.push_back(t);
        motion.trail_poses.push_back(between.pose);
      } else {
        add_panel(t, y, between);
      }
    }
    const Eigen::VectorXd& y = state_at(frame_times[i]);
    simulation.sample(frame_times[i], y, motion.samples[i], kinematics);
    if (!prescribed)
      motion.energy_error.push_back(column_value(balance, frame_times[i], y, motion.samples[i], simulation.origin()));
    if (!columns.empty()) add_panel(frame_times[i], y, motion.samples[i]);
    if (fine) {
      motion.trail_times.push_back(frame_times[i]);
      motion.trail_poses.push_back(motion.samples[i].pose);
    }
    if (progress) progress(ClipStage::simulate, static_cast<long>(i) + 1, total);
  }
  const std::size_t between_frames = fine ? motion.trail_times.size() - frame_times.size() : 0;
  result.stats.samples += static_cast<std::int64_t>(frame_times.size() + between_frames);
  result.stats.simulate_seconds += seconds_since(start);
  // A prescribed motion's energy does not balance: nothing to warn about.
  const std::string warning = prescribed ? std::string() : mechanism_result_warning(options, simulation.stats());
  if (!warning.empty()) result.warnings.push_back(warning);
  if (result.evaluator.empty()) result.evaluator = simulation.stats().evaluator;
  return motion;
}

std::vector<MechanismMotion> overlay_motions(const sym::System& system, const GiNaC::exmap& initial,
                                             const MechanismClip& clip, const SimulationOptions& options,
                                             const std::vector<double>& times, ClipResult& result) {
  std::vector<MechanismMotion> motions;
  ClipResult scratch;  // the main run's warnings stand for the ensemble's
  if (clip.ensemble >= 2)
    for (const GiNaC::exmap& state : ensemble_states(system, initial, clip.ensemble, clip.spread)) {
      throw_if_interrupted();
      motions.push_back(
          sample_mechanism_motion(system, state, options, times, 1, scratch, {}, {}, nullptr, clip.derived));
    }
  if (clip.compare && clip.compare->table) {
    const sym::System& other = clip.compare->system != nullptr ? *clip.compare->system : system;
    motions.push_back(table_motion(*clip.compare->table, mechanism_geometry(other), times,
                                   clip.compare->aliased ? &other.mechanism() : nullptr, &other));
  } else if (clip.compare) {
    const sym::System& other = clip.compare->system != nullptr ? *clip.compare->system : system;
    SimulationOptions compared = clip.compare->simulation;
    compared.duration = options.duration;
    scratch.warnings.clear();
    motions.push_back(sample_mechanism_motion(other, clip.compare->initial, compared, times, 1, scratch));
    for (const std::string& warning : scratch.warnings) result.warnings.push_back("compared run: " + warning);
  }
  result.stats.samples += scratch.stats.samples;
  result.stats.simulate_seconds += scratch.stats.simulate_seconds;
  return motions;
}

MechanismRun mechanism_compared_run(const std::vector<std::string>& items, const Mechanism& mechanism,
                                    const SimulationOptions& simulation, const std::string& flag,
                                    std::unique_ptr<sym::System>& system) {
  MechanismRun run;
  run.simulation = simulation;
  Mechanism other = mechanism;
  bool own_system = false;
  for (const std::string& item : items) {
    const auto equals = item.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == item.size())
      throw Error::invalid("compare",
                           "'" + item + "' is not NAME=VALUE; e.g. 2.theta=-1.2000001, integrator=rk4 or case=1");
    const std::string name = item.substr(0, equals), value = item.substr(equals + 1);
    try {
      if (name == "integrator") {
        run.simulation.integrator = parse_integrator(value, "integrator");
      } else if (name == "case") {
        if (value != "1" && value != "2" && value != "3")
          throw Error::invalid("case", "'" + value + "' is not a case; valid: 1, 2, 3");
        run.simulation.case_id = value[0] - '0';
      } else {  // by its key or its alias (the homework's theta1 for 1.theta)
        apply_setting(other, mechanism.unaliased(name) + "=" + value, flag + " " + name);
        own_system = true;
      }
    } catch (const Error& e) {
      if (e.setting() != "set") throw Error::invalid("compare", e.what());
      throw Error::invalid("compare", e.detail() + "; or integrator=NAME, case=1|2|3");
    }
    if (!run.label.empty()) run.label += ", ";
    run.label += item;
  }
  try {
    run.simulation.validate();
  } catch (const Error& e) {
    throw Error::invalid("compare", e.what());
  }
  if (own_system) {
    try {  // a setting that breaks the mechanism (L=-1) is the compared run's to report
      system = std::make_unique<sym::System>(std::move(other));
      run.initial = sym::checked_initial_state(*system).state;
    } catch (const Error& e) {
      throw Error::invalid("compare", e.what());
    }
    run.system = system.get();
  }
  return run;
}

std::vector<std::string> mechanism_pose_columns(const MechanismGeometry& geometry, const Mechanism* aliases) {
  std::vector<std::string> names{"t"};
  const auto named = [&](const std::string& key) { return aliases != nullptr ? aliases->aliased(key) : key; };
  for (const MechanismGeometry::BodyShape& body : geometry.bodies) {
    names.push_back(named(body.name + ".x"));
    names.push_back(named(body.name + ".y"));
    if (body.shape != Shape::point) names.push_back(named(body.name + ".theta"));
  }
  return names;
}

std::string motion_csv(const sym::System& system, const MechanismMotion& motion) {
  const MechanismGeometry geometry = mechanism_geometry(system);
  const Mechanism& mechanism = system.mechanism();
  std::string csv = joined_names(mechanism_pose_columns(geometry, mechanism.speaks_aliases ? &mechanism : nullptr));
  csv += '\n';
  std::vector<double> row;
  for (std::size_t k = 0; k < motion.samples.size() && k < motion.times.size(); ++k) {
    const std::vector<double>& pose = motion.samples[k].pose;
    row.assign(1, motion.times[k]);
    for (std::size_t b = 0; b < geometry.bodies.size() && 3 * b + 2 < pose.size(); ++b) {
      row.push_back(pose[3 * b]);
      row.push_back(pose[3 * b + 1]);
      if (geometry.bodies[b].shape != Shape::point) row.push_back(pose[3 * b + 2]);
    }
    csv.append(joined_values(row, ",")).append("\n");
  }
  return csv;
}

std::vector<std::string> mechanism_coordinate_columns(const sym::System& system, const Mechanism* aliases) {
  std::vector<std::string> names{"t"};
  for (const sym::GeneralizedCoordinate& c : system.coordinates())
    names.push_back(aliases != nullptr ? aliases->aliased(c.coordinate.key) : c.coordinate.key);
  return names;
}

MechanismMotion table_motion(const TrajectoryTable& table, const MechanismGeometry& geometry,
                             const std::vector<double>& times, const Mechanism* aliases, const sym::System* system) {
  const auto named = [&](const std::string& key) { return aliases != nullptr ? aliases->aliased(key) : key; };
  std::vector<std::optional<std::size_t>> columns;  // per body: x, y, theta
  for (const MechanismGeometry::BodyShape& body : geometry.bodies)
    for (const char* part : {".x", ".y", ".theta"}) columns.push_back(table.find(named(body.name + part)));
  // A body's pose the file lacks follows from the generalized coordinates, as the System
  // states it (the homework's x2, y2 from x1, y1, theta1, theta2 through the pin).
  std::vector<std::pair<std::optional<std::size_t>, GiNaC::symbol>> coordinates;
  std::vector<GiNaC::ex> computed(columns.size());
  if (system != nullptr) {
    for (const sym::GeneralizedCoordinate& c : system->coordinates())
      coordinates.emplace_back(table.find(named(c.coordinate.key)), c.symbols.q);
    for (std::size_t b = 0; b < system->bodies().size() && 3 * b + 2 < columns.size(); ++b) {
      const sym::BodySystem& body = system->bodies()[b];
      const sym::CoordinateSymbols* parts[] = {&body.x, &body.y, &body.theta};
      for (std::size_t i = 0; i < 3; ++i)
        computed[3 * b + i] = i == 2 && !body.rotates ? GiNaC::ex(0)
                                                      : GiNaC::ex(parts[i]->q)
                                                            .subs(system->to_generalized())
                                                            .subs(system->constants())
                                                            .subs(system->constants())
                                                            .subs(system->parameter_values());
    }
  }
  const bool from_coordinates =
      system != nullptr && std::all_of(coordinates.begin(), coordinates.end(), [](const auto& c) { return c.first; });
  MechanismMotion motion;
  motion.times = times;
  motion.samples.resize(times.size());
  GiNaC::exmap values;
  for (std::size_t k = 0; k < times.size(); ++k) {
    std::vector<double>& pose = motion.samples[k].pose;
    pose.assign(columns.size(), 0.0);
    for (const auto& [column, q] : coordinates)
      if (column) values[q] = table.at(*column, times[k]);
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i])
        pose[i] = table.at(*columns[i], times[k]);
      else if (from_coordinates)
        pose[i] = sym::evaluate(computed[i], values);
    }
  }
  return motion;
}

std::vector<GiNaC::exmap> ensemble_states(const sym::System& system, const GiNaC::exmap& initial, int n,
                                          double spread) {
  std::vector<GiNaC::exmap> states;
  if (system.coordinates().empty() || n < 2) return states;
  const GiNaC::symbol& q = ensemble_coordinate(system).symbols.q;
  const auto found = initial.find(q);
  const double q0 = found == initial.end() ? 0.0 : GiNaC::ex_to<GiNaC::numeric>(found->second).to_double();
  bool loops = false;
  for (const sym::JointSystem& joint : system.joints()) loops = loops || !joint.in_tree;
  for (int k = 1; k < n; ++k) {
    GiNaC::exmap state = initial;
    state[q] = q0 + spread * static_cast<double>(k) / static_cast<double>(n - 1);
    states.push_back(loops ? sym::close_loops(system, state).state : state);
  }
  return states;
}

void show_mode(MechanismClip& clip, const ModeMotion& motion) {
  clip.prescribed = motion.prescribed;
  clip.hud_run = motion.hud;
}

bool MechanismClip::is_still() const { return out && linkage::is_still(output_kind(*out, "out")); }

void MechanismClip::validate(const sym::System& system) const {
  if (!out && !frames) throw Error::invalid("out", "a clip needs an output file or a frames folder");
  std::error_code ec;
  if (out) {
    if (fs::is_directory(*out, ec))
      throw Error::invalid("out", "'" + out->string() + "' is a folder, expected a file name");
    (void)output_kind(*out, "out");
  }
  settings.validate();
  simulation.validate();
  if (out) {
    if (is_video(output_kind(*out, "out")))
      VideoWriter::validate(clip_video_options(settings, output_kind(*out, "out")));
    require_writable_directory(out->parent_path(), "out");
  }
  if (frames && fs::exists(*frames, ec) && !fs::is_directory(*frames, ec))
    throw Error::invalid("frames", "'" + frames->string() + "' exists and is not a folder");
  (void)resolve_trails(mechanism_geometry(system), trails);
  (void)resolve_points(mechanism_geometry(system), points);
  if (!(trail_seconds > 0) || !std::isfinite(trail_seconds))
    throw Error::invalid("trail_length", format_significant(trail_seconds, 6) + " s; valid: seconds > 0, or cycle");
  if (!settings.panel.empty()) (void)mechanism_panel_columns(mechanism_columns(system), settings.panel, &system);
  if (ensemble != 0 && (ensemble < 2 || ensemble > 200))
    throw Error::invalid("ensemble", std::to_string(ensemble) + " runs; expected 2 .. 200");
  if (!(spread > 0 && spread <= kMaxSpread))
    throw Error::invalid("spread", "expected a number in (0, " + format_significant(kMaxSpread, 6) +
                                       "] (rad or m, the first coordinate's unit)");
  if (compare && !compare->table) compare->simulation.validate();
}

/// The motion at every frame time, the overlays, the layout and the frames drawn from them.
struct MechanismClipFrames::Drawn {
  Drawn(const sym::System& system, const GiNaC::exmap& initial, const MechanismClip& clip, ClipResult& result,
        const ClipProgress& progress)
      : width(clip.settings.width),
        height(clip.settings.height),
        times(frame_times(clip.settings)),
        motion(sample_mechanism_motion(system, initial, clip.simulation, times, trail_steps(clip), result, progress,
                                       clip.settings.panel, &panel, clip.derived,
                                       clip.settings.elements.has(Element::acceleration), clip.prescribed)),
        overlays(sample_overlays(system, initial, clip, clip.simulation, times, result)),
        layout(clip.settings, clip.theme, ending(std::move(panel), clip.settings.duration)),
        frames(mechanism_geometry(system), motion, clip, layout.scene_settings(), overlays,
               ensemble_label(system, clip)) {}

  static std::vector<double> frame_times(const RenderSettings& s) {
    std::vector<double> times(static_cast<std::size_t>(s.frame_count()));
    for (std::size_t k = 0; k < times.size(); ++k) times[k] = s.frame_time(static_cast<long>(k));
    return times;
  }
  static PanelData ending(PanelData panel, double t_end) {
    panel.t_end = t_end;
    return panel;
  }

  int width, height;
  std::vector<double> times;
  PanelData panel;  // filled by the sampling, then the layout's
  MechanismMotion motion;
  std::vector<Overlay> overlays;
  FrameLayout layout;
  MechanismFrames frames;
};

MechanismClipFrames::MechanismClipFrames(const sym::System& system, const GiNaC::exmap& initial,
                                         const MechanismClip& clip, ClipResult& result, const ClipProgress& progress)
    : drawn_(std::make_unique<Drawn>(system, initial, clip, result, progress)) {}

MechanismClipFrames::~MechanismClipFrames() = default;

long MechanismClipFrames::count() const { return static_cast<long>(drawn_->times.size()); }

void MechanismClipFrames::draw(std::size_t k, Frame& frame) {
  if (k >= drawn_->times.size())
    throw Error::failure("frame " + std::to_string(k) + " of a clip of " + std::to_string(drawn_->times.size()));
  if (frame.width != drawn_->width || frame.height != drawn_->height)
    throw Error::failure("frame is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                         ", expected " + std::to_string(drawn_->width) + "x" + std::to_string(drawn_->height));
  drawn_->layout.draw(k, drawn_->times[k], frame, [&](Frame& scene) { drawn_->frames.draw(k, scene); });
}

void MechanismClipFrames::draw_layers(std::size_t k, const LayerContexts& at) {
  if (k >= drawn_->times.size())
    throw Error::failure("frame " + std::to_string(k) + " of a clip of " + std::to_string(drawn_->times.size()));
  drawn_->layout.draw_layers(drawn_->times[k], at, [&](const LayerContexts& scene) { drawn_->frames.paint(k, scene); });
}

double MechanismClipFrames::time(std::size_t k) const { return drawn_->times.at(k); }

Rect MechanismClipFrames::scene_rect() const { return drawn_->layout.scene_rect(); }

const RenderStats& MechanismClipFrames::stats() const { return drawn_->frames.stats(); }

Camera MechanismClipFrames::camera(std::size_t k) const { return drawn_->frames.camera_at(k); }

const MechanismDrawList& MechanismClipFrames::list() const { return drawn_->frames.list(); }

const ForceLayout& MechanismClipFrames::layout() const { return drawn_->frames.layout(); }

const MechanismMotion& MechanismClipFrames::motion() const { return drawn_->motion; }

const PanelData& MechanismClipFrames::panel() const { return drawn_->layout.panel(); }

std::vector<PanelPart> MechanismClipFrames::panel_parts() const { return drawn_->layout.panel_parts(); }

ClipResult produce_mechanism_clip(const sym::System& system, const GiNaC::exmap& initial, const MechanismClip& clip,
                                  const ClipProgress& progress) {
  clip.validate(system);
  ClipResult result;
  if (clip.frames || (clip.out && !clip.is_still())) {
    MechanismClipFrames frames(system, initial, clip, result, progress);
    const bool page = clip.out && output_kind(*clip.out, "out") == OutputKind::html;
    if (page) produce_clip_page(system, frames, clip, *clip.out, progress, result);
    if (clip.frames || !page)
      encode_frames(
          clip.out && is_video(output_kind(*clip.out, "out")) ? clip.out : std::nullopt, clip.frames, clip.settings,
          frames.count(), [&](std::size_t k, Frame& frame) { frames.draw(k, frame); }, progress, result);
    add_drawing(result.stats, frames.stats());
  }
  if (clip.is_still()) produce_still(system, initial, clip, progress, result);
  return result;
}

}  // namespace linkage
