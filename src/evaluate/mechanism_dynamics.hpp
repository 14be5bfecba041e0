#pragma once
// One case of any mechanism as a first-order system for the integrators, compiled once
// from the case's GiNaC rows (the very expressions `solve` prints):
//   state y = (q, q', W): the case's coordinates (Case 1: x, y, theta of every body;
//   Cases 2 and 3: the tree's generalized coordinates), their rates, and W, the work done
//   so far by dampers, applied loads and drivers, so that E(t) - E(0) - W(t) = 0 is a
//   check even when the energy is not conserved. A mechanism with none of them has no W
//   (it would stay 0): its state is (q, q'), an even number of values, and the
//   integrators do not carry a constant along;
//   y' = (q', q'', P) with A(q, q', t) u = B(q, q', t) solved for u, whose first entries are
//   q'' (the remaining ones joint forces), and P the power of dampers, applied loads and drivers.
// Constraints C(q) = 0 that the case keeps (Case 1: every joint; Cases 2 and 3: the joints
// that close loops; in every case each driver's C(q, t) = driven(q) - motion(t), after
// them) are met at the acceleration level only, with C' = J q' + C_t; Baumgarte's correction asks
//   C'' + 2 alpha C' + beta^2 C = 0,   so   B <- B - 2 alpha C' - beta^2 C   on their rows,
// and a projection moves q and q' back onto C = 0, C' = 0 in the kinetic-energy metric
// M = d^2 T / dq'^2 (mass-weighted, so free mechanisms keep their momentum).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "evaluate/native_library.hpp"
#include "evaluate/program.hpp"
#include "evaluate/static_solve.hpp"
#include "formulations/case_system.hpp"

namespace linkage::eval {

class TreeDynamics;

/// What one sample of a run reports, for the columns of `simulate` and the drawing.
struct MechanismSample {
  std::vector<double> pose;    // per body: x, y, theta (0 for a point mass)
  std::vector<double> rates;   // per body: x', y', theta'
  std::vector<double> slider;  // per joint: s for a slider, 0 for a pin
  // Per joint: force x, force y, moment (the force bodies[1] exerts on bodies[0]); then per
  // joint its first two force unknowns when its type writes them (a rolling's normal, friction), else 0.
  std::vector<double> force;
  std::vector<double> constraint;       // per joint: |C| of its position rows, m (and rad)
  std::vector<double> constraint_rate;  // per joint: |C'|, m/s (and rad/s)
  double kinetic = 0, potential = 0;
  double power = 0;             // of dampers and applied loads, W
  std::vector<double> drivers;  // per [[driver]]: its torque (N m) or force (N) on its joint's bodies[1]
  double momentum_x = 0, momentum_y = 0;
  double angular_momentum = 0;  // about the centre of mass
  std::array<double, 4> com{};  // the centre of mass: x, y, x', y'
  // The force the moving bodies exert on the ground (x, y, N) and its moment about the
  // world origin (N m): sym::ground_reaction.
  std::array<double, 3> shaking{};
  // Only when sample() is asked for the kinematics (a column needs them), else empty:
  std::vector<double> accelerations;         // per body: x'', y'', theta'' (0 for a point mass)
  std::vector<double> slider_accelerations;  // per joint: s'' for a slider, 0 for a pin
  std::vector<double> points;                // per named point: x, y, x', y', x'', y'' (world frame)
};

/// A named point of a moving body, in the order of MechanismSample::points: bodies in
/// file order, each body's points by name.
struct NamedPoint {
  std::size_t body = 0;
  std::string name;
};
[[nodiscard]] std::vector<NamedPoint> named_points(const sym::System& system);

/// W of a state (q, q', W); 0 for a state (q, q') that carries none (an even size).
[[nodiscard]] inline double work_of(const Eigen::VectorXd& y) { return y.size() % 2 == 1 ? y[y.size() - 1] : 0.0; }

class MechanismDynamics {
 public:
  /// `system` must outlive this. `derived`: the case as derive_case(system, id) gives it,
  /// when the caller has it already (solve's check of the initial state), so that a long
  /// chain is not derived twice.
  MechanismDynamics(const sym::System& system, CaseId id, std::optional<CaseSystem> derived = {});
  ~MechanismDynamics();
  MechanismDynamics(MechanismDynamics&&) noexcept;
  MechanismDynamics& operator=(MechanismDynamics&&) noexcept;

