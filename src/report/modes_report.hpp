#pragma once
// `linkage modes`: the small vibrations of a mechanism (formulations/linearization.hpp)
// as text (the equilibrium, the expansion in symbols, M, C, K in numbers, the modes) and
// as JSON (the contract of issue 26: equilibrium, coordinates, M, C, K, modes, stable).
#include <string>

#include "formulations/linearization.hpp"
#include "report/report_options.hpp"
#include "symbolic/system.hpp"

namespace linkage {

[[nodiscard]] std::string modes_text(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                                     const ReportOptions& options);

[[nodiscard]] std::string modes_json(const sym::System& system, const Linearization& linear,
                                     const ModalAnalysis& modes);

}  // namespace linkage
