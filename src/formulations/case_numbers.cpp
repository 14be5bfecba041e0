#include "formulations/case_numbers.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/number_format.hpp"

namespace linkage {

double value_at(const GiNaC::ex& e, const GiNaC::exmap& values) { return sym::evaluate(e, values); }

void require_finite(const std::string& name, double value) {
  if (std::isnan(value))
    throw Error::input(name + " is not a number in double precision (an overflow, or zero over zero)");
  if (!std::isfinite(value)) throw Error::input(name + " = " + format_roundtrip(value) + " overflows double precision");
}

namespace {

GiNaC::numeric finite_number(const sym::System& system, const GiNaC::ex& symbol, double value) {
  const sym::SymbolInfo* info = system.table().find(GiNaC::ex_to<GiNaC::symbol>(symbol));
  require_finite(info != nullptr ? info->ascii : GiNaC::ex_to<GiNaC::symbol>(symbol).get_name(), value);
  return GiNaC::numeric(value);
}

}  // namespace

GiNaC::exmap state_values(const sym::System& system, const GiNaC::exmap& state, double time) {
  GiNaC::exmap values = system.parameter_values();
  for (const auto& [symbol, expression] : system.constants())
    values[symbol] = finite_number(system, symbol, sym::evaluate(expression, system.parameter_values()));
  for (const auto& [symbol, value] : state) values[symbol] = value;
  values[system.time()] = GiNaC::numeric(time);
  // Maximal positions and rates from the generalized state (accelerations stay unknown).
  for (const auto& [symbol, expression] : system.to_generalized()) {
    const sym::SymbolInfo* info = system.table().find(GiNaC::ex_to<GiNaC::symbol>(symbol));
    if (info == nullptr || info->role == sym::Role::acceleration) continue;
    values[symbol] = finite_number(system, symbol, sym::evaluate(expression, values));
  }
  for (const auto& [symbol, expression] : system.lengths()) {
    values[symbol] = finite_number(system, symbol, sym::evaluate(expression, values));
    if (values[symbol].is_zero()) {
      const std::string& key = system.table().find(GiNaC::ex_to<GiNaC::symbol>(symbol))->key;
      throw Error::input("spring " + key.substr(0, key.rfind('.')) +
                         " has length 0 at this state: its two points coincide and its direction is undefined; "
                         "valid: a state with its ends apart");
    }
  }
  return values;
}

namespace {

GiNaC::exset symbols_in(const GiNaC::ex& e) {
  GiNaC::exset out;
  for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i)
    if (GiNaC::is_a<GiNaC::symbol>(*i)) out.insert(*i);
  return out;
}

}  // namespace

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
      // A recovered force may use forces recovered before it (those it holds: a long
      // chain recovers hundreds, and most values hold none).
      GiNaC::ex e = r.value;
      GiNaC::exset held = symbols_in(e);
      for (const Recovered& earlier : c.recovered) {
        if (&earlier == &r) break;
        if (held.count(earlier.symbol) == 0) continue;
        e = e.subs(GiNaC::exmap{{earlier.symbol, earlier.value}});
        held = symbols_in(e);
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
  // Divide and conquer: Jacobi's sweeps took seconds, with no signal check, for a long
  // chain's Case 1 (500 unknowns for 100 links); below 16 columns it is Jacobi's.
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(out.A);
  const auto& sigma = svd.singularValues();
  const double smallest = sigma.size() > 0 ? sigma[sigma.size() - 1] : 0;
  out.condition = smallest > 0 ? sigma[0] / smallest : std::numeric_limits<double>::infinity();
  if (rows != cols || !(smallest > sigma[0] * 64 * std::numeric_limits<double>::epsilon()))
    throw Error::input(
        name + " is singular at this state (condition number " +
        (std::isfinite(out.condition) ? format_significant(out.condition, 3) : std::string("infinite")) +
        "): the mechanism is at a dead point or change point, a constraint is redundant, or its sizes are too far "
        "apart for double precision; valid: a state where the links are not aligned, sizes within a few decades");
  out.solution = out.A.fullPivLu().solve(out.B);
  out.residual = (out.A * out.solution - out.B).stableNorm();  // no overflow of the squares
  return out;
}

}  // namespace linkage
