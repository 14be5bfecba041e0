#pragma once
// A mechanism as the lecturer wrote it (mechanisms/*.toml): bodies, their named points,
// joints, springs, applied loads, parameters and the initial state. Plain data, read-only
// once read: every quantity stays the text the file gave (a number or an expression in
// the parameters), with its position in the file, so the symbolic layer can parse it and
// name FILE:LINE:COLUMN when it is wrong. The file's contract is in mechanisms/README.md.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "model/joint_types.hpp"

namespace linkage {

/// Where a value came from: "two-blocks.toml", line and column (1-based; 0 when built in code).
struct SourcePos {
  std::string file;
  long line = 0;
  long column = 0;
};

/// A quantity: a number written as text ("0.3") or an expression ("L/2 - b").
struct Quantity {
  std::string text;
  SourcePos pos;
};

struct Vector2Quantity {
  Quantity x, y;
};

struct NamedPoint {
  std::string name;
  Vector2Quantity at;  // body frame (origin at the centre of mass, x along the length); world for ground
  SourcePos pos;
};

enum class Shape { rectangle, rod, disc, ring, point };
inline constexpr std::array<const char*, 5> kShapeNames{"rectangle", "rod", "disc", "ring", "point"};

struct Body {
  std::string name;
  Shape shape = Shape::point;
  Quantity mass;
  std::optional<Quantity> length;   // rectangle, rod
  std::optional<Quantity> width;    // rectangle
  std::optional<Quantity> radius;   // disc, ring
  std::optional<Quantity> inertia;  // about the centre of mass; overrides the shape's formula
  std::vector<NamedPoint> points;
  SourcePos pos;
};

/// The name that stands for the fixed frame in `bodies` and in point references.
inline constexpr const char* kGround = "ground";

struct Joint {
  std::string name;
  JointType type = JointType::pin;
  std::array<std::string, 2> bodies;  // kGround or a body name
  std::array<std::string, 2> points;  // a named point of each body, in the order of `bodies`
  // Pin only: a torsional spring-damper; torque on bodies[1] = -stiffness*(th_b - th_a -
  // rest_angle) - damping*(th_b' - th_a'), the opposite on bodies[0].
  std::optional<Quantity> stiffness, damping, rest_angle;
  std::optional<Vector2Quantity> axis;  // slider, rolling: direction in the frame of bodies[0]
  std::optional<Quantity> radius;       // rolling only: the rolling radius (read: the disc's when not given)
  std::optional<Quantity> angle;        // weld only: the relative angle th_b - th_a it holds (absent: 0)
  // Gear only: the body both gears are pinned to (`points` are those pins' points on the
  // gears), the pitch radii of bodies[0] and bodies[1], and whether the mesh is internal.
  std::string carrier = kGround;
  SourcePos carrier_pos;
  std::optional<std::array<Quantity, 2>> radii;
  bool internal = false;
  SourcePos pos;
};

/// A motor at a pin or slider joint: one more constraint, rheonomic, (th_b - th_a) = motion(t)
/// at a pin, s = motion(t) at a slider; its multiplier is the driver's torque or force on
/// the joint's bodies[1] (the `NAME.torque` or `NAME.force` column).
struct Driver {
  std::string name;
  std::string joint;  // a joint of the file whose type's row is drivable
  Quantity motion;    // in t, parameters and definitions: rad (pin) or m (slider)
  SourcePos pos;
};

/// "body.point", e.g. "ground.O" or "1.P".
struct PointRef {
  std::string body;
  std::string point;
  SourcePos pos;
};

/// A linear spring-damper between two points: force along the line
/// -stiffness*(l - rest_length) - damping*l'.
struct Spring {
  std::string name;
  std::array<PointRef, 2> between;
  Quantity stiffness, rest_length, damping;
  SourcePos pos;
};

/// An applied force at a body's point, world frame; may use the time t.
struct AppliedForce {
  std::string body, point;
  Vector2Quantity value;
  SourcePos pos;
};

/// An applied torque on a body; may use the time t.
struct AppliedTorque {
  std::string body;
  Quantity value;
  SourcePos pos;
};

struct Parameter {
  std::string name;
  double value = 0;
  SourcePos pos;
  std::string unit{};     // ASCII, e.g. "m/s^2"; empty when the file gives none
  std::string meaning{};  // e.g. "block length"
};

struct Definition {
  std::string name;
  Quantity value;
  SourcePos pos;
};

/// One initial value: the generalized coordinate or rate `key` ("1.theta", "1.x_dot",
/// "slider.s") as the file spelt it.
struct InitialValue {
  std::string key;
  double value = 0;
  SourcePos pos;
};

/// Another name for a key of the worked solution's JSON ("1.x_ddot" = "x1_ddot"): the name
/// an interface built on this file prints instead (plain `linkage solve` on two-blocks).
struct Alias {
  std::string key;   // as `linkage solve --mechanism --format json` prints it
  std::string name;  // printed instead
  SourcePos pos;     // of the key
};

/// How the file's picture looks by default ([picture]): `linkage render` flags override it.
struct Picture {
  std::string title;                // the picture's title line; empty: the file's title
  std::vector<std::string> trails;  // "BODY.POINT" whose path is drawn (--trail)
  std::string ensemble;             // the coordinate --ensemble spreads ("1.theta"); empty: the first
};

/// A column of the table the file's interface writes by default ([table] columns).
struct TableColumn {
  std::string name;  // a column of `linkage simulate --mechanism FILE --columns all` ("1.x", "energy")
  SourcePos pos;     // of the list entry
};

struct Mechanism {
  std::string name;                 // file stem, e.g. "two-blocks"
  std::string title;                // one line
  std::string description;          // one paragraph: what it teaches
  std::string source;               // the file path (or "built-in two-blocks.toml")
  std::optional<Quantity> gravity;  // magnitude along -y; absent means none
  std::vector<Parameter> parameters;
  std::vector<Definition> definitions;
  std::vector<NamedPoint> ground_points;
  std::vector<Body> bodies;
  std::vector<Joint> joints;
  std::vector<Driver> drivers;  // [[driver]], in file order
  std::vector<Spring> springs;
  std::vector<AppliedForce> forces;
  std::vector<AppliedTorque> torques;
  std::vector<InitialValue> initial;
  SourcePos initial_pos;                 // the [initial] table (the file's start when absent)
  std::vector<std::string> independent;  // loop closure keeps these coordinates
  SourcePos independent_pos;
  std::vector<Alias> aliases;  // [aliases], in file order
  Picture picture;
  // The table an interface built on the file (its [aliases]) writes by default, in order;
  // empty: every column.
  std::vector<TableColumn> table;
  // Tables and messages name quantities by `aliases`: a run from the homework's flags
  // speaks the spec's names (x1_dot, not 1.x_dot).
  bool speaks_aliases = false;

  [[nodiscard]] const Body* find_body(const std::string& body_name) const;
  /// Index into `bodies`, -1 for the ground or a name that is not a body.
  [[nodiscard]] int body_index(const std::string& body_name) const;
  [[nodiscard]] const Joint* find_joint(const std::string& joint_name) const;
  /// `key`'s alias, or `key` when it has none.
  [[nodiscard]] std::string aliased(const std::string& key) const;
  /// The key whose alias is `alias`, or `alias` when it is none ("theta1" -> "1.theta").
  [[nodiscard]] std::string unaliased(const std::string& alias) const;
  /// `key` as tables and messages name it: aliased(key) when speaks_aliases, else `key`.
  [[nodiscard]] std::string named(const std::string& key) const;
};

/// "file:line:column: " or "" for a position built in code.
[[nodiscard]] std::string where(const SourcePos& pos);

}  // namespace linkage
