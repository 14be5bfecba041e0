#pragma once
// `linkage modes`: the small vibrations of a mechanism (formulations/linearization.hpp)
// as text, LaTeX and Markdown from one list of sections (the equilibrium, the expansion in
// symbols, M, C, K in numbers, the modes and, through a loop, each body's motion) and as
// JSON (the contract of issue 26: equilibrium, coordinates, M, C, K, modes, stable).
#include <optional>
#include <string>
#include <vector>

#include "formulations/linearization.hpp"
#include "integrate/mode_verification.hpp"
#include "report/report_options.hpp"
#include "symbolic/system.hpp"

namespace linkage {

/// What a modes report shows of a mechanism: its linearization, its modes and (modes
/// --verify) their checks against the full equations.
struct ModesAnalysis {
  Linearization linear;
  ModalAnalysis modes;
  std::optional<std::vector<ModeCheck>> checks;
  [[nodiscard]] const std::vector<ModeCheck>* checked() const { return checks ? &*checks : nullptr; }
};
/// `system` linearized (at its [initial] coordinates themselves with `at_initial`) and its
/// modes, checked with `verify`; Error::input as linearize.
[[nodiscard]] ModesAnalysis analyse_modes(const sym::System& system, bool at_initial, bool verify);

/// With `checks` (modes --verify), a last section comparing them.
[[nodiscard]] std::string modes_text(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                                     const ReportOptions& options, const std::vector<ModeCheck>* checks = nullptr);
/// The same as a LaTeX fragment (ASCII; needs amsmath), the expressions in LaTeX.
[[nodiscard]] std::string modes_latex(const sym::System& system, const Linearization& linear,
                                      const ModalAnalysis& modes, const ReportOptions& options,
                                      const std::vector<ModeCheck>* checks = nullptr);
/// The same in Markdown: a heading per section, pipe tables, math in $ and $$.
[[nodiscard]] std::string modes_markdown(const sym::System& system, const Linearization& linear,
                                         const ModalAnalysis& modes, const ReportOptions& options,
                                         const std::vector<ModeCheck>* checks = nullptr);

/// With `checks`, a "verify" list: mode (1-based), predicted, measured, relative_error.
[[nodiscard]] std::string modes_json(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                                     const std::vector<ModeCheck>* checks = nullptr);

/// The agreement --verify asks of each mode, relative.
inline constexpr double kModeCheckTolerance = 1e-5;

}  // namespace linkage
