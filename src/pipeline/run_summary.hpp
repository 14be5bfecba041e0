#pragma once
// A simulated run summed up as a table: its case and method, its cost, its errors and
// where it ended.
#include <string>

#include "core/result_table.hpp"
#include "integrate/mechanism_simulation.hpp"
#include "integrate/simulation_options.hpp"
#include "pipeline/run.hpp"

namespace linkage {

/// "dop853 (rtol 1e-10, atol 1e-10)" or "rk4 (dt 0.001 s)", 3 significant digits, with
/// Case 1's stabilization.
[[nodiscard]] std::string method_text(const SimulationOptions& options);

/// A run's summary: the mechanism, case, method, cost, errors, every generalized
/// coordinate at the end (y = `end`) in words and units (named as run.built names
/// them), run time.
[[nodiscard]] ResultTable mechanism_summary(const Run& run, const MechanismStats& stats, const Eigen::VectorXd& end);

}  // namespace linkage
