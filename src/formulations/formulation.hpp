#pragma once
// The three formulations behind one runtime interface, for reports and the CLI:
// `solve_case` evaluates and solves a case at a state; `symbolic_system` prints its
// definition. Both come from the one definition in case1/2/3.hpp.
#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "formulations/expr.hpp"
#include "formulations/unknowns.hpp"
#include "model/params.hpp"
#include "model/state.hpp"

namespace linkage {

inline constexpr std::array<int, 3> kCaseIds{1, 2, 3};

struct CaseSolution {
  int id = 0;
  std::string_view title;
  std::vector<Unknown> unknowns;
  std::vector<std::string_view> equations;  // labels in row order, "1.1" ...
  Eigen::MatrixXd A;
  Eigen::VectorXd B;
  Eigen::VectorXd solution;
  double residual = 0;          // || A q - B ||_2
  double condition_number = 0;  // 2-norm, sigma_max / sigma_min
};

/// Evaluates and solves case `id` (1, 2 or 3) at the state. Throws Error::diverged
/// when the matrix is singular to working precision.
[[nodiscard]] CaseSolution solve_case(int id, const Params& p, const State& s);

struct SymbolicSystem {
  std::vector<std::vector<std::string>> A;  // printed entries, row by row
  std::vector<std::string> B;
};
/// The printed A and B of case `id`.
[[nodiscard]] SymbolicSystem symbolic_system(int id, expr::Style style);

/// The value of `u` in a case's solution, if the case has that unknown. Cases 2 and 3
/// also yield x2'', y2'' (and Case 3 the pin force) through the eliminated equations.
[[nodiscard]] double solution_value(const CaseSolution& solution, Unknown u, const Params& p);

}  // namespace linkage
