#pragma once
// Case 3's accelerations by recursion over the spanning tree, in O(n) for n bodies: the
// articulated-body algorithm in the plane, then a Schur complement for the constraints
// of the joints that close loops.
//
// Planar spatial vectors in world axes, each body's about its own point O (its joint's
// point; a floating base's centre): near the body, so I + m |c|^2 keeps I's digits, and
// from one body to the next only a translation. A motion v = (omega, vx, vy), (vx, vy) the
// velocity of the body point at O; a force f = (n, Fx, Fy), n the moment about O. A body of
// mass m, inertia I about its centre of mass c (relative to O) has the spatial inertia
//   [ I + m |c|^2   -m c_y   m c_x ]
//   [ -m c_y         m        0    ]
//   [  m c_x         0        m    ]
// and each joint's motion subspace S (3 x k) and bias S' q' give, root to leaves,
//   v_i = X v_p + S_i q'_i,   c_i = (X v_p) x S_i q'_i,
// leaves to root the articulated inertias and bias forces
//   U = I^A S,  D = S^T U,  u = tau - S^T p^A,
//   I^A_p += X^T (I^A - U D^-1 U^T) X,   p^A_p += X^T (p^A + (I^A - U D^-1 U^T) c + U D^-1 u),
// and root to leaves the accelerations q''_i = D^-1 (u - U^T (X a_p + c_i)), with X the
// move from O_p to O_i. A pin's S = (1, 0, 0) about its own point, so U is I^A's first
// column and D a scalar; sliders translate along their axis, a floating base moves in x,
// y, theta of its centre of mass. The relative angle of a pin is the child's absolute
// angle (its generalized coordinate) less its parent's.
//
// The loads (gravity, springs, dampers, joint springs, applied forces and torques) come
// from the one symbolic system, compiled into a program; only the rigid-body recursion is
// numeric. Loop closure: with J = dPhi/dq and Phi'' = J q'' + phi0 = 0,
//   q'' = q''_0 + M^-1 J^T lambda,   (J M^-1 J^T) lambda = -phi0 - J q''_0,
// each column of M^-1 J^T one more pass of the recursion without velocities or loads, on
// the articulated inertias of the loaded pass (they depend on the positions alone).
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "evaluate/program.hpp"
#include "symbolic/system.hpp"

namespace linkage::eval {

class TreeDynamics {
 public:
  /// Whether the recursion applies: every body reached through a joint rotates (a point
  /// mass hanging from a pin has no angle to give the recursion).
  [[nodiscard]] static bool applies(const sym::System& system);

  explicit TreeDynamics(const sym::System& system);
  ~TreeDynamics();
  TreeDynamics(TreeDynamics&&) noexcept;
  TreeDynamics& operator=(TreeDynamics&&) noexcept;

  /// q'' (generalized coordinates, the System's order) at t and y = (q, q', ...), at the
  /// System's parameter values. False when the loop constraints are singular there (a
  /// change point): q'' is then not to be used.
  bool accelerations(double t, const Eigen::VectorXd& y, Eigen::VectorXd& q_ddot) const;

  /// The programs it runs (the loads, the loops' Jacobian), for native code.
  [[nodiscard]] std::vector<Program*> programs();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace linkage::eval
