#include "pipeline/modes_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/frame.hpp"
#include "core/number_format.hpp"
#include "encode/png_writer.hpp"
#include "pipeline/mode_motion.hpp"
#include "render/cairo_util.hpp"
#include "render/mechanism_painter.hpp"
#include "render/overlays.hpp"
#include "render/panel.hpp"
#include "render/text.hpp"
#include "render/vector_still.hpp"
#include "symbolic/loop_closure.hpp"

namespace linkage {
namespace {

constexpr int kArcSamples = 32;   // poses from -A to +A: the trails' resolution
constexpr double kMargin = 0.08;  // of the views' larger side, around every panel's motion
constexpr int kCaptionLines = 3;  // the heading and the shape, wrapped once

/// What a panel leaves out: the loads of a pose that is not a motion, and the frame's
/// own title, HUD and legend (the sheet has one title; its subtitle says what is drawn).
ElementSet panel_elements(ElementSet shown) {
  for (const Element e :
       {Element::hud, Element::legend, Element::title, Element::equations, Element::pin_force, Element::gravity,
        Element::velocity, Element::spring_force, Element::loads, Element::acceleration, Element::motor})
    shown.hide(e);
  return shown;
}

/// The tree coordinates `q` as a state at rest.
GiNaC::exmap state_of(const sym::System& system, const Eigen::VectorXd& q) {
  GiNaC::exmap state;
  const auto& coordinates = system.coordinates();
  for (std::size_t i = 0; i < coordinates.size(); ++i) {
    state[coordinates[i].symbols.q] = q[static_cast<Eigen::Index>(i)];
    state[coordinates[i].symbols.q_dot] = 0;
  }
  return state;
}

/// The tree coordinates `q` at rest with the loops closed again (the independent ones kept).
Eigen::VectorXd closed(const sym::System& system, const Eigen::VectorXd& q) {
  bool loops = false;
  for (const sym::JointSystem& joint : system.joints()) loops = loops || !joint.in_tree;
  if (!loops) return q;
  const GiNaC::exmap done = sym::close_loops(system, state_of(system, q)).state;
  const auto& coordinates = system.coordinates();
  Eigen::VectorXd out(q.size());
  for (std::size_t i = 0; i < coordinates.size(); ++i)
    out[static_cast<Eigen::Index>(i)] =
        GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(done.at(coordinates[i].symbols.q))).to_double();
  return out;
}

/// "2.theta : 3.theta = 0.707 : 1": the shape as `linkage modes` gives it (largest 1), a
/// component at round-off (a node of the mode) as 0.
std::string shape_words(const Linearization& linear, const Mode& mode) {
  std::string names, values;
  for (std::size_t i = 0; i < linear.coordinates.size(); ++i) {
    const double v = mode.shape[static_cast<Eigen::Index>(i)];
    names += (i > 0 ? " : " : "") + linear.coordinates[i];
    values += (i > 0 ? " : " : "") + (std::fabs(v) < 1e-12 ? std::string("0") : format_significant(v, 3));
  }
  return names + " = " + values;
}

std::string heading_of(int number, const Mode& mode, bool damped) {
  const std::string name = "mode " + std::to_string(number) + " \u00b7 ";
  switch (mode.kind) {
    case Mode::Kind::oscillation:
      return name + format_significant(mode.omega / (2 * std::numbers::pi), 3) + " Hz (" +
             format_significant(mode.omega, 3) + " rad/s)" +
             (damped ? ", \u03b6 = " + format_significant(mode.damping_ratio, 3) : "");
    case Mode::Kind::unstable:
      return name + "unstable, growth rate " + format_significant(mode.growth_rate, 3) + " 1/s";
    case Mode::Kind::neutral:
      return name + "neutral (no stiffness)";
  }
  return name;
}

std::string shape_line(const Linearization& linear, const Mode& mode) {
  switch (mode.kind) {
    case Mode::Kind::oscillation:
      return shape_words(linear, mode);
    case Mode::Kind::unstable:
      return "grows as exp(" + format_significant(mode.growth_rate, 3) + " t) from the equilibrium: no oscillation (" +
             shape_words(linear, mode) + ")";
    case Mode::Kind::neutral:
      return "drifts without coming back: no oscillation (" + shape_words(linear, mode) + ")";
  }
  return {};
}

std::vector<MechanismDrawList::Outline> outlines_of(const MechanismGeometry& geometry,
                                                    const std::vector<double>& pose) {
  std::vector<MechanismDrawList::Outline> outlines;
  for (std::size_t b = 0; b < geometry.bodies.size(); ++b)
    outlines.push_back({b, body_outline(geometry.bodies[b], pose, b), geometry.bodies[b].shape});
  return outlines;
}

/// Every named point of a body, its centre and a rod's ends, that moves between the first
/// and last samples: the trails of the mode's motion.
std::vector<BodyPoint> moving_points(const MechanismGeometry& geometry, const MechanismMotion& motion) {
  std::vector<BodyPoint> points;
  const auto add = [&](const BodyPoint& p) {
    const Vec2 a = world_point(motion.samples.front().pose, p), b = world_point(motion.samples.back().pose, p);
    for (const BodyPoint& other : points)  // a pin's point on both its bodies: one trail
      if ((world_point(motion.samples.front().pose, other) - a).norm() < 1e-9 &&
          (world_point(motion.samples.back().pose, other) - b).norm() < 1e-9)
        return;
    if ((a - b).norm() > 1e-9) points.push_back(p);
  };
  for (std::size_t b = 0; b < geometry.bodies.size(); ++b) {
    const MechanismGeometry::BodyShape& shape = geometry.bodies[b];
    const int body = static_cast<int>(b);
    for (const auto& [name, local] : shape.points) add({body, local});
    add({body, Vec2::Zero()});
    switch (shape.shape) {
      case Shape::rod:  // its free end swings farthest
        add({body, Vec2(0.5 * shape.length, 0)});
        add({body, Vec2(-0.5 * shape.length, 0)});
        break;
      case Shape::rectangle:
      case Shape::disc:
      case Shape::ring:
      case Shape::point:
        break;
    }
  }
  return points;
}

}  // namespace

