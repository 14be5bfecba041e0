#pragma once
// The homework's closed-form cases behind one runtime interface: `solve_case` evaluates
// and solves a case at a state from the definitions in case1/2/3.hpp (the bench's
// stress study uses it; bench/tests/general_cases_test.cpp holds the general procedure
// to it).
#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "bench/closed_form/expr.hpp"
#include "bench/closed_form/params.hpp"
#include "bench/closed_form/state.hpp"
#include "bench/closed_form/unknowns.hpp"

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

/// The value of `u` in a case's solution, if the case has that unknown. Cases 2 and 3
/// also yield x2'', y2'' (and Case 3 the pin force) through the eliminated equations.
[[nodiscard]] double solution_value(const CaseSolution& solution, Unknown u, const Params& p);

}  // namespace linkage