  [[nodiscard]] CaseId case_id() const { return id_; }
  /// Coordinates n; the state has 2 n values, and 2 n + 1 when it carries W.
  [[nodiscard]] int coordinates() const { return static_cast<int>(coordinate_names_.size()); }
  [[nodiscard]] int state_size() const { return 2 * coordinates() + (carries_work() ? 1 : 0); }
  /// Whether anything does work besides gravity and springs' potential: dampers, applied
  /// loads, drivers. Only then does the state carry W.
  [[nodiscard]] bool carries_work() const { return !power_zero_ || drivers_ > 0; }
  /// "1.x", "2.theta", "slider.s": the state's coordinates in order.
  [[nodiscard]] const std::vector<std::string>& coordinate_names() const { return coordinate_names_; }
  /// Constraint rows kept by the case (met at the acceleration level).
  [[nodiscard]] int constraint_rows() const { return constraint_rows_; }
  /// The joint each kept constraint row belongs to (index into Mechanism::joints).
  [[nodiscard]] const std::vector<int>& constraint_joints() const { return constraint_joint_; }

  /// The state at the mechanism's (closed) initial generalized state `values` (W = 0 where carried).
  [[nodiscard]] Eigen::VectorXd initial_state(const GiNaC::exmap& values) const;

  /// Baumgarte gains in 1/s (both 0: the plain equations).
  void set_baumgarte(double alpha, double beta);

  /// y' at (t, y), y of 2 n values or 2 n + 1 with W (W' then the power, else not
  /// computed). False when A is singular there (rcond below round-off): dydt is then NaN.
  bool derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const;
  /// The case's unknowns u at (t, y) and the ratio of A's smallest to largest LU pivot, a
  /// cheap stand-in for its reciprocal condition (0: singular, u not to be used).
  double unknowns(double t, const Eigen::VectorXd& y, Eigen::VectorXd& u) const;

  /// Moves y onto C(q) = 0 and C'(q, q') = 0 (Newton in the kinetic-energy metric); the
  /// largest |C| left. Does nothing without kept constraints.
  double project(double t, Eigen::VectorXd& y) const;
  /// The largest |C| of the kept constraints at y (0 without).
  [[nodiscard]] double constraint_violation(double t, const Eigen::VectorXd& y) const;
  /// The name of the joint whose kept constraint is violated most at y ("" without).
  [[nodiscard]] std::string worst_joint(double t, const Eigen::VectorXd& y) const;

  /// True when the drivers take every degree of freedom: as many kept rows as coordinates,
  /// so C(q, t) = 0 alone fixes q (kinematic analysis, integrator/kinematic_path.hpp).
  [[nodiscard]] bool kinematic() const { return drivers_ > 0 && static_cast<std::size_t>(constraint_rows_) == n_; }
  /// Kinematic only. Newton's method on C(q, t) = 0 from y's q, J square; true when it met
  /// the constraints to round-off (q is then that solution, q' untouched).
  bool close_positions(double t, Eigen::VectorXd& y) const;
  /// Kinematic only. q' from J q' = -C_t at y's q.
  void solve_rates(double t, Eigen::VectorXd& y) const;
  /// The kept rows' Jacobian J's smallest over its largest singular value at y's q (0:
  /// singular; 1 without kept rows).
  [[nodiscard]] double jacobian_spread(double t, const Eigen::VectorXd& y) const;
  /// Kinematic only. The sign of det J at y's q (1, -1; 0 when singular), from J's LU so
  /// that no product of pivots under- or overflows: it changes where a path crosses a
  /// singular point.
  [[nodiscard]] int jacobian_sign(double t, const Eigen::VectorXd& y) const;

