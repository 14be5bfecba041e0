#include "symbolic/loop_closure.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "symbolic/validate.hpp"

namespace linkage::sym {

ClosedState close_loops(const System& system, const GiNaC::exmap& state, double t) {
  ClosedState out{state, false, 0, {}};
  const SpanningTree& tree = system.tree();
  if (tree.loop_joints.empty() && system.drivers().empty()) return out;
  const Mechanism& mechanism = system.mechanism();

  // The rows closed together: the loop joints' constraints, then each driver's row at t = 0.
  std::vector<GiNaC::ex> phi;
  std::string loop_names, driver_names;
  for (int j : tree.loop_joints) {
    for (const GiNaC::ex& row : system.joints()[static_cast<std::size_t>(j)].constraints)
      phi.push_back(row.subs(system.to_generalized()));
    loop_names += (loop_names.empty() ? "" : ", ") + mechanism.joints[static_cast<std::size_t>(j)].name;
  }
  const std::size_t loop_rows = phi.size();
  for (const DriverSystem& d : system.drivers()) {
    phi.push_back(d.constraint.subs(system.to_generalized()));
    driver_names += (driver_names.empty() ? "" : ", ") + mechanism.drivers[static_cast<std::size_t>(d.index)].name;
  }
  const auto& coordinates = system.coordinates();
  std::vector<std::vector<GiNaC::ex>> jacobian(phi.size(), std::vector<GiNaC::ex>(coordinates.size()));
  for (std::size_t r = 0; r < phi.size(); ++r) {
    for (std::size_t c = 0; c < coordinates.size(); ++c) jacobian[r][c] = GiNaC::diff(phi[r], coordinates[c].symbols.q);
  }

  GiNaC::exmap constants;
  for (const auto& [symbol, expression] : system.constants())
    constants[symbol] = GiNaC::numeric(evaluate(expression, system.parameter_values()));
  for (const auto& [symbol, value] : system.parameter_values()) constants[symbol] = value;
  constants[system.time()] = t;
  // Values looked up, never substituted: GiNaC would combine the floats in a run-dependent order.
  auto value = [&](const GiNaC::ex& e) {
    GiNaC::exmap at = constants;
    for (const auto& [symbol, v] : out.state) at[symbol] = v;
    return evaluate(e, at);
  };

  // Held: the `independent` coordinates (by default the first ones the loops leave free),
  // less one for each driver: the first held one its row moves, else (it moves dependent
  // ones only) the first whose release makes the rows' Jacobian in the released ones gain rank.
  const std::size_t free_count = coordinates.size() >= loop_rows ? coordinates.size() - loop_rows : 0;
  std::vector<bool> held(coordinates.size()), driven(coordinates.size());
  for (std::size_t c = 0; c < coordinates.size(); ++c) {
    bool listed = false;
    for (const std::string& key : mechanism.independent) listed = listed || key == coordinates[c].coordinate.key;
    if (mechanism.independent.empty()) listed = c < free_count;
    held[c] = listed;
  }
  std::size_t released = 0;
  for (std::size_t r = loop_rows; r < phi.size(); ++r) {
    for (std::size_t c = 0; c < coordinates.size(); ++c) driven[c] = driven[c] || !jacobian[r][c].is_zero();
    for (std::size_t c = 0; c < coordinates.size(); ++c)
      if (held[c] && !jacobian[r][c].is_zero()) {
        held[c] = false;
        ++released;
        break;
      }
  }
  const auto rank = [&](const std::vector<bool>& kept) {
    std::vector<std::size_t> columns;
    for (std::size_t c = 0; c < coordinates.size(); ++c)
      if (!kept[c]) columns.push_back(c);
    Eigen::MatrixXd J(static_cast<Eigen::Index>(phi.size()), static_cast<Eigen::Index>(columns.size()));
    for (std::size_t r = 0; r < phi.size(); ++r)
      for (std::size_t k = 0; k < columns.size(); ++k)
        J(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k)) = value(jacobian[r][columns[k]]);
    return Eigen::FullPivLU<Eigen::MatrixXd>(J).rank();
  };
  while (released < system.drivers().size()) {
    const Eigen::Index before = rank(held);
    bool found = false;
    for (std::size_t c = 0; c < coordinates.size() && !found; ++c) {
      if (!held[c]) continue;
      std::vector<bool> trial = held;
      trial[c] = false;
      if (rank(trial) > before) {
        held = trial;
        found = true;
      }
    }
    if (!found) break;
    ++released;
  }
  std::vector<std::size_t> independent, dependent;
  for (std::size_t c = 0; c < coordinates.size(); ++c) (held[c] ? independent : dependent).push_back(c);
  const std::string what = loop_names.empty()     ? "driver " + driver_names
                           : driver_names.empty() ? "the loop through " + loop_names
                                                  : "the loop through " + loop_names + " with driver " + driver_names;
  std::string all;
  for (const auto& g : coordinates) all += (all.empty() ? "" : ", ") + g.coordinate.key;
  if (dependent.size() != phi.size()) {
    const std::size_t keep = coordinates.size() >= phi.size() ? coordinates.size() - phi.size() : 0;
    const std::string listed = std::to_string(independent.size() + released),
                      free = std::to_string(keep + system.drivers().size());
    if (system.drivers().empty())
      throw Error::input(where(mechanism.independent_pos) + "independent lists " + listed +
                         " coordinates, but the loops through " + loop_names + " leave " + free + " free; list " +
                         free + " of: " + all);
    throw Error::input(where(mechanism.independent_pos) + "independent lists " + listed + " coordinates, but " + what +
                       " leave " + free + " free, the driven ones among them; list " + free + " of: " + all);
  }

