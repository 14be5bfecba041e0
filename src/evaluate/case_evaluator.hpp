#pragma once
// A case's A and B compiled once into a Program over the mechanism's inputs: the
// parameters (file order), the generalized coordinates and rates (coordinate order) and
// the time. Definitions and inertias are substituted by their expressions in the
// parameters, and Case 1's maximal coordinates and rates by theirs in the generalized
// ones, so the numbers come from the very expressions the report prints.
#include <ginac/ginac.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <vector>

#include "evaluate/program.hpp"
#include "formulations/case_system.hpp"

namespace linkage::eval {

class CaseEvaluator {
 public:
  CaseEvaluator(const sym::System& system, const CaseSystem& c);

  /// The input symbols, in the order of inputs().
  [[nodiscard]] const std::vector<GiNaC::symbol>& input_symbols() const { return inputs_; }
  /// The input vector at a state: every parameter, generalized coordinate and rate from `values`.
  [[nodiscard]] std::vector<double> inputs(const GiNaC::exmap& values) const;
  /// A and B at `inputs` (sized to the case).
  void evaluate(const std::vector<double>& inputs, Eigen::MatrixXd& A, Eigen::VectorXd& B) const;
  /// Solves A u = B at `inputs` into `unknowns` (in the case's order) and returns an
  /// estimate of A's reciprocal condition number: near 0 means singular, and then
  /// `unknowns` is not to be used. The one seam for the accelerations of any mechanism.
  double solve(const std::vector<double>& inputs, Eigen::VectorXd& unknowns) const;
  /// The programs it runs, for native_library.hpp's attach_native.
  [[nodiscard]] std::vector<Program*> programs() { return {&program_}; }

 private:
  std::vector<GiNaC::symbol> inputs_;
  Program program_;
  std::size_t rows_ = 0, cols_ = 0;
  mutable std::vector<double> outputs_, scratch_;
  mutable Eigen::MatrixXd A_;
  mutable Eigen::VectorXd B_;
  mutable Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace linkage::eval
