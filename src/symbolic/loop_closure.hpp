#pragma once
// Closing a mechanism's loops at the start: the file's [initial] need only be close. With
// Phi(q, t) the loop-closing joints' constraints and the drivers' rows in the generalized
// coordinates q, split q = (q_i, q_d): the coordinates in `independent` that no driver
// moves stay, Newton's method solves Phi(q_i, q_d, 0) = 0 for q_d (so a driven coordinate
// lands on its motion at t = 0), and the rates follow from Phi_q q' = -Phi_t with q_i' kept.
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

/// The state with every loop closed and every driver on its motion at time t (the initial
/// state: t = 0); Error::input naming the loop
/// joints when Newton's method does not converge or the independent coordinates do not fit.
[[nodiscard]] ClosedState close_loops(const System& system, const GiNaC::exmap& state, double t = 0);

/// The file's initial state checked and closed, as every command starts from it: the
/// quantities evaluate (validate_quantities), no constraint is redundant before or after
/// closing (validate_constraints), the loops are closed (close_loops).
[[nodiscard]] ClosedState checked_initial_state(const System& system);

}  // namespace linkage::sym
