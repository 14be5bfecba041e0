#pragma once
// Closing a mechanism's loops at the start: the file's [initial] need only be close. With
// Phi(q) the loop-closing joints' constraints in the generalized coordinates q, split
// q = (q_i, q_d): the coordinates in `independent` stay, Newton's method solves
// Phi(q_i, q_d) = 0 for q_d, and the rates follow from Phi_q q' = 0 with q_i' kept.
#include <ginac/ginac.h>

#include <string>

#include "symbolic/system.hpp"

namespace linkage::sym {

struct ClosedState {
  GiNaC::exmap state;  // generalized coordinates and rates
  bool changed = false;
  double largest_change = 0;  // of a coordinate, m or rad
  std::string note;           // one sentence for the report, empty when nothing closed
};

/// The initial state with every loop closed; Error::input naming the loop joints when
/// Newton's method does not converge or the independent coordinates do not fit.
[[nodiscard]] ClosedState close_loops(const System& system, const GiNaC::exmap& state);

/// The file's initial state checked and closed, as every command starts from it: the
/// quantities evaluate (validate_quantities), no constraint is redundant before or after
/// closing (validate_constraints), the loops are closed (close_loops).
[[nodiscard]] ClosedState checked_initial_state(const System& system);

/// Throws Error::input naming the first driver whose joint `state` (generalized
/// coordinates and rates) does not put on its motion at t = 0, position or rate.
void require_on_the_motion(const System& system, const GiNaC::exmap& state);

}  // namespace linkage::sym