  /// `values` as sym::System::quantity() reads them (maximal coordinates, their rates, t)
  /// compiled over this case's state, for evaluate_over_state().
  [[nodiscard]] Program compile_over_state(const std::vector<GiNaC::ex>& values) const;
  /// Runs such a program at (t, y): its output_count() values into `out`; `scratch` holds
  /// its scratch_size() doubles.
  void evaluate_over_state(const Program& program, double t, const Eigen::VectorXd& y, double* out,
                           double* scratch) const;

  /// Everything a sample reports at (t, y), from one evaluation of the unknowns; with
  /// `kinematics` the accelerations and the named points' motion too (compiled on first need).
  void sample(double t, const Eigen::VectorXd& y, MechanismSample& out, bool kinematics = false) const;

  /// Compiles the case (and with `kinematics` the sample's kinematics) now, then runs every
  /// program of this case, the tree recursion's included, as native code
  /// (native_library.hpp), or none of them; what happened and why. Programs compiled later
  /// (the kinematics, when not asked for here) stay interpreted.
  [[nodiscard]] NativeAttachment attach_native(bool kinematics = false, bool may_compile = true);
  /// As attach_native(), on a tree's Case 3 for the programs derivative() runs there
  /// without Baumgarte's terms alone (the recursion's and the power), A and B not expanded
  /// (minutes for a long chain); for `bench mechanisms`. Other cases: attach_native().
  [[nodiscard]] NativeAttachment attach_native_derivative(bool may_compile = true);
  /// Runs every program of programs(kinematics) as built-in native code
  /// (native_builtin.hpp) when each has some, else none; whether it did. The kinematics,
  /// compiled later, are then attached too when built in.
  [[nodiscard]] bool attach_builtin(bool kinematics = false);
  /// Every program this case runs (compiled now), the tree recursion's included, and with
  /// `kinematics` the sample's kinematics: the one list native code is made for.
  [[nodiscard]] std::vector<Program*> programs(bool kinematics = false);
  /// Whether derivative() solves A u = B by its structure (the default: an unrolled
  /// fixed-size LU up to 8 rows; the Schur complement of [M G; J 0] above, M by LDL^T) or
  /// by the general LU (off: the reference it agrees with to 1e-12, not to the last bit).
  void solve_by_structure(bool on) { structured_ = on; }

 private:
  [[nodiscard]] GiNaC::ex prepare(const GiNaC::ex& e) const;
  /// Derives the case and compiles A, B and the sample, on first need: a long chain's
  /// Case 3 integrates by the tree's recursion without ever expanding them.
  void compile_case() const;
  void compile_kinematics() const;
  void fill_inputs(double t, const Eigen::VectorXd& y) const;
  void evaluate_constraints(double t, const Eigen::VectorXd& y) const;
  /// The drivers' C_t and J q' into time_rate_values_ (nothing without drivers).
  void evaluate_time_rates(double t, const Eigen::VectorXd& y) const;
  /// C' = J q' + C_t of the kept rows, J_ evaluated at y already.
  [[nodiscard]] Eigen::VectorXd constraint_rate(double t, const Eigen::VectorXd& y) const;
  /// The drivers' power at (t, y) with the case's unknowns u, W.
  [[nodiscard]] double driver_power(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& u) const;
  /// A (row major) and B into values_, B with Baumgarte's terms.
  void evaluate_rows(double t, const Eigen::VectorXd& y) const;
  /// As unknowns(), by A's structure: up to kFixedRows rows one fixed-size LU (no
  /// allocation, unrolled); A = [M G; J 0] with G = +-J^T by the Schur complement
  /// (J M^-1 G) lambda = J M^-1 b1 - b2 (M diagonal: divided by); else the general LU.
  /// Not for a long tree's Case 3, which the recursion solves in O(n).
  double structured_unknowns(double t, const Eigen::VectorXd& y, Eigen::VectorXd& u) const;
  void find_structure(const std::vector<GiNaC::ex>& rhs) const;
  void find_sparsity(const std::vector<GiNaC::ex>& rhs) const;
  /// structured_unknowns() for M diagonal and at most kFixedRows constraint rows: only
  /// J's structural non-zeros, S = J M^-1 J^T symmetric (its upper triangle, LDL^T).
  double diagonal_schur(Eigen::VectorXd& u) const;
  /// The general LU of A and B at values_.
  double general_unknowns(Eigen::VectorXd& u) const;
  /// u_ by solve_ (A, B and their solve in one program, static_solve.hpp), native or
  /// interpreted alike, without Baumgarte's terms; false when there is no such program or
  /// its pivots reject it.
  bool static_unknowns(double t, const Eigen::VectorXd& y) const;

