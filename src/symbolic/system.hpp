#pragma once
// A mechanism's equations as GiNaC expressions, built from the file by one procedure:
//   each body b: maximal coordinates x_b, y_b, theta_b (a point mass has no theta), a point
//     s of b at r_b + R(theta_b) s in the world;
//   each joint: its position constraint rows Phi(q) = 0 (joint_pin.cpp, joint_slider.cpp)
//     and its force (the force bodies[1] exerts on bodies[0]) as unknown symbols;
//   each driver: one row C(q, t) = 0 and its torque or force as an unknown symbol;
//   loads: gravity, springs and dampers, joint springs, applied forces and torques;
//   Newton-Euler of each body, each row an expression r(q, q', q'', F) = 0:
//     m_b x_b'' - sum F_x,  m_b y_b'' - sum F_y,  I_b theta_b'' - sum (p - r_b) x F - sum M;
//   the spanning tree's generalized coordinates, with every maximal coordinate, rate and
//   acceleration as an expression in them (for Case 2 and Case 3).
// Time derivatives are taken by the chain rule over coordinate and rate symbols.
#include <ginac/ginac.h>

#include <map>
#include <string>
#include <vector>

#include "model/mechanism.hpp"
#include "model/spanning_tree.hpp"
#include "symbolic/symbols.hpp"

namespace linkage::sym {

struct Vec2 {
  GiNaC::ex x = 0, y = 0;
};

/// A maximal coordinate with its rate and acceleration symbols.
struct CoordinateSymbols {
  GiNaC::symbol q, q_dot, q_ddot;
};

struct BodySystem {
  std::string name;
  GiNaC::ex mass;             // in parameters and definitions
  GiNaC::ex inertia;          // the symbol printed in the equations (I, I₁) or 0 for a point mass
  GiNaC::ex inertia_formula;  // its value in parameters and definitions
  bool rotates = true;        // false for a point mass: no theta
  CoordinateSymbols x, y, theta;
  std::map<std::string, Vec2> points;  // body frame
};

/// A force and moment on one body. `point` is where it acts, world frame, in maximal
/// coordinates; `moment` a pure couple.
struct Load {
  int body = -1;
  Vec2 force;
  Vec2 point;
  GiNaC::ex moment = 0;
  std::string source;  // "gravity", a spring, joint or "force 1" name
};

struct JointSystem {
  int index = -1;                       // into Mechanism::joints
  std::vector<GiNaC::ex> constraints;   // Phi(q) = 0, maximal coordinates
  std::vector<GiNaC::symbol> unknowns;  // force components: Fx, Fy (pin); N, M (slider)
  Vec2 force;                           // the force bodies[1] exerts on bodies[0], world frame
  GiNaC::ex moment = 0;                 // and its moment (slider)
  bool in_tree = false;
};

/// A [[driver]]: one more constraint row C(q, t) = driven(q) - motion(t) = 0 (pin: th_b -
/// th_a; slider: s), kept in every case, with its multiplier `unknown` among the unknowns.
/// The multiplier enters each body's Newton-Euler rows as the generalized force
/// unknown * dC/dq (maximal coordinates): at a pin the torque on bodies[1] (the opposite on
/// bodies[0]), at a slider the force along the unit axis on bodies[1].
struct DriverSystem {
  int index = -1;  // into Mechanism::drivers
  int joint = -1;  // into Mechanism::joints
  GiNaC::ex constraint;
  GiNaC::symbol unknown;  // NAME.torque or NAME.force
  // unknown * dC/dq on each body it moves: (d/dx, d/dy) as a force at the centre of mass,
  // d/dtheta as a couple; the Newton-Euler rows and the reports read these.
  std::vector<Load> loads;
};

/// One generalized coordinate: its symbols (for a floating base and a pin, the body's own
/// maximal symbols; a slider's s its own).
struct GeneralizedCoordinate {
  Coordinate coordinate;
  CoordinateSymbols symbols;
};

struct NewtonEulerRows {
  int body = -1;
  std::vector<GiNaC::ex> rows;  // x, y[, theta]: each = 0
};

class System {
 public:
  explicit System(const Mechanism& mechanism);

  [[nodiscard]] const Mechanism& mechanism() const { return mechanism_; }
  [[nodiscard]] const SymbolTable& table() const { return table_; }
  [[nodiscard]] const SpanningTree& tree() const { return tree_; }
  [[nodiscard]] const GiNaC::symbol& time() const { return t_; }
  [[nodiscard]] const std::vector<BodySystem>& bodies() const { return bodies_; }
  [[nodiscard]] const std::vector<JointSystem>& joints() const { return joints_; }
  [[nodiscard]] const std::vector<DriverSystem>& drivers() const { return drivers_; }
  [[nodiscard]] const std::vector<Load>& loads() const { return loads_; }
  [[nodiscard]] const std::vector<GeneralizedCoordinate>& coordinates() const { return coordinates_; }
  [[nodiscard]] const std::vector<NewtonEulerRows>& newton_euler() const { return newton_euler_; }
  /// Definition and inertia symbols -> their expressions in parameters (for numbers).
  [[nodiscard]] const GiNaC::exmap& constants() const { return constants_; }
  /// Parameter symbols -> values.
  [[nodiscard]] const GiNaC::exmap& parameter_values() const { return parameter_values_; }
  /// The parameters' and definitions' symbols by the names the file gives them.
  [[nodiscard]] const GiNaC::symtab& names() const { return names_; }
  /// Maximal coordinates, rates and accelerations -> expressions in generalized ones.
  [[nodiscard]] const GiNaC::exmap& to_generalized() const { return to_generalized_; }
  /// Each spring's length symbol (l_k1, in its loads) -> |r_b - r_a| in maximal
  /// coordinates: the equations print the symbol, the numbers substitute this.
  [[nodiscard]] const GiNaC::exmap& lengths() const { return lengths_; }

