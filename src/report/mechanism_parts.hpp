#pragma once
// Pieces every writer of a mechanism's derivation uses alike (mechanism_text,
// mechanism_latex): how a body is called, where a load acts, whether anything ties the
// mechanism to the world, and a constraint's acceleration form.
#include <string>

#include "core/style.hpp"
#include "model/mechanism.hpp"
#include "report/notation.hpp"
#include "symbolic/system.hpp"

namespace linkage {

/// "block 1", "rod 2", "disc 3", "mass 4" for a body named by digits, else its name;
/// "the ground" for -1.
[[nodiscard]] std::string body_label(const Mechanism& mechanism, int body);

/// The label of the body named `name` (kGround: "the ground").
[[nodiscard]] std::string body_label(const Mechanism& mechanism, const std::string& name);

/// Where `load` acts on body `body`: "the centre of mass", a named point of the body, or ""
/// when it is neither.
[[nodiscard]] std::string load_place(const sym::System& system, std::size_t body, const sym::Load& load);

/// Whether a joint or spring holds the mechanism to the ground, or an applied force or
/// torque acts: otherwise its horizontal momentum stays constant.
[[nodiscard]] bool touches_ground(const Mechanism& mechanism);

/// The second time derivative of the constraint row `phi` as Case 1 writes it: the
/// accelerations on the left (in the order of the symbol table), the rest on the right.
[[nodiscard]] EquationSides acceleration_form(const sym::System& system, const GiNaC::ex& phi, Style style);

}  // namespace linkage
