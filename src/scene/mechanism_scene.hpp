#pragma once
// What a frame of any mechanism shows, in world units (metres, y up): the numbers of the
// mechanism's drawing (shapes, points, joints, springs, loads) taken once from the System,
// and a sampled motion turned frame by frame into outlines, markers, coils, dashpots,
// force and torque arrows and trails.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "evaluate/mechanism_dynamics.hpp"
#include "evaluate/program.hpp"
#include "model/mechanism.hpp"
#include "scene/arrow_scale.hpp"
#include "scene/bounds.hpp"
#include "scene/elements.hpp"
#include "symbolic/system.hpp"

namespace linkage {

/// A point of a body in its frame, or of the ground (body -1) in the world.
struct BodyPoint {
  int body = -1;
  Vec2 local = Vec2::Zero();
};

struct MechanismGeometry {
  struct BodyShape {
    std::string name;
    Shape shape = Shape::point;
    double length = 0, width = 0, radius = 0;          // m; those the shape has, else 0
    double mass = 0;                                   // kg
    std::vector<std::pair<std::string, Vec2>> points;  // body frame
  };
  struct JointShape {
    std::string name;
    JointType type = JointType::pin;
    std::array<BodyPoint, 2> points;  // the joint's point on bodies[0] and bodies[1]
    Vec2 axis = Vec2::UnitX();        // slider, rolling: unit, in the frame of bodies[0]
    double radius = 0;                // rolling: m
    std::array<double, 2> radii{};    // gear: the pitch radii, m
    double mesh = 1;                  // gear: +1 external, -1 internal
    double constant = 0;              // gear: c_G, m (its row's constant)
    int carrier = -1;                 // gear: the carrier body (-1: the ground)
    /// The force's own name when the file's [aliases] give `<joint>.force_x` as
    /// `<name>_x` (two-blocks: P.force_x = F_x, so "F on 1", "−F on 2"); else empty.
    std::string force_name{};
    bool torsion = false;  // a pin's torsional spring or damper: drawn as a spiral about it
    double rest = 0;       // rad: the spring's rest angle (th_b - th_a), where the spiral is as drawn at rest
  };
  struct SpringShape {
    std::string name;
    std::array<BodyPoint, 2> ends;
    double damping = 0;  // N s/m; > 0 draws a dashpot beside the coil
  };
  /// An applied force ([[force]]): its point and value, world frame, N, in t and the state.
  struct ForceShape {
    BodyPoint at;
    GiNaC::ex x, y;
  };
  /// An applied torque ([[torque]]) on a body, N m, in t and the state.
  struct TorqueShape {
    int body = 0;
    GiNaC::ex value;
  };
  /// Gravity on a body or a spring's (and its damper's) force on a body at its end: the
  /// System's own load, evaluated per sample by `load_values`.
  struct LoadShape {
    int body = 0;
    bool gravity = false;  // else a spring
    std::string name;      // the spring's, or the weight's label: "mg", "m₁g" (weight_name)
  };
  std::vector<BodyShape> bodies;
  std::vector<std::pair<std::string, Vec2>> ground;  // world
  std::vector<JointShape> joints;
  std::vector<SpringShape> springs;
  std::vector<ForceShape> forces;
  std::vector<TorqueShape> torques;
  std::vector<LoadShape> loads;
  /// A [[driver]]: its name and joint (an index of `joints`), in file order as
  /// MechanismSample::drivers holds their torques or forces.
  struct DriverShape {
    std::string name;
    std::size_t joint = 0;
  };
  std::vector<DriverShape> drivers;
  /// Per load: force x, y (N) and its point x, y (m), world frame; inputs per body x, y,
  /// theta, then per body their rates, then t (load_inputs).
  eval::Program load_values;
  double gravity = 0;  // m/s^2, along -y
  /// Per body, per named point: its world velocity x, y in load_values' inputs, the time
  /// derivative of its position as the System states it (compiled for the points traced).
  std::vector<std::vector<std::array<GiNaC::ex, 2>>> point_velocities;
  std::vector<GiNaC::symbol> inputs;  // load_values' inputs, in order
  GiNaC::ex time;                     // the symbol t of the loads' values
  std::vector<GiNaC::ex> state;       // and the state's: per body x, y, theta, then their rates

