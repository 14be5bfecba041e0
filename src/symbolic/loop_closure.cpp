#include "symbolic/loop_closure.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "symbolic/validate.hpp"

namespace linkage::sym {

ClosedState close_loops(const System& system, const GiNaC::exmap& state) {
  ClosedState out{state, false, 0, {}};
  const SpanningTree& tree = system.tree();
  if (tree.loop_joints.empty()) return out;
  const Mechanism& mechanism = system.mechanism();

  std::vector<GiNaC::ex> phi;
  std::string loop_names;
  for (int j : tree.loop_joints) {
    for (const GiNaC::ex& row : system.joints()[static_cast<std::size_t>(j)].constraints)
      phi.push_back(row.subs(system.to_generalized()));
    loop_names += (loop_names.empty() ? "" : ", ") + mechanism.joints[static_cast<std::size_t>(j)].name;
  }
  const auto& coordinates = system.coordinates();
  std::vector<std::size_t> independent, dependent;
  const std::size_t free_count = coordinates.size() >= phi.size() ? coordinates.size() - phi.size() : 0;
  for (std::size_t c = 0; c < coordinates.size(); ++c) {
    bool listed = false;
    for (const std::string& key : mechanism.independent) listed = listed || key == coordinates[c].coordinate.key;
    if (mechanism.independent.empty()) listed = c < free_count;
    (listed ? independent : dependent).push_back(c);
  }
  std::string all;
  for (const auto& g : coordinates) all += (all.empty() ? "" : ", ") + g.coordinate.key;
  if (dependent.size() != phi.size())
    throw Error::input(where(mechanism.independent_pos) + "independent lists " + std::to_string(independent.size()) +
                       " coordinates, but the loops through " + loop_names + " leave " + std::to_string(free_count) +
                       " free; list " + std::to_string(free_count) + " of: " + all);

  GiNaC::exmap constants;
  for (const auto& [symbol, expression] : system.constants())
    constants[symbol] = GiNaC::numeric(evaluate(expression, system.parameter_values()));
  for (const auto& [symbol, value] : system.parameter_values()) constants[symbol] = value;
  const auto n = static_cast<Eigen::Index>(phi.size());
  std::vector<std::vector<GiNaC::ex>> jacobian(phi.size(), std::vector<GiNaC::ex>(coordinates.size()));
  for (std::size_t r = 0; r < phi.size(); ++r) {
    for (std::size_t c = 0; c < coordinates.size(); ++c) jacobian[r][c] = GiNaC::diff(phi[r], coordinates[c].symbols.q);
  }
  // Values looked up, never substituted: GiNaC would combine the floats in a run-dependent order.
  auto value = [&](const GiNaC::ex& e) {
    GiNaC::exmap at = constants;
    for (const auto& [symbol, v] : out.state) at[symbol] = v;
    return evaluate(e, at);
  };

  const GiNaC::exmap start = state;
  double residual = 0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::VectorXd f(n);
    Eigen::MatrixXd J(n, n);
    for (Eigen::Index r = 0; r < n; ++r) {
      f(r) = value(phi[static_cast<std::size_t>(r)]);
      for (Eigen::Index c = 0; c < n; ++c)
        J(r, c) = value(jacobian[static_cast<std::size_t>(r)][dependent[static_cast<std::size_t>(c)]]);
    }
    residual = f.norm();
    if (!std::isfinite(residual)) break;
    if (residual < 1e-14) break;
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
    if (!lu.isInvertible()) {
      residual = std::numeric_limits<double>::infinity();
      break;
    }
    const Eigen::VectorXd step = lu.solve(f);
    for (Eigen::Index c = 0; c < n; ++c) {
      const GiNaC::symbol& q = coordinates[dependent[static_cast<std::size_t>(c)]].symbols.q;
      out.state[q] = GiNaC::numeric(to_double(out.state[q]) - step(c));
    }
  }
  if (!(residual < 1e-10))
    throw Error::input(where(mechanism.independent_pos) + "the loop through " + loop_names + " cannot close with " +
                       (independent.empty() ? std::string("these values") : "the independent coordinates kept") +
                       " (constraint error " + format_significant(residual, 3) +
                       " m); valid: independent values at which the links can meet (check the lengths and the angles)");

