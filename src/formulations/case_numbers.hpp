#pragma once
// A case's A and B at a state, and its solution. Numbers come from the case's own GiNaC
// entries (exact substitution; the compiled evaluator of src/evaluate is the fast route
// to the same values).
#include <ginac/ginac.h>

#include <Eigen/Core>
#include <optional>
#include <string>

#include "formulations/case_system.hpp"

namespace linkage {

/// Every symbol's value at a state: parameters, definitions and inertias, the generalized
/// coordinates and rates in `state`, the maximal ones they imply, the springs' lengths,
/// and the time. Throws
/// Error::input (require_finite) naming a value that overflows.
[[nodiscard]] GiNaC::exmap state_values(const sym::System& system, const GiNaC::exmap& state, double time);

struct CaseNumbers {
  Eigen::MatrixXd A;
  Eigen::VectorXd B;
  Eigen::VectorXd solution;
  double residual = 0;   // ||A u - B||_2
  double condition = 0;  // sigma_max / sigma_min
};

/// Evaluates and solves; throws Error::input naming the case and the condition number
/// when A is singular to working precision, and Error::input when an entry is not finite.
[[nodiscard]] CaseNumbers solve_numbers(const CaseSystem& c, const GiNaC::exmap& values);

/// Solves numeric A and B of case `id`, with the same checks.
[[nodiscard]] CaseNumbers solve_matrices(CaseId id, Eigen::MatrixXd A, Eigen::VectorXd B);

/// The value of `u` (an acceleration or joint force symbol) in a solved case: from the
/// solution, or from the case's recovered expressions; nullopt when the case has neither.
/// `recovered` says which.
[[nodiscard]] std::optional<double> case_value(const CaseSystem& c, const CaseNumbers& numbers,
                                               const GiNaC::exmap& values, const GiNaC::symbol& u,
                                               bool* recovered = nullptr);

/// Throws Error::input "NAME = inf overflows double precision" (or "is not a number")
/// unless `value` is finite.
void require_finite(const std::string& name, double value);

/// The value of an expression at `values` (every symbol in it must have one).
[[nodiscard]] double value_at(const GiNaC::ex& e, const GiNaC::exmap& values);

}  // namespace linkage