  /// Whether any joint or spring holds the mechanism to the ground (else it floats).
  [[nodiscard]] bool grounded() const;
  /// `body.point` ("3.B", "ground.O") resolved; Error::invalid(`setting`, ...) naming the
  /// valid bodies or points otherwise (its reader says where: --trail, a lesson key).
  [[nodiscard]] BodyPoint resolve(const std::string& reference, const std::string& setting) const;
};

/// The drawing's numbers, evaluated at the mechanism's parameters.
[[nodiscard]] MechanismGeometry mechanism_geometry(const sym::System& system);

/// load_values' inputs for a sample: its poses, rates and time.
void load_inputs(const eval::MechanismSample& sample, double t, std::vector<double>& inputs);

/// The world position of `p` for per-body poses (x, y, theta each).
[[nodiscard]] Vec2 world_point(const std::vector<double>& pose, const BodyPoint& p);
/// A body's outline in the world, counter-clockwise (rectangle: 4 corners; rod: a bar
/// of width length/12 with round ends; disc: a polygon on its rim; point: its centre).
[[nodiscard]] std::vector<Vec2> body_outline(const MechanismGeometry::BodyShape& body, const std::vector<double>& pose,
                                             std::size_t index);

/// One frame's drawing, world units. Markers are drawn at a fixed size in pixels.
struct MechanismDrawList {
  struct Outline {
    std::size_t body = 0;
    std::vector<Vec2> points;  // closed polygon (one point for a point mass)
    Shape shape = Shape::point;
  };
  struct Line {
    // surface: hatched on its right; slot: a closed channel cut out of its body's fill;
    // teeth: a gear's pitch circle or a tooth mark on it
    enum class Kind { spin, rail, spring, dashpot, trail, surface, slot, teeth } kind = Kind::rail;
    std::vector<Vec2> points;
    std::vector<double> fade{};  // a trail's, per point: 1 now, falling to 0 with age
    int body = -1;               // the body it moves with in the free-body view (-1: the world)
  };
  struct Marker {
    enum class Kind { ground, pin, guide, com, bracket } kind = Kind::pin;
    Vec2 at = Vec2::Zero();
    Vec2 direction = Vec2::UnitX();  // guide: along the rail; bracket: its leg on bodies[0]
    int body = -1;                   // the body it moves with in the free-body view (-1: the world)
    Vec2 across = Vec2::UnitY();     // bracket: its leg on bodies[1]
  };
  struct Arrow {
    enum class Kind { joint, applied, gravity, spring, velocity, acceleration, driver } kind = Kind::joint;
    Vec2 tail = Vec2::Zero(), vector = Vec2::Zero();  // vector in metres: force x scale, or cut
    double force = 0;                                 // N, the magnitude
    bool cut = false;                                 // drawn shorter than the scale says
    std::string label;                                // "B on 3", "F = 0.5 N"
    bool stretched = false;                           // too short to see at the scale: drawn longer
    int body = -1;                                    // the body it acts on (-1: none)
  };
  /// An applied torque: an arc about the body's centre, counter-clockwise for sweep > 0,
  /// its head at start + sweep.
  struct Torque {
    Vec2 centre = Vec2::Zero();
    double radius = 0, start = 0, sweep = 0;  // m, rad
    std::string label;                        // "τ = 0.01 N m"
    int body = -1;
    bool driver = false;  // a driver's torque (the motor's colour), else an applied one
  };
  /// A driver's motor: a circle at a pin's point, or at a slider's guide along its axis.
  struct Motor {
    Vec2 at = Vec2::Zero();
    Vec2 axis = Vec2::UnitX();  // a slider's axis in the world
    bool slider = false;
    int body = -1;  // the body it moves with in the free-body view
  };
  struct Label {
    Vec2 at = Vec2::Zero();
    std::string text;
    int body = -1;
  };
  /// What an arrow's length means: a reference arrow of `metres` stands for `newtons`
  /// (joint forces; applied ones have their own when --arrow-scale sets them apart).
  struct Legend {
    double newtons = 0, metres = 0;  // 0: no force arrows in the clip
    std::string value;               // "2 N"
    bool joint = false, applied = false;
    bool cut = false;                                // some arrow of the clip is cut
    bool stretched = false;                          // some arrow of the clip is drawn longer than its scale
    double applied_newtons = 0, applied_metres = 0;  // the applied forces' reference arrow
    std::string applied_value;
    std::string joint_scale, applied_scale;  // "1 cm = 0.5 N"
    /// A row per other kind shown (gravity, spring, velocity): its reference arrow.
    struct Row {
      Arrow::Kind kind = Arrow::Kind::gravity;
      double metres = 0;
      std::string value, scale;  // "2 N", "1 cm = 0.5 N"
      double sweep = 0;          // a torque's row: its reference arc (rad), drawn instead of an arrow
    };
    std::vector<Row> rows;
    bool relative_velocity = false;   // the velocity row: relative to the centre of mass G
    bool com = false;                 // the centres of mass's symbol, beside a row with room for it
    std::vector<std::string> trails;  // a row per traced point: "path of P"
    double trail_seconds = 0;         // "last 2 s"
    std::string note{};               // a closing line: "the view follows the centre of mass; ..."
  };
  std::vector<Outline> outlines;
  std::vector<Line> lines;
  std::vector<Marker> markers;
  std::vector<Arrow> arrows;
  std::vector<Torque> torques;
  std::vector<Motor> motors;
  std::vector<Label> labels;        // body names at their centres
  std::vector<Label> joint_labels;  // joint names at their points (not in the free-body view)
  /// Another run's bodies, drawn over this one: an ensemble member (faint, at `ramp`
  /// 0..1 of the colour ramp) or the compared run.
  struct Ghost {
    std::vector<Outline> outlines;
    double ramp = 0;
    bool compare = false;
  };
  std::vector<Ghost> ghosts;
  Legend legend;
  /// The HUD's errors at this sample: the energy balance E − E0 − W (J) and, when the
  /// case keeps a constraint, the largest joint's constraint error (m).
  struct Hud {
    double energy_error = 0, constraint_error = 0;
    bool constraint = false;
    bool energy = true;  // false: the motion is prescribed, its energy balance means nothing
  };
  Hud hud;
  Vec2 centre_of_mass = Vec2::Zero();         // of the whole mechanism, world
  ElementSet shown = ElementSet::defaults();  // also what the painter adds: grid, axes, hud, legend, title
  void clear();
};

/// The sampled motion: one sample per frame time, increasing; and, for trails, poses at
/// finer times (increasing, the frame times among them; empty: the frames' poses).
struct MechanismMotion {
  std::vector<double> times;
  std::vector<eval::MechanismSample> samples;
  std::vector<double> energy_error;  // per sample: E − E0 − W, J (empty: not recorded)
  bool constraints_kept = false;     // the case keeps a joint's constraint (its error is worth showing)
  bool kinematic = false;            // the drivers fixed the motion: nothing was integrated
  bool prescribed = false;           // a motion given, not integrated (a mode's linear motion): no energy balance
  std::vector<double> trail_times;
  std::vector<std::vector<double>> trail_poses;
};

/// "0.42 N", "23 N": three significant digits at most, no exponent in the usual range.
[[nodiscard]] std::string format_quantity(double value, const char* unit);
/// The unit of an arrow of `kind`'s magnitude (MechanismDrawList::Arrow::force): "N", "m/s", "m/s²".
[[nodiscard]] const char* arrow_unit(MechanismDrawList::Arrow::Kind kind);

/// A whole clip's frames: scales and camera bounds come from every sample.
class MechanismScene {
 public:
  /// `trails`: points whose path over the last `trail_seconds` each frame draws.
  /// `arrows`: --arrow-scale (kinds "joint" and "applied"); by default joint and applied
  /// forces share one scale from the clip's typical force, as "common" does.
  /// `shown`: the elements drawn (bodies, joints, each kind of arrow, trail, com, labels).
  /// `free_body`: each body pulled away from the others (from the centroid, by half its
  /// distance) with every force on it, a joint's pin drawn on each of its bodies.
  /// `relative_velocities`: velocities drawn relative to the centre of mass G (what a
  /// camera following G shows), the legend saying so; else in the world frame.
  /// `points`: points of bodies whose velocity and acceleration arrows are drawn (when
  /// those elements are shown) with their magnitude, besides the trails' points.
  MechanismScene(MechanismGeometry geometry, const MechanismMotion& motion, std::vector<BodyPoint> trails,
                 double trail_seconds = 2.0, const ArrowScaleRequest& arrows = {},
                 ElementSet shown = ElementSet::defaults(), bool free_body = false, bool relative_velocities = false,
                 const std::vector<BodyPoint>& points = {});

