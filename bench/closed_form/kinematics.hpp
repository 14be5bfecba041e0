#pragma once
// Positions, velocities and the invariants of the motion (spec sec. 2):
//   P  = C1 + D (cos th1, sin th1)             the pin
//   C2 = P  + D (cos th2, sin th2)             block 2's centre of mass
//   C2' = C1' + D (-th1' sin th1 - th2' sin th2,  th1' cos th1 + th2' cos th2)
//   T = m/2 (|C1'|^2 + |C2'|^2) + I/2 (th1'^2 + th2'^2),  V = m g (y1 + y2)
//   p = m (C1' + C2'),   H_c = m/2 (C2 - C1) x (C2' - C1') + I (th1' + th2')
// H_c is the angular momentum about the system's centre of mass. Nothing external
// acts but uniform gravity, so T + V, p_x, H_c are constant and p_y falls at 2 m g.
#include "bench/closed_form/params.hpp"
#include "bench/closed_form/state.hpp"
#include "core/types.hpp"

namespace linkage {

/// The Case 1 coordinates that satisfy the pin constraint exactly.
[[nodiscard]] BodyState body_state(const Params& p, const State& s);

[[nodiscard]] Vec2 pin_position(const Params& p, double x1, double y1, double theta1);

struct Invariants {
  double kinetic_energy = 0;
  double potential_energy = 0;
  double energy = 0;
  Vec2 momentum = Vec2::Zero();
  double angular_momentum = 0;  // about the system's centre of mass
};
[[nodiscard]] Invariants invariants(const Params& p, const BodyState& s);

/// The system's centre of mass G = (C1 + C2) / 2.
[[nodiscard]] Vec2 system_com(const BodyState& s);
/// Its velocity.
[[nodiscard]] Vec2 system_com_velocity(const BodyState& s);

/// Constraint residuals of a Case 1 state: C = C2 - (C1 + D(e1 + e2)) and its rate.
struct ConstraintError {
  Vec2 position = Vec2::Zero();
  Vec2 velocity = Vec2::Zero();
};
[[nodiscard]] ConstraintError constraint_error(const Params& p, const BodyState& s);

/// Everything `linkage solve` reports before the equations of motion.
struct Derived {
  double I_zz_C = 0, D = 0, I_zz_P = 0;
  Vec2 pin = Vec2::Zero();
  Vec2 C2 = Vec2::Zero();
  Vec2 C2_dot = Vec2::Zero();
  Invariants invariants;
};
[[nodiscard]] Derived derive(const Params& p, const State& s);

/// A size of the system's energy for relative energy errors: |E| when the potential
/// datum is irrelevant would mislead, so this is kinetic + m g (|y1| + |y2|) + m g L.
[[nodiscard]] double energy_scale(const Params& p, const BodyState& s);

}  // namespace linkage
