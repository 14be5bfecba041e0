#include "evaluate/case_evaluator.hpp"

#include <stdexcept>

#include "evaluate/substitute.hpp"

namespace linkage::eval {

CaseEvaluator::CaseEvaluator(const sym::System& system, const CaseSystem& c)
    : rows_(c.A.size()), cols_(c.unknowns.size()) {
  // The parameters in file order (the symbol table's), not parameter_values()'s map order.
  for (const sym::SymbolInfo& info : system.table().all())
    if (info.role == sym::Role::parameter) inputs_.push_back(info.symbol);
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    inputs_.push_back(g.symbols.q);
    inputs_.push_back(g.symbols.q_dot);
  }
  inputs_.push_back(system.time());

  // Maximal positions and rates in the generalized ones (accelerations are unknowns).
  GiNaC::exmap maximal;
  for (const auto& [symbol, expression] : system.to_generalized()) {
    const sym::SymbolInfo* info = system.table().find(GiNaC::ex_to<GiNaC::symbol>(symbol));
    if (info != nullptr && info->role != sym::Role::acceleration) maximal[symbol] = expression;
  }
  std::vector<GiNaC::ex> outputs;
  // Expanded: GiNaC may build equal entries in differently nested forms from run to run
  // (its term order follows address-dependent hashes); the expanded form is one.
  auto prepare = [&](const GiNaC::ex& e) {
    return substitute_in_turn(e, {&system.lengths(), &maximal, &system.constants(), &system.constants()}, true);
  };
  for (const auto& row : c.A)
    for (const GiNaC::ex& e : row) outputs.push_back(prepare(e));
  for (const GiNaC::ex& e : c.B) outputs.push_back(prepare(e));
  program_ = compile(outputs, inputs_);
  outputs_.resize(outputs.size());
  free_checking(outputs);
  scratch_.resize(program_.scratch_size());
}

std::vector<double> CaseEvaluator::inputs(const GiNaC::exmap& values) const {
  std::vector<double> out;
  out.reserve(inputs_.size());
  for (const GiNaC::symbol& s : inputs_) {
    const auto it = values.find(s);
    if (it == values.end()) throw std::logic_error("no value for the input " + s.get_name());
    out.push_back(sym::to_double(it->second));
  }
  return out;
}

void CaseEvaluator::evaluate(const std::vector<double>& inputs, Eigen::MatrixXd& A, Eigen::VectorXd& B) const {
  program_.run(inputs.data(), outputs_.data(), scratch_.data());
  A.resize(static_cast<Eigen::Index>(rows_), static_cast<Eigen::Index>(cols_));
  B.resize(static_cast<Eigen::Index>(rows_));
  std::size_t k = 0;
  for (std::size_t i = 0; i < rows_; ++i)
    for (std::size_t j = 0; j < cols_; ++j)
      A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = outputs_[k++];
  for (std::size_t i = 0; i < rows_; ++i) B(static_cast<Eigen::Index>(i)) = outputs_[k++];
}

double CaseEvaluator::solve(const std::vector<double>& inputs, Eigen::VectorXd& unknowns) const {
  evaluate(inputs, A_, B_);
  lu_.compute(A_);
  const double rcond = lu_.rcond();
  if (!(rcond > 0)) return 0;  // NaN entries count as singular
  unknowns = lu_.solve(B_);
  return rcond;
}

}  // namespace linkage::eval