  /// Force arrows shorter than `metres` (but not zero) are drawn `drawn` long (0: that
  /// long) and marked stretched, their labels giving the value; the legend says whether any is.
  void set_shortest_arrow(double metres, double drawn = 0);
  /// A trail over a whole cycle is drawn at full strength end to end, so the closed curve
  /// reads as closed (by default the oldest part fades out).
  void set_trail_fades(bool fades) { trail_fades_ = fades; }

  [[nodiscard]] const MechanismGeometry& geometry() const { return geometry_; }
  /// Every outline point over the motion and the ground points (the fixed camera's view).
  [[nodiscard]] const Bounds& bounds() const { return bounds_; }
  /// The mechanism's centre of mass at sample k (the floating camera's centre): the
  /// bodies' centres weighted by their masses.
  [[nodiscard]] Vec2 centroid(std::size_t k) const;
  /// Its velocity at sample k: the bodies' velocities weighted by their masses.
  [[nodiscard]] Vec2 centroid_velocity(std::size_t k) const;
  /// The largest distance of an outline point from the centroid over the motion.
  [[nodiscard]] double reach() const { return reach_; }
  /// bounds() and reach() grown to take in the force arrows too (what the camera shows).
  [[nodiscard]] const Bounds& view_bounds() const { return view_bounds_; }
  [[nodiscard]] double view_reach() const { return view_reach_; }
  /// Metres per newton of the force arrows (0 without forces): the upper quartile of the
  /// frames' largest force is a sixth of the extent, so a typical frame reads.
  [[nodiscard]] double force_scale() const { return force_scale_; }
  /// Metres per newton of the applied forces' arrows (force_scale() unless set apart).
  [[nodiscard]] double applied_scale() const { return applied_scale_; }
  /// Metres per unit of an arrow of `kind` (N, or m/s for velocity); 0 when none is drawn.
  [[nodiscard]] double scale_of(MechanismDrawList::Arrow::Kind kind) const;
  /// The longest arrow drawn, m: a longer one is cut to it (1.5 the typical length).
  [[nodiscard]] double arrow_cap() const { return arrow_cap_; }
  /// The larger side of bounds(), or 2 reach() for a floating mechanism.
  [[nodiscard]] double extent() const { return extent_; }

