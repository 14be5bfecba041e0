#include "bench/general_rhs.hpp"

#include <Eigen/Core>
#include <stdexcept>
#include <vector>

#include "evaluate/mechanism_dynamics.hpp"
#include "integrate/mechanism_simulation.hpp"
#include "model/mechanism_toml.hpp"

namespace linkage::bench {

struct GeneralCase3Rhs::Shared {
  Params params;
  std::unique_ptr<sym::System> system;
  std::unique_ptr<eval::MechanismDynamics> dynamics;
  std::string evaluator;
};

GeneralCase3Rhs::GeneralCase3Rhs(const Params& p) {
  // One per Params for the process: the study runs single-threaded.
  static std::vector<std::shared_ptr<Shared>> built;
  for (const std::shared_ptr<Shared>& s : built)
    if (s->params.L == p.L && s->params.w == p.w && s->params.b == p.b && s->params.m == p.m && s->params.g == p.g) {
      shared_ = s;
      dynamics_ = s->dynamics.get();
      return;
    }
  shared_ = std::make_shared<Shared>();
  shared_->params = p;
  Mechanism mechanism = load_mechanism("two-blocks");
  for (Parameter& q : mechanism.parameters) {
    if (q.name == "L") q.value = p.L;
    if (q.name == "w") q.value = p.w;
    if (q.name == "b") q.value = p.b;
    if (q.name == "m") q.value = p.m;
    if (q.name == "g") q.value = p.g;
  }
  shared_->system = std::make_unique<sym::System>(mechanism);
  shared_->dynamics = std::make_unique<eval::MechanismDynamics>(*shared_->system, CaseId::reduced);
  if (shared_->dynamics->coordinate_names() != std::vector<std::string>{"1.x", "1.y", "1.theta", "2.theta"})
    throw std::logic_error("two-blocks.toml's Case 3 coordinates are not the closed form's");
  shared_->evaluator = choose_evaluator(*shared_->dynamics, SimulationOptions{});
  built.push_back(shared_);
  dynamics_ = shared_->dynamics.get();
}

Eigen::VectorXd GeneralCase3Rhs::state(const Vec<8>& y) const {
  if (dynamics_->state_size() != 8) throw std::logic_error("two-blocks.toml's Case 3 state is not the closed form's");
  return y;
}

const std::string& GeneralCase3Rhs::evaluator() const { return shared_->evaluator; }

}  // namespace linkage::bench
