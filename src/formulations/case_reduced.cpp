// Case 3, the generalized coordinates with the tree's joint forces eliminated; only the
// forces of loop-closing joints and the drivers' torques and forces stay unknown. From Case 2's rows, each tree force
// component f is solved from the row that holds it alone among the tree forces,
//   r = c f + rest = 0  =>  f = -rest / c,
// preferring a row where c does not depend on the state, then the row with the fewest
// accelerations (for the homework, the Newton rows of
// block 1: Fx = m x1'', Fy = m (y1'' + g)), and substituted into every other row; that
// row leaves the system. What remains is, for each tree joint, the moment about it of
// everything beyond it, and for a floating base its total force (the homework's (1.3) to
// (4.3)). A coefficient c that depends on the state is not divided by: the other rows
// combine as c r_k - (coefficient of f in r_k) r.
#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "formulations/case_system.hpp"

namespace linkage {

namespace {

// The coordinates, lengths and rates: a coefficient holding one depends on the state.
GiNaC::exset state_symbols(const sym::SymbolTable& table) {
  GiNaC::exset out;
  for (const sym::SymbolInfo& info : table.all())
    if (info.role == sym::Role::coordinate || info.role == sym::Role::length || info.role == sym::Role::rate)
      out.insert(info.symbol);
  return out;
}

GiNaC::exset symbols_in(const GiNaC::ex& e) {
  GiNaC::exset out;
  for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i)
    if (GiNaC::is_a<GiNaC::symbol>(*i)) out.insert(*i);
  return out;
}

bool depends_on_state(const GiNaC::ex& e, const GiNaC::exset& state) {
  for (const GiNaC::ex& s : symbols_in(e))
    if (state.count(s) != 0) return true;
  return false;
}

// What the choice of a pivot needs to know of one row, from one pass over its symbols
// (the rows are expanded and linear in the forces and accelerations, so a symbol that
// occurs has a non-zero coefficient): the tree forces it holds (indices into the forces
// to eliminate) and how many accelerations.
struct RowContent {
  std::vector<std::size_t> forces;
  std::size_t accelerations = 0;
  std::optional<std::size_t> score;  // of the row as a pivot, once asked for
};

}  // namespace

CaseSystem reduced_case(const sym::System& system) {
  GeneralizedRows g = generalized_rows(system);
  std::vector<GiNaC::ex>& rows = g.rows;
  std::vector<GiNaC::symbol> eliminate;
  for (const sym::JointSystem& j : system.joints())
    if (j.in_tree)
      for (const GiNaC::symbol& u : j.unknowns) eliminate.push_back(u);
  std::vector<GiNaC::symbol> accelerations;
  for (const sym::GeneralizedCoordinate& c : system.coordinates()) accelerations.push_back(c.symbols.q_ddot);

  const GiNaC::exset state = state_symbols(system.table());
  std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> force_index;
  for (std::size_t i = 0; i < eliminate.size(); ++i) force_index[eliminate[i]] = i;
  GiNaC::exset acceleration_set(accelerations.begin(), accelerations.end());
  std::vector<RowContent> content(rows.size());
  auto scan = [&](std::size_t r) {
    RowContent c;
    for (const GiNaC::ex& s : symbols_in(rows[r])) {
      if (const auto it = force_index.find(s); it != force_index.end()) c.forces.push_back(it->second);
      if (acceleration_set.count(s) != 0) ++c.accelerations;
    }
    content[r] = std::move(c);
  };
  for (std::size_t r = 0; r < rows.size(); ++r) scan(r);

  std::vector<bool> used(rows.size(), false);
  std::vector<Recovered> forces;
  for (std::size_t left = eliminate.size(); left > 0; --left) {
    throw_if_interrupted();
    // The row holding one force alone with the lowest score: a constant coefficient
    // first (dividing by it is always safe), then the fewest accelerations; ties to the
    // force first in joint order, then the first row.
    std::size_t best_force = 0, best_row = rows.size();
    std::size_t best_score = static_cast<std::size_t>(-1);
    for (std::size_t ri = 0; ri < rows.size(); ++ri) {
      RowContent& c = content[ri];
      if (used[ri] || c.forces.size() != 1) continue;
      const std::size_t fi = c.forces[0];
      if (!c.score) c.score = (depends_on_state(rows[ri].coeff(eliminate[fi], 1), state) ? 1000 : 0) + c.accelerations;
      if (*c.score < best_score || (*c.score == best_score && fi < best_force)) {
        best_score = *c.score;
        best_force = fi;
        best_row = ri;
      }
    }
    if (best_row == rows.size())
      throw Error::input(system.mechanism().source + ": the tree's joint forces cannot be eliminated one by one");
    const GiNaC::symbol f = eliminate[best_force];
    const GiNaC::ex pivot = rows[best_row];
    const GiNaC::ex c = pivot.coeff(f, 1);
    const GiNaC::ex rest = GiNaC::expand(pivot - c * f);
    const bool divide = !depends_on_state(c, state);
    const GiNaC::ex value = GiNaC::expand(-rest / c);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (k == best_row || used[k]) continue;
      const std::vector<std::size_t>& held = content[k].forces;
      if (std::find(held.begin(), held.end(), best_force) == held.end()) continue;
      const GiNaC::ex ck = rows[k].coeff(f, 1);
      rows[k] =
          divide ? GiNaC::expand(rows[k].subs(GiNaC::exmap{{f, value}})) : GiNaC::expand(c * rows[k] - ck * pivot);
      scan(k);
    }
    used[best_row] = true;
    forces.push_back({f, divide ? value : GiNaC::ex(-rest / c)});
  }

  std::vector<GiNaC::ex> kept;
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (!used[r]) kept.push_back(rows[r]);
  std::vector<GiNaC::symbol> unknowns = accelerations;
  for (const sym::JointSystem& j : system.joints())
    if (!j.in_tree)
      for (const GiNaC::symbol& u : j.unknowns) unknowns.push_back(u);
  for (const sym::DriverSystem& d : system.drivers()) unknowns.push_back(d.unknown);

  CaseSystem out = linear_system(CaseId::reduced, kept, unknowns);
  out.recovered = std::move(g.recovered);
  for (Recovered& r : forces) out.recovered.push_back(std::move(r));
  const bool loops = !system.tree().loop_joints.empty();
  out.title = count_word(kept.size()) + " equations in generalized coordinates, " +
              (loops                               ? "only loop-closing forces"
               : system.mechanism().joints.empty() ? std::string("no joints")
                                                   : "no " + force_phrase(system));
  if (!system.drivers().empty()) out.title += loops ? " and drivers" : ", drivers kept";
  return out;
}

}  // namespace linkage
