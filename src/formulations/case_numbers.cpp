#include "formulations/case_numbers.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/number_format.hpp"

namespace linkage {

double value_at(const GiNaC::ex& e, const GiNaC::exmap& values) { return sym::to_double(e.subs(values)); }

GiNaC::exmap state_values(const sym::System& system, const GiNaC::exmap& state, double time) {
  GiNaC::exmap values = system.parameter_values();
  for (const auto& [symbol, expression] : system.constants())
    values[symbol] = GiNaC::evalf(expression.subs(system.parameter_values()));
  for (const auto& [symbol, value] : state) values[symbol] = value;
  values[system.time()] = GiNaC::numeric(time);
  // Maximal positions and rates from the generalized state (accelerations stay unknown).
  for (const auto& [symbol, expression] : system.to_generalized()) {
    const sym::SymbolInfo* info = system.table().find(GiNaC::ex_to<GiNaC::symbol>(symbol));
    if (info == nullptr || info->role == sym::Role::acceleration) continue;
    values[symbol] = GiNaC::evalf(expression.subs(values));
  }
  return values;
}

std::optional<double> case_value(const CaseSystem& c, const CaseNumbers& numbers, const GiNaC::exmap& values,
                                 const GiNaC::symbol& u, bool* recovered) {
  for (std::size_t j = 0; j < c.unknowns.size(); ++j)
    if (c.unknowns[j].is_equal(u)) {
      if (recovered != nullptr) *recovered = false;
      return numbers.solution(static_cast<Eigen::Index>(j));
    }
  for (const Recovered& r : c.recovered)
    if (r.symbol.is_equal(u)) {
      GiNaC::exmap with_solution = values;
      for (std::size_t j = 0; j < c.unknowns.size(); ++j)
        with_solution[c.unknowns[j]] = GiNaC::numeric(numbers.solution(static_cast<Eigen::Index>(j)));
      // A recovered force may use forces recovered before it.
      GiNaC::ex e = r.value;
      for (const Recovered& earlier : c.recovered) {
        if (&earlier == &r) break;
        e = e.subs(GiNaC::exmap{{earlier.symbol, earlier.value}});
      }
      if (recovered != nullptr) *recovered = true;
      return value_at(e, with_solution);
    }
  return std::nullopt;
}

CaseNumbers solve_numbers(const CaseSystem& c, const GiNaC::exmap& values) {
  const auto rows = static_cast<Eigen::Index>(c.A.size());
  const auto cols = static_cast<Eigen::Index>(c.unknowns.size());
  Eigen::MatrixXd A(rows, cols);
  Eigen::VectorXd B(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index j = 0; j < cols; ++j)
      A(i, j) = value_at(c.A[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], values);
    B(i) = value_at(c.B[static_cast<std::size_t>(i)], values);
  }
  return solve_matrices(c.id, std::move(A), std::move(B));
}

CaseNumbers solve_matrices(CaseId id, Eigen::MatrixXd A, Eigen::VectorXd B) {
  CaseNumbers out;
  out.A = std::move(A);
  out.B = std::move(B);
  const Eigen::Index rows = out.A.rows(), cols = out.A.cols();
  const std::string name = "the Case " + std::to_string(case_number(id)) + " matrix";
  if (!out.A.allFinite() || !out.B.allFinite())
    throw Error::input(name +
                       " has an entry that is not finite at this state: a parameter or the state makes a "
                       "quantity overflow or divide by zero");
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(out.A);
  const auto& sigma = svd.singularValues();
  const double smallest = sigma.size() > 0 ? sigma[sigma.size() - 1] : 0;
  out.condition = smallest > 0 ? sigma[0] / smallest : std::numeric_limits<double>::infinity();
  if (rows != cols || !(smallest > sigma[0] * 64 * std::numeric_limits<double>::epsilon()))
    throw Error::input(
        name + " is singular at this state (condition number " +
        (std::isfinite(out.condition) ? format_significant(out.condition, 3) : std::string("infinite")) +
        "): the mechanism is at a dead point or change point, or a constraint is redundant; valid: a state where "
        "the links are not aligned");
  out.solution = out.A.fullPivLu().solve(out.B);
  out.residual = (out.A * out.solution - out.B).norm();
  return out;
}

}  // namespace linkage
