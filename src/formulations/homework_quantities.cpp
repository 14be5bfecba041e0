#include "formulations/homework_quantities.hpp"

#include <numbers>

#include "formulations/formulation.hpp"
#include "model/kinematics.hpp"

namespace linkage {

std::optional<std::size_t> find_quantity(std::string_view name) {
  for (std::size_t i = 0; i < kQuantities.size(); ++i)
    if (kQuantities[i].name == name) return i;
  return std::nullopt;
}

QuantityValues evaluate_quantities(const Inputs& inputs) {
  const Params& p = inputs.params();
  const State& s = inputs.state();
  const Derived d = derive(p, s);
  const CaseSolution case1 = solve_case(1, p, s);
  const CaseSolution case2 = solve_case(2, p, s);
  const CaseSolution case3 = solve_case(3, p, s);
  auto q = [&](Unknown u) { return solution_value(case1, u, p); };

  QuantityValues v{};
  std::size_t i = 0;
  for (const InputKey& key : kInputKeys) v[i++] = inputs.value(key);
  const double values[] = {d.I_zz_C,
                           d.D,
                           d.I_zz_P,
                           d.pin.x(),
                           d.pin.y(),
                           d.C2.x(),
                           d.C2.y(),
                           d.C2_dot.x(),
                           d.C2_dot.y(),
                           (s.x1 + d.C2.x()) / 2,
                           (s.y1 + d.C2.y()) / 2,
                           (s.x1_dot + d.C2_dot.x()) / 2,
                           (s.y1_dot + d.C2_dot.y()) / 2,
                           d.invariants.kinetic_energy,
                           d.invariants.potential_energy,
                           d.invariants.energy,
                           d.invariants.momentum.x(),
                           d.invariants.momentum.y(),
                           d.invariants.angular_momentum,
                           q(Unknown::x1_ddot),
                           q(Unknown::y1_ddot),
                           q(Unknown::theta1_ddot),
                           q(Unknown::x2_ddot),
                           q(Unknown::y2_ddot),
                           q(Unknown::theta2_ddot),
                           q(Unknown::F_x),
                           q(Unknown::F_y),
                           case1.condition_number,
                           case2.condition_number,
                           case3.condition_number,
                           case1.residual,
                           std::numbers::pi};
  static_assert(kInputKeys.size() + sizeof(values) / sizeof(values[0]) == kQuantities.size(),
                "one value per quantity, in table order");
  for (double x : values) v[i++] = x;
  return v;
}

}  // namespace linkage
