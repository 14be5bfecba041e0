#pragma once
// Projection of a Case 1 state back onto the pin constraint, after an accepted step.
//
// Positions q = (x1, y1, th1, x2, y2, th2) move to the nearby point with C(q) = 0 in the
// kinetic-energy metric M = diag(m, m, I, m, m, I), by Newton's method on
//   q <- q - M^-1 J^T (J M^-1 J^T)^-1 C(q),        J = dC/dq (2 x 6)
//   C  = (x2 - x1 - D (cos th1 + cos th2),  y2 - y1 - D (sin th1 + sin th2))
//   J  = [ -1   0   D sin th1   1  0   D sin th2 ]
//        [  0  -1  -D cos th1   0  1  -D cos th2 ]
// iterated until |C| is at round-off of the coordinates. Velocities are then projected
// onto J v = 0 with the same metric, exactly (the condition is linear):
//   v <- v - M^-1 J^T (J M^-1 J^T)^-1 J v
// Mass weighting moves the two blocks by equal and opposite amounts in x and y, so the
// centre of mass and the linear momentum are unchanged.
#include "bench/closed_form/params.hpp"
#include "core/types.hpp"

namespace linkage {

struct ProjectionResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0;  // |C| after the last iteration, m
};

/// Projects y = (x1, y1, th1, x2, y2, th2, rates) in place. On failure (no convergence
/// in a few iterations) y holds the last iterate and `converged` is false.
[[nodiscard]] ProjectionResult project_onto_constraint(const Params& p, Vec<12>& y);

}  // namespace linkage
