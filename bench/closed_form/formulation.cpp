#include "bench/closed_form/formulation.hpp"

#include <Eigen/SVD>

#include "bench/closed_form/case1.hpp"
#include "bench/closed_form/case2.hpp"
#include "bench/closed_form/case3.hpp"
#include "bench/closed_form/linear_solve.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"

namespace linkage {
namespace {

template <class Case>
CaseSolution solve_typed(const Params& p, const State& s) {
  const expr::Env env = make_env(p, s.theta1, s.theta2, s.theta1_dot, s.theta2_dot);
  const LinearSystem<Case> system = assemble<Case>(env);
  CaseSolution out;
  out.id = Case::id;
  out.title = Case::title;
  out.unknowns.assign(Case::unknowns.begin(), Case::unknowns.end());
  out.equations.assign(Case::equations.begin(), Case::equations.end());
  out.A = system.A;
  out.B = system.B;

  const Eigen::JacobiSVD<Mat<Case::size>> svd(system.A);
  const auto& sigma = svd.singularValues();
  out.condition_number =
      sigma[Case::size - 1] > 0 ? sigma[0] / sigma[Case::size - 1] : std::numeric_limits<double>::infinity();
  Vec<Case::size> q;
  // Singular means the elimination breaks down. A large condition number alone is not
  // singular: Case 2's m and 1/m rows make it large for extreme masses while the block
  // solve stays accurate.
  if (!solve_blocks<Case>(system.A, system.B, q))
    throw Error::diverged("the Case " + std::to_string(Case::id) +
                          " matrix is singular to working precision (condition number " +
                          format_significant(out.condition_number, 3) + ") at theta1 = " + format_roundtrip(s.theta1) +
                          ", theta2 = " + format_roundtrip(s.theta2) + "; check m, w and L");
  out.solution = q;
  out.residual = (system.A * q - system.B).norm();
  return out;
}

}  // namespace

CaseSolution solve_case(int id, const Params& p, const State& s) {
  switch (id) {
    case 1:
      return solve_typed<Case1>(p, s);
    case 2:
      return solve_typed<Case2>(p, s);
    case 3:
      return solve_typed<Case3>(p, s);
    default:
      throw Error::input("case " + std::to_string(id) + " does not exist; valid cases: 1, 2, 3");
  }
}

double solution_value(const CaseSolution& solution, Unknown u, const Params& p) {
  for (std::size_t i = 0; i < solution.unknowns.size(); ++i)
    if (solution.unknowns[i] == u) return solution.solution[static_cast<Eigen::Index>(i)];
  auto get = [&](Unknown v) { return solution_value(solution, v, p); };
  switch (u) {
    case Unknown::F_x:
      return p.m * get(Unknown::x1_ddot);  // (1.2)
    case Unknown::F_y:
      return p.m * (get(Unknown::y1_ddot) + p.g);  // (2.2)
    case Unknown::x2_ddot:
      return -get(Unknown::F_x) / p.m;  // (4.1)
    case Unknown::y2_ddot:
      return -p.g - get(Unknown::F_y) / p.m;  // (5.1)
    case Unknown::x1_ddot:
    case Unknown::y1_ddot:
    case Unknown::theta1_ddot:
    case Unknown::theta2_ddot:
      break;  // every case solves for these
  }
  throw Error::failure("unknown missing from a case's solution");
}

}  // namespace linkage