struct ModesSheet::Cell {
  Rect picture, caption;
};

ModesSheet::ModesSheet(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                       double amplitude, const MechanismClip& clip)
    : clip_(clip) {
  check_amplitude(amplitude);
  const MechanismGeometry geometry = mechanism_geometry(system);
  const ElementSet shown = panel_elements(clip.settings.elements);
  SimulationOptions options = clip.simulation;
  options.case_id = 3;  // the tree coordinates' state, which the poses are prescribed in
  options.duration = 1;
  const Eigen::VectorXd q0 = linear.equilibrium;
  const GiNaC::exmap at_rest = state_of(system, closed(system, q0));
  const auto sample = [&](const std::vector<double>& times, const PrescribedState& path) {
    ClipResult scratch;
    return sample_mechanism_motion(system, at_rest, options, times, 1, scratch, {}, {}, nullptr, {}, false, path);
  };
  const PrescribedState at_equilibrium = [&](double, Eigen::VectorXd& y) {
    y.head(q0.size()) = q0;
    y.segment(q0.size(), q0.size()).setZero();
  };
  const std::vector<double> equilibrium_pose = sample({0.0}, at_equilibrium).samples.front().pose;
  Bounds bounds;
  for (std::size_t k = 0; k < modes.modes.size(); ++k) {
    const Mode& mode = modes.modes[k];
    ModesSheetPanel panel;
    panel.number = static_cast<int>(k) + 1;
    panel.kind = mode.kind;
    panel.heading = heading_of(panel.number, mode, modes.damped);
    panel.shape = shape_line(linear, mode);
    panel.equilibrium_pose = equilibrium_pose;
    std::vector<BodyPoint> trails;
    if (mode.kind == Mode::Kind::oscillation) {
      // As --mode scales it: the largest tree coordinate moves by the amplitude.
      const Eigen::VectorXd d = amplitude / mode.tree_shape.cwiseAbs().maxCoeff() * mode.tree_shape;
      panel.plus = closed(system, q0 + d);
      panel.minus = closed(system, q0 - d);
      std::vector<double> times;
      for (int j = 0; j <= kArcSamples; ++j) times.push_back(static_cast<double>(j) / kArcSamples);
      // From -A (s = 0) to +A (s = 1) along q0 - cos(pi s) d, closed at each pose.
      panel.motion = sample(times, [&](double s, Eigen::VectorXd& y) {
        const Eigen::Index n = q0.size();
        y.head(n) = s == 0   ? panel.minus
                    : s == 1 ? panel.plus
                             : closed(system, q0 - std::cos(std::numbers::pi * s) * d);
        y.segment(n, n).setZero();
      });
      trails = moving_points(geometry, panel.motion);
    } else {
      panel.motion = sample({0.0}, at_equilibrium);
    }
    MechanismScene scene(geometry, panel.motion, trails, 2.0, {}, shown);
    scene.set_trail_fades(false);
    const bool moves = mode.kind == Mode::Kind::oscillation;
    scene.frame(panel.motion.samples.size() - 1, panel.list);
    if (moves) {
      panel.list.ghosts.push_back({outlines_of(geometry, equilibrium_pose), 0.0, false});
      panel.list.ghosts.push_back({outlines_of(geometry, panel.motion.samples.front().pose), 0.0, true});
    }
    const Bounds& b = scene.view_bounds();
    if (!b.empty()) {
      bounds.include(b.min);
      bounds.include(b.max);
    }
    panels_.push_back(std::move(panel));
  }
  const RenderSettings& s = clip.settings;
  const DrawStyle style{&clip.theme, DrawStyle::unit_for(s.width, s.height)};
  const auto n = static_cast<int>(panels_.size());
  columns_ = std::clamp(n, 1, 3);
  rows_ = std::max(1, (n + columns_ - 1) / columns_);
  top_ = style.padding() + 1.5 * style.title_size() + 1.6 * style.small_size();
  caption_ = kCaptionLines * 1.45 * style.text_size() + 0.5 * style.padding();
  subtitle_ = "Each mode displaced by " + format_significant(amplitude, 3) +
              " (rad or m) in its largest coordinate: +A filled, \u2212A outlined, the equilibrium faint; the "
              "trails are the path between";
  const Cell first = cell(0);
  if (!(first.picture.width >= 1 && first.picture.height >= 1))
    throw Error::invalid("size", std::to_string(s.width) + "x" + std::to_string(s.height) + " leaves no room for " +
                                     std::to_string(n) + " panels; valid: a larger size");
  camera_ =
      Camera(view_of(bounds, kMargin), static_cast<int>(first.picture.width), static_cast<int>(first.picture.height));
}

