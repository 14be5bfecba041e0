#pragma once
// Checks of a mechanism that need its expressions: every quantity evaluates to a finite
// number at the parameters (no unknown symbol, no division by zero), masses, sizes and
// inertias are positive, spring constants are not negative, a slider joins two bodies that
// rotate, and no joint's constraint repeats what the others already impose.
#include "symbolic/system.hpp"

namespace linkage::sym {

/// Throws Error::input with FILE:LINE:COLUMN, the value and the valid range.
void validate_quantities(const System& system);

/// Throws Error::input naming the joints when the constraints are redundant at `state`
/// (generalized coordinates and rates).
void validate_constraints(const System& system, const GiNaC::exmap& state);

/// Throws Error::input naming the gear when its centres are not r1 + r2 (external) or
/// |r1 - r2| (internal) apart, within a relative 1e-9, at `state` (the closed initial one).
void validate_meshes(const System& system, const GiNaC::exmap& state);

}  // namespace linkage::sym
