#pragma once
// The unit of an expression in the parameters, by dimensional analysis: a definition such
// as D = L/2 - b gets the unit its parameters give it (m), so the reports can print it.
#include <ginac/ginac.h>

#include <optional>
#include <string>

#include "symbolic/symbols.hpp"

namespace linkage::sym {

/// An ASCII unit ("m", "kg m^2", "N s/m", "1/s", "rad") as a product of powers of the
/// base units kg, m and s (rad and an empty unit count as 1); nullopt for a unit this
/// does not know.
[[nodiscard]] std::optional<GiNaC::ex> parse_unit(const std::string& unit);

/// The unit of `e` from the units of the parameters in `table`: "m", "kg m^2", "m/s^2",
/// "" when it has none (a pure number or an angle); nullopt when a parameter's unit is
/// unknown or the terms of a sum disagree.
[[nodiscard]] std::optional<std::string> unit_of(const GiNaC::ex& e, const SymbolTable& table);

}  // namespace linkage::sym
