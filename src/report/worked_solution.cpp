#include "report/worked_solution.hpp"

namespace linkage {

WorkedSolution work_out(const Inputs& inputs, const std::vector<int>& case_ids) {
  WorkedSolution w{inputs, derive(inputs.params(), inputs.state()), {}};
  for (int id : case_ids) w.cases.push_back(solve_case(id, inputs.params(), inputs.state()));
  return w;
}

}  // namespace linkage
