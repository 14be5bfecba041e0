#pragma once
// The values of a mechanism file that change during a run because they read the state (or
// t): a [[force]]'s or [[torque]]'s value, a spring's or damper's, a pin's torsional
// spring's. The run checks them at every state it reaches (integrate/load_guard), the
// derivation prints them as the file writes them (report/mechanism_parts).
#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "model/mechanism.hpp"
#include "symbolic/system.hpp"

namespace linkage::sym {

struct StateValue {
  std::string what;           // "stiffness of spring k1", as the start's checks name it
  const Quantity* quantity;   // the file's text and position
  bool non_negative = false;  // a stiffness, damping or rest length
  GiNaC::ex value;            // in maximal coordinates and rates (System::quantity)
};

/// In file order: joints, springs, forces, torques. Only the values that read the state
/// or t; the others are checked once at the start.
[[nodiscard]] std::vector<StateValue> state_values(const System& system);

}  // namespace linkage::sym