  CaseId id_;
  const sym::System* system_;
  std::size_t parameters_ = 0, n_ = 0, bodies_ = 0, joints_ = 0;
  std::vector<std::size_t> joint_rows_;  // each joint's position rows, in its constraint error
  mutable std::size_t rows_ = 0, cols_ = 0;
  mutable bool compiled_ = false;
  std::optional<CaseSystem> derived_;  // the case, when given; derived on first need otherwise
  GiNaC::exmap to_state_;              // maximal coordinates and rates in the state's (none for Case 1)
  std::vector<GiNaC::symbol> input_symbols_;
  Program power_;  // P, of dampers and applied loads
  bool power_zero_ = false;
  std::unique_ptr<TreeDynamics> tree_;  // Case 3 of a tree: the O(n) recursion
  int constraint_rows_ = 0;
  std::size_t drivers_ = 0;  // the last constraint rows and the last unknowns
  Program time_rates_;       // with drivers: C_t of every kept row, then each driver's J q'
  mutable std::vector<double> time_rate_values_;
  std::vector<int> constraint_joint_;
  std::vector<std::string> coordinate_names_;
  std::vector<double> parameter_values_;
  std::vector<GiNaC::symbol> state_symbols_;    // q, then q'
  std::vector<GiNaC::ex> initial_expressions_;  // the state in generalized coordinates and rates
  GiNaC::exmap constants_;                      // parameters, definitions and inertias
  mutable Program rhs_;                         // A (row major), B
  mutable Program solve_;                       // up to kFixedRows rows: u, then the pivots (static_solve.hpp)
  mutable bool static_plain_ = false;           // derivative() is solve_ alone: no power, no drivers
  mutable PivotCheck pivot_check_;              // whether solve_'s pivots allow its u
  mutable std::vector<double> solve_inputs_, solve_values_;  // solve_'s inputs: inputs_, then the hoisted factors
  Program constraints_;                                      // C, dC/dq (row major), M (row major)
  mutable Program outputs_;                                  // the sample, with the unknowns as inputs too
  mutable Program kinematics_;                               // accelerations and points, with the same inputs
  mutable bool kinematics_compiled_ = false;
  bool builtin_ = false;  // attach_builtin succeeded: the kinematics too, once compiled
  mutable std::vector<GiNaC::symbol> output_symbols_;
  double two_alpha_ = 0, beta_squared_ = 0;
  mutable std::vector<double> inputs_, values_, scratch_, constraint_values_, output_inputs_, power_values_;
  mutable Eigen::MatrixXd A_, J_, M_;
  mutable Eigen::VectorXd B_, u_;
  mutable Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  bool structured_ = true;                              // solve_by_structure(): derivative() solves by structure
  mutable bool schur_ = false, mass_diagonal_ = false;  // A = [M G; J 0], G = +-J^T (M diagonal)
  mutable int schur_sign_ = 1;                          // G = schur_sign_ J^T
  mutable std::vector<std::uint32_t> row_start_, row_columns_;    // J's non-zero columns by row
  mutable std::vector<std::uint32_t> pair_start_, pair_columns_;  // those rows k <= l share
  mutable Eigen::MatrixXd minv_g_;
  mutable Eigen::VectorXd minv_b_, mass_inverse_, lambda_;
  mutable std::vector<double> schur_values_;
  mutable Eigen::LDLT<Eigen::MatrixXd> mass_ldlt_;
  mutable Eigen::PartialPivLU<Eigen::MatrixXd> schur_lu_;
};

}  // namespace linkage::eval
