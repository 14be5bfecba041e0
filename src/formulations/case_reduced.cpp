// Case 3, the generalized coordinates with the tree's joint forces eliminated; only the
// forces of loop-closing joints stay unknown. From Case 2's rows, each tree force
// component f is solved from the row that holds it alone among the tree forces,
//   r = c f + rest = 0  =>  f = -rest / c,
// preferring a row where c does not depend on the state, then the row with the fewest
// accelerations (for the homework, the Newton rows of
// block 1: Fx = m x1'', Fy = m (y1'' + g)), and substituted into every other row; that
// row leaves the system. What remains is, for each tree joint, the moment about it of
// everything beyond it, and for a floating base its total force (the homework's (1.3) to
// (4.3)). A coefficient c that depends on the state is not divided by: the other rows
// combine as c r_k - (coefficient of f in r_k) r.
#include <stdexcept>

#include "core/error.hpp"
#include "formulations/case_system.hpp"

namespace linkage {

namespace {

bool depends_on_state(const GiNaC::ex& e, const sym::SymbolTable& table) {
  for (const sym::SymbolInfo& info : table.all())
    if ((info.role == sym::Role::coordinate || info.role == sym::Role::length || info.role == sym::Role::rate) &&
        e.has(info.symbol))
      return true;
  return false;
}

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

  std::vector<bool> used(rows.size(), false);
  std::vector<Recovered> forces;
  std::vector<GiNaC::symbol> remaining = eliminate;
  while (!remaining.empty()) {
    std::size_t best_component = 0, best_row = rows.size();
    std::size_t best_score = static_cast<std::size_t>(-1);
    for (std::size_t ci = 0; ci < remaining.size(); ++ci)
      for (std::size_t ri = 0; ri < rows.size(); ++ri) {
        if (used[ri] || rows[ri].coeff(remaining[ci], 1).is_zero()) continue;
        bool alone = true;
        for (std::size_t other = 0; other < remaining.size(); ++other)
          alone = alone && (other == ci || rows[ri].coeff(remaining[other], 1).is_zero());
        if (!alone) continue;
        // A constant coefficient first (dividing by it is always safe), then the fewest accelerations.
        std::size_t score = depends_on_state(rows[ri].coeff(remaining[ci], 1), system.table()) ? 1000 : 0;
        for (const GiNaC::symbol& a : accelerations) score += rows[ri].coeff(a, 1).is_zero() ? 0 : 1;
        if (score < best_score) {
          best_score = score;
          best_component = ci;
          best_row = ri;
        }
      }
    if (best_row == rows.size())
      throw Error::input(system.mechanism().source + ": the tree's joint forces cannot be eliminated one by one");
    const GiNaC::symbol f = remaining[best_component];
    const GiNaC::ex pivot = rows[best_row];
    const GiNaC::ex c = pivot.coeff(f, 1);
    const GiNaC::ex rest = GiNaC::expand(pivot - c * f);
    const bool divide = !depends_on_state(c, system.table());
    const GiNaC::ex value = GiNaC::expand(-rest / c);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (k == best_row || used[k]) continue;
      const GiNaC::ex ck = rows[k].coeff(f, 1);
      if (ck.is_zero()) continue;
      rows[k] =
          divide ? GiNaC::expand(rows[k].subs(GiNaC::exmap{{f, value}})) : GiNaC::expand(c * rows[k] - ck * pivot);
    }
    used[best_row] = true;
    forces.push_back({f, divide ? value : GiNaC::ex(-rest / c)});
    remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(best_component));
  }

  std::vector<GiNaC::ex> kept;
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (!used[r]) kept.push_back(rows[r]);
  std::vector<GiNaC::symbol> unknowns = accelerations;
  for (const sym::JointSystem& j : system.joints())
    if (!j.in_tree)
      for (const GiNaC::symbol& u : j.unknowns) unknowns.push_back(u);

  CaseSystem out = linear_system(CaseId::reduced, kept, unknowns);
  out.recovered = std::move(g.recovered);
  for (Recovered& r : forces) out.recovered.push_back(std::move(r));
  const bool loops = unknowns.size() > accelerations.size();
  out.title = count_word(kept.size()) + " equations in generalized coordinates, " +
              (loops                               ? "only loop-closing forces"
               : system.mechanism().joints.empty() ? std::string("no joints")
                                                   : "no " + force_phrase(system));
  return out;
}

}  // namespace linkage