  /// d/dt by the chain rule over every coordinate and rate symbol, and t.
  [[nodiscard]] GiNaC::ex time_derivative(const GiNaC::ex& e) const;
  /// World position of a body's point, maximal coordinates (body -1: the ground).
  [[nodiscard]] Vec2 point_position(int body, const std::string& point) const;
  /// A parsed quantity of the file, in parameters, definitions (and t where allowed). A
  /// load's value (`state_allowed`) may also name the state by its columns: a body's x,
  /// y, theta and their _dot as the maximal symbols, a slider's s and s_dot as their
  /// expressions in them; elsewhere such a name is refused.
  [[nodiscard]] GiNaC::ex quantity(const Quantity& q, bool time_allowed, bool state_allowed = false) const;
  /// The state's names a load's value may use (its columns: "1.theta", "S.s_dot") -> their
  /// expressions in maximal coordinates and rates.
  [[nodiscard]] const GiNaC::symtab& state_names() const { return state_; }
  /// Whether `e` holds a maximal coordinate or rate (a load that depends on the state).
  [[nodiscard]] bool depends_on_state(const GiNaC::ex& e) const;

  /// Generalized coordinate and rate symbols -> values from the file's [initial].
  [[nodiscard]] GiNaC::exmap initial_state() const;

  /// The constant joint `joint`'s row holds (a gear's c_G; its value in constants(): the
  /// rest of the row at the file's initial state), 0 for a type whose row holds none.
  [[nodiscard]] const GiNaC::ex& joint_constant(int joint) const {
    return joint_constants_.at(static_cast<std::size_t>(joint));
  }

 private:
  void add_parameters();
  void add_bodies();
  void add_joints();
  void add_drivers();
  void add_state_names();
  void add_loads();
  void add_generalized();
  void add_newton_euler();
  void set_joint_constants();

  Mechanism mechanism_;
  SymbolTable table_;
  SpanningTree tree_;
  GiNaC::symbol t_{"t"};
  GiNaC::symtab names_;    // parser symbols: parameters, definitions
  GiNaC::symtab state_;    // the state's column names (loads only) -> maximal expressions
  GiNaC::symtab refused_;  // the same names from the start, for a quantity that may not use them
  std::vector<BodySystem> bodies_;
  std::vector<JointSystem> joints_;
  std::vector<DriverSystem> drivers_;
  std::vector<Load> loads_;
  std::vector<GeneralizedCoordinate> coordinates_;
  std::vector<NewtonEulerRows> newton_euler_;
  GiNaC::exmap constants_, parameter_values_, to_generalized_, lengths_;
  std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> derivative_;  // q -> q', q' -> q''
  std::map<int, CoordinateSymbols> slider_symbols_;               // by joint index
  std::vector<GiNaC::ex> joint_constants_;                        // by joint index
};

[[nodiscard]] Vec2 rotate(const GiNaC::ex& angle, const Vec2& v);
[[nodiscard]] GiNaC::ex cross(const Vec2& a, const Vec2& b);
[[nodiscard]] inline Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.x + b.x, a.y + b.y}; }
[[nodiscard]] inline Vec2 operator-(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
[[nodiscard]] inline Vec2 operator*(const GiNaC::ex& k, const Vec2& v) { return {k * v.x, k * v.y}; }

/// `e` expanded with sin(x)^2 written 1 - cos(x)^2 for every argument x, so that
/// sin² + cos² never survives as such.
[[nodiscard]] GiNaC::ex simplify_trig(const GiNaC::ex& e);

/// A number from a closed expression (no free symbol left); throws std::logic_error if not.
[[nodiscard]] double to_double(const GiNaC::ex& e);

/// A product whose number is beyond double range distributed over its sums, so each term's
/// number is in range: GiNaC keeps a product of exact decimals as c (K1 a + K2) with
/// c = 1e-1318 and K = 1e1314, which double would evaluate as 0 * inf. Otherwise e itself.
[[nodiscard]] GiNaC::ex in_double_range(const GiNaC::ex& e);

/// The value of `e` with each symbol's value taken from `values` (itself evaluated), in
/// double precision. Deterministic where GiNaC's own evalf is not: GiNaC orders the terms
/// of a sum by hash values that change from run to run, so adding floats in its order
/// changes the last bits; here the terms' values are added in sorted order. NaN when a
/// value is not real; std::logic_error naming a symbol without a value.
[[nodiscard]] double evaluate(const GiNaC::ex& e, const GiNaC::exmap& values);

}  // namespace linkage::sym