  /// The drawing of sample k.
  void frame(std::size_t k, MechanismDrawList& out) const;

 private:
  MechanismGeometry geometry_;
  const MechanismMotion& motion_;
  std::vector<BodyPoint> trails_;
  struct Marked {
    BodyPoint point;
    bool valued = false;  // named by --points: its arrows' labels give their magnitude
  };
  std::vector<Marked> marked_;  // the trails' points, then the named ones
  std::vector<Marked> traced_;  // those on bodies, whose velocities are drawn
  double trail_seconds_;
  bool trail_fades_ = true;
  Bounds bounds_, view_bounds_;
  double reach_ = 0, view_reach_ = 0, force_scale_ = 0, applied_scale_ = 0, arrow_cap_ = 0, torque_scale_ = 0,
         extent_ = 1, shortest_ = 0, stretched_ = 0;
  MechanismDrawList::Legend legend_;
  std::vector<std::array<double, 2>> rail_span_;     // per joint: slider (rolling contact) travel range along the axis
  std::vector<std::array<double, 2>> spring_span_;   // per spring: shortest and longest length
  std::vector<std::vector<Vec2>> applied_;           // per sample, per applied force: N
  std::vector<std::vector<double>> torque_;          // per sample, per applied torque: N m
  std::vector<std::vector<double>> load_;            // per sample: load_values' outputs
  std::vector<std::vector<double>> trail_velocity_;  // per sample: each traced point's velocity x, y
  ElementSet shown_;
  bool free_body_ = false;
  bool relative_velocities_ = false;
  double gravity_scale_ = 0, spring_scale_ = 0, velocity_scale_ = 0, acceleration_scale_ = 0;
  double driver_scale_ = 0;         // a slider driver's force arrows, m/N
  double driver_torque_scale_ = 0;  // a pin driver's torque arcs, rad/(N m)
  /// Per marked point on a body: its index in marked_ and in MechanismSample::points.
  std::vector<std::pair<std::size_t, std::size_t>> traced_points_;

  void add_torsion(const MechanismGeometry::JointShape& joint, const std::vector<double>& pose,
                   MechanismDrawList& out) const;
  void add_gear(const MechanismGeometry::JointShape& joint, const std::vector<double>& pose,
                MechanismDrawList& out) const;
  void add_spring(const MechanismGeometry::SpringShape& spring, std::size_t index, const std::vector<double>& pose,
                  MechanismDrawList& out) const;
  void add_loads(std::size_t k, MechanismDrawList& out) const;
  void add_trails(std::size_t k, MechanismDrawList& out) const;
  void add_load_arrows(std::size_t k, MechanismDrawList& out) const;
  void add_acceleration_arrows(std::size_t k, MechanismDrawList& out) const;
  void add_motors(std::size_t k, MechanismDrawList& out) const;
  /// "3.P": a point of a body as --points names it.
  [[nodiscard]] std::string point_name(const BodyPoint& point) const;
  /// Its magnitude added to an arrow's label.
  static void with_value(MechanismDrawList::Arrow& arrow, const char* unit);
  /// An arc's radius for a torque on a body of this shape, m.
  [[nodiscard]] double torque_radius(const MechanismGeometry::BodyShape& shape) const;
  void place_joints(const std::vector<double>& pose, std::size_t first_marker, std::size_t first_line,
                    MechanismDrawList& out) const;
  void pull_apart(std::size_t k, MechanismDrawList& out) const;
  [[nodiscard]] MechanismDrawList::Arrow force_arrow(MechanismDrawList::Arrow::Kind kind, const Vec2& at,
                                                     const Vec2& force, std::string label) const;
};

}  // namespace linkage