ModesSheet::Cell ModesSheet::cell(std::size_t index) const {
  const RenderSettings& s = clip_.settings;
  const double pad = DrawStyle{&clip_.theme, DrawStyle::unit_for(s.width, s.height)}.padding();
  const double width = std::floor((s.width - pad * (columns_ + 1)) / columns_);
  const double height = std::floor((s.height - top_ - pad * rows_) / rows_);
  const auto column = static_cast<int>(index) % columns_, row = static_cast<int>(index) / columns_;
  const double x = std::round(pad + column * (width + pad)), y = std::round(top_ + row * (height + pad));
  const double picture = std::floor(height - caption_);
  return {{x, y, width, picture}, {x, y + picture, width, height - picture}};
}

void ModesSheet::paint(cairo_t* cr) const {
  const RenderSettings& s = clip_.settings;
  const DrawStyle style{&clip_.theme, DrawStyle::unit_for(s.width, s.height)};
  const Theme& theme = clip_.theme;
  // The panels first: each one's background is then the first paint where it lies, which a
  // vector surface keeps a shape (over anything drawn before it, a bitmap).
  const MechanismLabels labels;  // no title, run or HUD in a panel
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    const Cell c = cell(i);
    cairo_save(cr);
    cairo_translate(cr, c.picture.x, c.picture.y);
    cairo_rectangle(cr, 0, 0, c.picture.width, c.picture.height);
    cairo_clip(cr);
    paint_mechanism_frame(cr, style, camera_, panels_[i].list, labels, 0, static_cast<int>(c.picture.width),
                          static_cast<int>(c.picture.height));
    cairo_restore(cr);
  }
  // The sheet's background around them.
  cairo_save(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_rectangle(cr, 0, 0, s.width, s.height);
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    const Cell c = cell(i);
    cairo_rectangle(cr, c.picture.x, c.picture.y, c.picture.width, c.picture.height);
  }
  set_colour(cr, theme.background);
  cairo_fill(cr);
  cairo_restore(cr);
  double below = style.padding();
  if (!s.title.empty() && s.elements.has(Element::title)) {
    const TitleLayout title = title_layout(cr, style, s.title, s.width);
    paint_title(cr, style, s.title, title);
    below = title.rect.y + title.rect.height;
  }
  const text::Font small{style.small_size(), false};
  text::draw(cr, small, style.padding(), below + 1.2 * style.small_size(), subtitle_.c_str(), theme.text_muted);
  const text::Font bold{style.text_size(), true}, plain{style.text_size(), false};
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    const ModesSheetPanel& panel = panels_[i];
    const Cell c = cell(i);
    cairo_rectangle(cr, c.picture.x, c.picture.y, c.picture.width, c.picture.height);
    set_colour(cr, with_alpha(theme.text_muted, 0.6));
    cairo_set_line_width(cr, style.grid_width());
    cairo_stroke(cr);
    // The heading, then the shape wrapped to the panel's width.
    const double centre = c.caption.x + 0.5 * c.caption.width, step = 1.45 * style.text_size();
    double y = c.caption.y + step;
    text::draw(cr, bold, centre, y, panel.heading.c_str(), theme.text, text::Align::centre);
    for (const std::string& line : wrap_text(cr, style.text_size(), panel.shape, c.caption.width)) {
      y += step;
      text::draw(cr, plain, centre, y, line.c_str(), theme.text, text::Align::centre);
    }
  }
  cairo::check(cr, "drawing the modes sheet");
}

