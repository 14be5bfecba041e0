#pragma once
// Everything `linkage solve` shows, computed once and printed by each format.
#include <vector>

#include "formulations/formulation.hpp"
#include "model/inputs.hpp"
#include "model/kinematics.hpp"

namespace linkage {

struct WorkedSolution {
  Inputs inputs;
  Derived derived;
  std::vector<CaseSolution> cases;  // in the order asked
};

/// Solves the selected cases (each id in 1..3) at the inputs.
[[nodiscard]] WorkedSolution work_out(const Inputs& inputs, const std::vector<int>& case_ids);

}  // namespace linkage
