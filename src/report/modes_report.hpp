#pragma once
// `linkage modes`: the small vibrations of a mechanism (formulations/linearization.hpp)
// as text (the equilibrium, the expansion in symbols, M, C, K in numbers, the modes) and
// as JSON (the contract of issue 26: equilibrium, coordinates, M, C, K, modes, stable).
#include <string>

#include "formulations/linearization.hpp"
#include "integrate/mode_verification.hpp"
#include "report/report_options.hpp"
#include "symbolic/system.hpp"

namespace linkage {

/// With `checks` (modes --verify), a last section comparing them.
[[nodiscard]] std::string modes_text(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                                     const ReportOptions& options, const std::vector<ModeCheck>* checks = nullptr);

/// With `checks`, a "verify" list: mode (1-based), predicted, measured, relative_error.
[[nodiscard]] std::string modes_json(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                                     const std::vector<ModeCheck>* checks = nullptr);

/// The agreement --verify asks of each mode, relative.
inline constexpr double kModeCheckTolerance = 1e-5;

}  // namespace linkage