void ModesSheet::write(const std::filesystem::path& out, const std::string& origin) const {
  const RenderSettings& s = clip_.settings;
  const OutputKind kind = output_kind(out, origin);
  if (kind == OutputKind::png) {
    Frame frame(s.width, s.height);
    {
      const cairo::SurfacePtr surface = cairo::surface_for(frame);
      const cairo::ContextPtr cr = cairo::context(surface.get());
      paint(cr.get());
      cairo_surface_flush(surface.get());
    }
    write_png(frame, out, origin);
  } else if (kind == OutputKind::svg || kind == OutputKind::pdf) {
    write_vector_still([&](cairo_t* cr) { paint(cr); }, kind, s.width, s.height, out, origin);
  } else {
    throw Error::invalid(origin, "'" + out.string() + "' is a video; the sheet is one still: .png, .svg or .pdf");
  }
}

}  // namespace linkage

namespace linkage {

void produce_modes_sheet(const sym::System& system, const MechanismClip& clip, double amplitude,
                         const std::filesystem::path& out, const std::string& origin) {
  check_amplitude(amplitude);
  const Linearization linear = linearize(system);
  const ModesSheet sheet(system, linear, modal_analysis(linear), amplitude, clip);
  sheet.write(out, origin);
}

}  // namespace linkage
