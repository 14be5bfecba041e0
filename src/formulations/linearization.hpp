#pragma once
// Small vibrations: the mechanism's equations expanded to first order about a static
// equilibrium, one more transform of the symbolic system (the three cases are the
// others). From Lagrange's rows of Case 3 (case_lagrange.cpp),
//   F(q, q', q'', lambda) = M(q) q'' + A_lambda(q) lambda - B(q, q', t) = 0,  Phi(q) = 0,
// lambda the loop-closing joints' forces and the drivers' torques (A_lambda = -J^T), the
// equilibrium (q0, lambda0) solves F(q0, 0, 0, lambda0) = 0 and Phi(q0) = 0 at t = 0, and
//   M0 dq'' + C0 dq' + K0 dq + A_lambda dlambda = 0,  J0 dq = 0,
// with C0 = dF/dq' and K0 = dF/dq there (lambda0's term is the constraints' curvature).
// Over independent coordinates z, dq = R dz with J0 R = 0, and R^T A_lambda = 0 removes
// dlambda: (R^T M0 R) z'' + (R^T C0 R) z' + (R^T K0 R) z = 0.
#include <ginac/ginac.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "symbolic/system.hpp"

namespace linkage {

struct LinearizeOptions {
  /// Linearize at the file's [initial] coordinates (rates zero) instead of the equilibrium
  /// Newton's method finds from them.
  bool at_initial = false;
};

struct Linearization {
  std::vector<std::string> tree_coordinates;  // every generalized coordinate's column name
  std::vector<std::string> tree_units;        // "rad" or "m"
  Eigen::VectorXd equilibrium;                // their values at the point
  std::vector<std::size_t> independent;       // indices into tree_coordinates: the rows of M, C, K
  std::vector<std::string> coordinates;       // their names
  Eigen::MatrixXd R;                          // tree coordinates x independent ones: dq = R dz
  Eigen::MatrixXd M, C, K;                    // reduced to the independent coordinates
  Eigen::MatrixXd tree_M, tree_C, tree_K;     // in every tree coordinate, before the reduction
  // The same in symbols, as the board writes them: in q and the parameters, lambda kept,
  // rates zero (the tree coordinates' rows and columns).
  std::vector<std::vector<GiNaC::ex>> M_symbolic, C_symbolic, K_symbolic;
  Eigen::VectorXd multipliers;  // lambda0: the loop forces and drivers' torques holding it
  /// The largest generalized force left at the point (N or N m), against `force_scale`,
  /// the largest at [initial]: round-off at an equilibrium found, the imbalance at_initial.
  double residual = 0, force_scale = 0;
  int newton_steps = 0;
  bool at_initial = false;
};

/// The linearization of `system` (see the top of this file). Error::input, one line, when
/// the mechanism has no degree of freedom, a driver moves with t, Newton's method finds no
/// equilibrium, the constraints are singular there, or the mass matrix is not positive
/// definite.
[[nodiscard]] Linearization linearize(const sym::System& system, const LinearizeOptions& options = {});

/// How many modes `system` has, its degrees of freedom: the tree coordinates less the
/// loop and driver rows (0 when the rows take them all), without linearizing.
[[nodiscard]] std::size_t mode_count(const sym::System& system);

struct Mode {
  enum class Kind { oscillation, neutral, unstable };
  Kind kind = Kind::oscillation;
  double omega = 0;            // rad/s, of the undamped system (oscillation)
  double growth_rate = 0;      // 1/s: the motion grows as exp(growth_rate t) (unstable)
  double damping_ratio = 0;    // of the damped system's pair nearest this mode (0 without C)
  double damped_omega = 0;     // rad/s: that pair's imaginary part, the zero crossings' (omega without C)
  Eigen::VectorXd shape;       // in the independent coordinates, largest component +1
  Eigen::VectorXd tree_shape;  // R shape: every tree coordinate
};

/// "oscillation", "neutral" or "unstable", as `linkage modes` names a mode's kind.
[[nodiscard]] std::string kind_word(Mode::Kind kind);

struct ModalAnalysis {
  std::vector<Mode> modes;  // by increasing omega^2 (unstable first, then neutral, then oscillations)
  bool damped = false;      // C is not zero
  bool stable = true;       // no mode grows
};

/// The modes of M z'' + C z' + K z = 0: K v = omega^2 M v for the frequencies and shapes
/// (M symmetric positive definite), the state-space eigenvalues for the damping ratios.
[[nodiscard]] ModalAnalysis modal_analysis(const Linearization& linear);

}  // namespace linkage