  // Newton may land a whole turn away: keep each angle within pi of where the user put it.
  for (std::size_t d : dependent) {
    if (coordinates[d].coordinate.kind != CoordinateKind::theta) continue;
    const GiNaC::symbol& q = coordinates[d].symbols.q;
    const double given = to_double(start.at(q));
    out.state[q] = GiNaC::numeric(given + std::remainder(to_double(out.state[q]) - given, 2 * std::numbers::pi));
  }

  // Rates: Phi_q q' = 0 with the independent rates kept.
  Eigen::MatrixXd Jd(n, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    for (Eigen::Index c = 0; c < n; ++c)
      Jd(r, c) = value(jacobian[static_cast<std::size_t>(r)][dependent[static_cast<std::size_t>(c)]]);
    for (std::size_t i : independent)
      rhs(r) -= value(jacobian[static_cast<std::size_t>(r)][i]) * to_double(out.state[coordinates[i].symbols.q_dot]);
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> rate_lu(Jd);
  if (!rate_lu.isInvertible())
    throw Error::input(where(mechanism.independent_pos) + "the loop through " + loop_names +
                       " is at a change point (its links in line) at the independent coordinates kept, so its "
                       "rates are not determined; valid: independent values away from that position");
  const Eigen::VectorXd rates = rate_lu.solve(rhs);
  for (Eigen::Index c = 0; c < n; ++c)
    out.state[coordinates[dependent[static_cast<std::size_t>(c)]].symbols.q_dot] = GiNaC::numeric(rates(c));

  std::string moved;
  for (std::size_t d : dependent) {
    const auto& s = coordinates[d].symbols;
    const double change = std::abs(to_double(out.state[s.q]) - to_double(start.at(s.q)));
    out.largest_change = std::max(out.largest_change, change);
    moved += (moved.empty() ? "" : ", ") + coordinates[d].coordinate.key + " = " +
             format_significant(to_double(out.state[s.q]), 6);
  }
  out.changed = true;
  std::string kept;
  for (std::size_t i : independent) kept += (kept.empty() ? "" : ", ") + coordinates[i].coordinate.key;
  out.note = "The loop through " + loop_names + " was closed keeping " + (kept.empty() ? "nothing" : kept) + ": " +
             moved + " (largest change " + format_significant(out.largest_change, 3) +
             "); the dependent rates follow from the constraints.";
  return out;
}

ClosedState checked_initial_state(const System& system) {
  validate_quantities(system);

  validate_constraints(system, system.initial_state());  // structural redundancy, before closing
  ClosedState closed = close_loops(system, system.initial_state());
  validate_constraints(system, closed.state);
  require_on_the_motion(system, closed.state);
  return closed;
}

void require_on_the_motion(const System& system, const GiNaC::exmap& state) {
  if (system.drivers().empty()) return;
  GiNaC::exmap at = system.parameter_values();
  // Definitions by their expressions (evaluate() evaluates a value in turn): a value out of
  // double range is then named by the finiteness checks, never made a CLN number here.
  for (const auto& [symbol, expression] : system.constants()) at[symbol] = expression;
  for (const auto& [symbol, value] : state) at[symbol] = value;
  at[system.time()] = 0;
  for (const DriverSystem& d : system.drivers()) {
    const Driver& driver = system.mechanism().drivers[static_cast<std::size_t>(d.index)];
    const GiNaC::ex motion = system.quantity(driver.motion, true);
    const GiNaC::ex driven = (d.constraint + motion).subs(system.to_generalized());
    const double value = evaluate(driven, at), rate = evaluate(system.time_derivative(driven), at);
    const double wanted = evaluate(motion, at), wanted_rate = evaluate(motion.diff(system.time()), at);
    if (std::abs(value - wanted) <= 1e-9 && std::abs(rate - wanted_rate) <= 1e-9) continue;
    throw Error::input(where(driver.pos) + "driver '" + driver.name + "': [initial] puts joint '" + driver.joint +
                       "' at " + format_significant(value, 9) + " moving at " + format_significant(rate, 9) +
                       ", its motion at t = 0 at " + format_significant(wanted, 9) + " moving at " +
                       format_significant(wanted_rate, 9) +
                       "; valid for now: [initial] on the motion at t = 0 (placing it there is the next step)");
  }
}

}  // namespace linkage::sym