  const auto n = static_cast<Eigen::Index>(phi.size());

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
    throw Error::input(where(mechanism.independent_pos) + what + " cannot close with " +
                       (independent.empty() ? std::string("these values") : "the independent coordinates kept") +
                       (system.drivers().empty()
                            ? std::string()
                            : " and the driven ones on their motion at t = " + format_significant(t, 6)) +
                       " (constraint error " + format_significant(residual, 3) +
                       " m); valid: independent values at which the links can meet (check the lengths and the angles)");

  // Newton may land a whole turn away: keep each angle within pi of where the user put it
  // (one a driver's row moves stays where the motion puts it).
  for (std::size_t d : dependent) {
    if (coordinates[d].coordinate.kind != CoordinateKind::theta || driven[d]) continue;
    const GiNaC::symbol& q = coordinates[d].symbols.q;
    const double given = to_double(start.at(q));
    out.state[q] = GiNaC::numeric(given + std::remainder(to_double(out.state[q]) - given, 2 * std::numbers::pi));
  }

  // Rates: C_q q' = -C_t (C_t from the drivers' motion) with the independent rates kept.
  Eigen::MatrixXd Jd(n, n);
  Eigen::VectorXd rhs(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const auto row = static_cast<std::size_t>(r);
    rhs(r) = -value(GiNaC::diff(phi[row], system.time()));
    for (Eigen::Index c = 0; c < n; ++c) Jd(r, c) = value(jacobian[row][dependent[static_cast<std::size_t>(c)]]);
    for (std::size_t i : independent)
      rhs(r) -= value(jacobian[row][i]) * to_double(out.state[coordinates[i].symbols.q_dot]);
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> rate_lu(Jd);
  if (!rate_lu.isInvertible())
    throw Error::input(where(mechanism.independent_pos) + what +
                       " is at a change point (its links in line) at the independent coordinates kept, so its "
                       "rates are not determined; valid: independent values away from that position");
  const Eigen::VectorXd rates = rate_lu.solve(rhs);
  for (Eigen::Index c = 0; c < n; ++c)
    out.state[coordinates[dependent[static_cast<std::size_t>(c)]].symbols.q_dot] = GiNaC::numeric(rates(c));

  std::string moved;
  double largest_rate_change = 0;
  for (Eigen::Index c = 0; c < n; ++c) {
    const std::size_t d = dependent[static_cast<std::size_t>(c)];
    const auto& s = coordinates[d].symbols;
    const double change = std::abs(to_double(out.state[s.q]) - to_double(start.at(s.q)));
    out.largest_change = std::max(out.largest_change, change);
    const auto given_rate = start.find(s.q_dot);
    const double rate_given = given_rate == start.end() ? 0.0 : to_double(given_rate->second);
    largest_rate_change = std::max(largest_rate_change, std::abs(rates(c) - rate_given));
    moved += (moved.empty() ? "" : ", ") + coordinates[d].coordinate.key + " = " +
             format_significant(to_double(out.state[s.q]), 6);
  }
  // Without loops a note only when a driven coordinate moved: on the motion already, nothing to say.
  if (loop_names.empty() && out.largest_change == 0 && largest_rate_change == 0) return out;
  out.changed = true;
  std::string kept, placed;
  for (std::size_t i : independent) kept += (kept.empty() ? "" : ", ") + coordinates[i].coordinate.key;
  for (std::size_t c = 0; c < coordinates.size(); ++c)
    if (driven[c]) placed += (placed.empty() ? "" : ", ") + coordinates[c].coordinate.key;
  if (loop_names.empty()) {
    out.note = "Driver " + driver_names + " placed " + placed + " on its motion at t = " + format_significant(t, 6) +
               ": " + moved + " (largest change " + format_significant(out.largest_change, 3) +
               "), the rates from the motion.";
    return out;
  }
  out.note = "The loop through " + loop_names + " was closed " +
             (placed.empty() ? std::string()
                             : "with " + placed + " on driver " + driver_names +
                                   "'s motion at t = " + format_significant(t, 6) + ", ") +
             "keeping " + (kept.empty() ? "nothing" : kept) + ": " + moved + " (largest change " +
             format_significant(out.largest_change, 3) + "); the dependent rates follow from the constraints.";
  return out;
}

ClosedState checked_initial_state(const System& system) {
  validate_quantities(system);

  validate_constraints(system, system.initial_state());  // structural redundancy, before closing
  ClosedState closed = close_loops(system, system.initial_state());
  validate_constraints(system, closed.state);
  validate_meshes(system, closed.state);
  return closed;
}

}  // namespace linkage::sym
