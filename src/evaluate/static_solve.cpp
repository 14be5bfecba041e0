#include "evaluate/static_solve.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <tuple>

#include "symbolic/system.hpp"

namespace linkage::eval {
namespace {

using GiNaC::ex;

bool depends_on(const ex& v, const std::vector<GiNaC::symbol>& state) {
  for (const GiNaC::symbol& s : state)
    if (v.has(s)) return true;
  return false;
}

// A name for a state-independent factor that is the same on every run and machine (GiNaC's
// own order of terms is not): its value with each symbol set to a number made from the
// symbol's name, to 12 digits. Distinct factors of one system collide with no real chance.
std::string canonical_key(const ex& factor) {
  GiNaC::exmap probe;
  for (auto it = factor.preorder_begin(); it != factor.preorder_end(); ++it)
    if (GiNaC::is_a<GiNaC::symbol>(*it)) {
      std::uint64_t h = 0xcbf29ce484222325ULL;
      for (const char c : GiNaC::ex_to<GiNaC::symbol>(*it).get_name())
        h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
      probe[*it] = GiNaC::numeric(static_cast<long>(h % 1000003 + 1000003), 1000003L);  // in [1, 2)
    }
  const double v = sym::to_double(factor.subs(probe, GiNaC::subs_options::no_pattern).evalf());
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%+.11e", v);
  return buffer;
}

// Which entries the first phase may pivot on: numbers before parameters' expressions,
// numbers alone, parameters' alone, or none (A itself symmetric). Tried in this order.
enum class Fixed { any, numbers, parameters, none };

// `e` expanded, with sin(x)^2 written 1 - cos(x)^2 where that leaves fewer terms: the
// reduced rows' sin^2 + cos^2 cancel (the homework's reduced mass matrix is constant).
ex reduced(const ex& e) {
  const ex expanded = GiNaC::expand(e);
  const ex simplified = sym::simplify_trig(expanded);
  const auto terms = [](const ex& v) { return GiNaC::is_a<GiNaC::add>(v) ? v.nops() : 1; };
  return terms(simplified) <= terms(expanded) ? simplified : expanded;
}

// The distinct state-dependent parts of `e`'s terms (expanded): the sums a step computes
// once its parameter factors are hoisted.
std::size_t state_parts(const ex& e, const std::vector<GiNaC::symbol>& state) {
  if (e.is_zero()) return 0;
  std::vector<ex> parts;
  const std::size_t terms = GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1;
  for (std::size_t k = 0; k < terms; ++k) {
    const ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(k) : e;
    ex varying = 1;
    const std::size_t factors = GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1;
    for (std::size_t j = 0; j < factors; ++j) {
      const ex f = GiNaC::is_a<GiNaC::mul>(term) ? term.op(j) : term;
      if (depends_on(f, state)) varying *= f;
    }
    if (std::none_of(parts.begin(), parts.end(), [&](const ex& p) { return p.is_equal(varying); }))
      parts.push_back(varying);
  }
  return parts.size();
}

class Planner {
 public:
  Planner(const std::vector<ex>& entries, std::size_t n, const std::vector<GiNaC::symbol>& state,
          const GiNaC::exmap& parameters)
      : n_(n), state_(state.begin(), state.end()), parameters_(parameters) {
    for (std::size_t k = 0; k < n * n; ++k) {
      e_.push_back(reduced(entries[k]));
      given_constant_.push_back(!varies(e_.back()));
    }
    for (std::size_t i = 0; i < n; ++i) b_.push_back(reduced(entries[n * n + i]));
    g_ = e_;
    gb_ = b_;
  }

  std::optional<StaticSolve> run(Fixed fixed) {
    std::vector<bool> row_done(n_, false), col_done(n_, false);
    struct Pivot {
      std::size_t row, col;
      ex value;
    };
    std::vector<Pivot> pivots;
    // The first phase, on the expressions themselves: each eliminated row's terms combine
    // and are reduced (the homework's I + k, gravity cancelling); an entry that would grow
    // by more than one term (a Schur complement's products of sums) is a step instead.
    while (fixed != Fixed::none) {
      // The cheapest state-independent pivot by Markowitz's count, numbers first under `any`.
      std::optional<std::tuple<int, std::size_t, std::size_t, std::size_t>> best;
      for (std::size_t i = 0; i < n_; ++i)
        for (std::size_t j = 0; j < n_; ++j) {
          if (row_done[i] || col_done[j] || e_[i * n_ + j].is_zero()) continue;
          const ex& v = e_[i * n_ + j];
          const bool number = GiNaC::is_a<GiNaC::numeric>(v);
          // Only entries given state-independent and untouched since: one the elimination
          // changed (the homework's I, now I + k) stays in the remainder, whose steps keep
          // its neighbours' products (k cos(th1 - th2)) unexpanded.
          if (!given_constant_[i * n_ + j]) continue;
          if ((fixed == Fixed::numbers && !number) || (fixed == Fixed::parameters && number)) continue;
          if (!nonzero_at_parameters(v)) continue;
          std::size_t in_row = 0, in_col = 0;
          for (std::size_t k = 0; k < n_; ++k) {
            in_row += !col_done[k] && !e_[i * n_ + k].is_zero() ? 1 : 0;
            in_col += !row_done[k] && !e_[k * n_ + j].is_zero() ? 1 : 0;
          }
          const auto key = std::make_tuple(number ? 0 : 1, (in_row - 1) * (in_col - 1), i, j);
          if (!best || key < *best) best = key;
        }
      if (!best) break;
      const std::size_t i = std::get<2>(*best), j = std::get<3>(*best);
      // The pivot row divided by its pivot (a constant): the multipliers are then the
      // column's entries, and the row's unknown is its B less a sum.
      const ex pivot = e_[i * n_ + j];
      for (std::size_t c = 0; c < n_; ++c)
        if (!col_done[c] && !e_[i * n_ + c].is_zero()) {
          e_[i * n_ + c] = reduced(e_[i * n_ + c] / pivot);
          g_[i * n_ + c] = GiNaC::is_a<GiNaC::symbol>(g_[i * n_ + c]) ? g_[i * n_ + c] / pivot : e_[i * n_ + c];
        }
      b_[i] = reduced(b_[i] / pivot);
      gb_[i] = GiNaC::is_a<GiNaC::symbol>(gb_[i]) ? gb_[i] / pivot : b_[i];
      for (std::size_t r = 0; r < n_; ++r) {
        if (row_done[r] || r == i || e_[r * n_ + j].is_zero()) continue;
        const ex l = e_[r * n_ + j];
        std::optional<ex> l_step;  // the multiplier as a step, on first need
        const auto update = [&](ex& exact, ex& form, const ex& exact_pivot_row, ex& form_pivot_row) {
          const ex updated = reduced(exact - l * exact_pivot_row);
          if (state_parts(updated, state_) <= state_parts(exact, state_) + 1) {
            form = updated;
          } else {
            // Named, so that hoisting does not multiply the sums out again.
            if (!l_step) l_step = early_step(g_[r * n_ + j]);
            form_pivot_row = early_step(form_pivot_row);
            form = early_step(form - *l_step * form_pivot_row);
          }
          exact = updated;
        };
        for (std::size_t c = 0; c < n_; ++c)
          if (!col_done[c] && c != j && !e_[i * n_ + c].is_zero()) {
            update(e_[r * n_ + c], g_[r * n_ + c], e_[i * n_ + c], g_[i * n_ + c]);
            given_constant_[r * n_ + c] = false;
          }
        update(b_[r], gb_[r], b_[i], gb_[i]);
        e_[r * n_ + j] = 0;
        g_[r * n_ + j] = 0;
      }
      pivots.push_back({i, j, pivot});
      row_done[i] = col_done[j] = true;
    }

    // The remainder: its k-th row with its k-th column, symmetric or no plan.
    std::vector<std::size_t> rows, cols;
    for (std::size_t k = 0; k < n_; ++k) {
      if (!row_done[k]) rows.push_back(k);
      if (!col_done[k]) cols.push_back(k);
    }
    const std::size_t m = rows.size();
    for (std::size_t a = 0; a < m; ++a)
      for (std::size_t b = a + 1; b < m; ++b)
        if (!sym::simplify_trig(e_[rows[a] * n_ + cols[b]] - e_[rows[b] * n_ + cols[a]]).is_zero()) return std::nullopt;

    // Every entry the steps read, each term's parameter factor hoisted (computed once per
    // run): the pivot rows (over their pivots), the pivots, the remainder's upper triangle,
    // B, and the first phase's steps.
    std::vector<ex> used;
    std::vector<std::size_t> at;  // index into `used` by entry (A row major, then B); n*n+n: unused
    at.assign(n_ * n_ + n_, n_ * n_ + n_);
    const auto use = [&](std::size_t k, const ex& v) {
      at[k] = used.size();
      used.push_back(v);
    };
    for (const Pivot& p : pivots) {
      for (std::size_t c = 0; c < n_; ++c)
        if (c != p.col && !e_[p.row * n_ + c].is_zero()) use(p.row * n_ + c, g_[p.row * n_ + c]);
      use(n_ * n_ + p.row, gb_[p.row]);
    }
    const std::size_t first_pivot = used.size();
    for (const Pivot& p : pivots) used.push_back(p.value);
    for (std::size_t a = 0; a < m; ++a) {
      for (std::size_t b = a; b < m; ++b) use(rows[a] * n_ + cols[b], g_[rows[a] * n_ + cols[b]]);
      use(n_ * n_ + rows[a], gb_[rows[a]]);
    }
    const std::size_t first_early = used.size();
    for (const Definition& d : early_) used.push_back(d.second);
    const Hoisted hoisted = hoist_parameters(used, state_);
    out_.constants = hoisted.factors;
    for (std::size_t k = 0; k < early_.size(); ++k)
      out_.definitions.emplace_back(early_[k].first, hoisted.entries[first_early + k]);
    const auto entry = [&](std::size_t k) { return at[k] == at.size() ? ex(0) : hoisted.entries[at[k]]; };
    std::vector<ex> f(n_ * n_), b(n_);
    for (std::size_t k = 0; k < n_ * n_; ++k) f[k] = step(entry(k), "a");
    for (std::size_t i = 0; i < n_; ++i) b[i] = step(entry(n_ * n_ + i), "b");

    // LDL^T by elimination on the upper triangle: S_bc -= (S_ab / d_a) S_ac for a < b <= c.
    const auto s = [&](std::size_t a, std::size_t c) -> ex& { return f[rows[a] * n_ + cols[c]]; };
    std::vector<ex> inverses;
    std::vector<ex> diagonal;
    for (std::size_t a = 0; a < m; ++a) {
      if (s(a, a).is_zero()) return std::nullopt;  // structurally singular
      diagonal.push_back(s(a, a));
      inverses.push_back(step(1 / s(a, a), "inv"));
      for (std::size_t c = a + 1; c < m; ++c) {
        if (s(a, c).is_zero()) continue;
        const ex l = step(s(a, c) * inverses[a], "l");
        for (std::size_t d = c; d < m; ++d)
          if (!s(a, d).is_zero()) s(c, d) = step(s(c, d) - l * s(a, d), "a");
        b[rows[c]] = step(b[rows[c]] - l * b[rows[a]], "b");
      }
    }
    // Back substitution: the remainder's unknowns, then the first phase's in reverse.
    std::vector<ex> u(n_, 0);
    for (std::size_t a = m; a-- > 0;) {
      ex v = b[rows[a]];
      for (std::size_t c = a + 1; c < m; ++c) v -= s(a, c) * u[cols[c]];
      u[cols[a]] = step(v * inverses[a], "u");
    }
    for (std::size_t p = pivots.size(); p-- > 0;) {
      const Pivot& pivot = pivots[p];
      ex v = b[pivot.row];
      for (std::size_t c = 0; c < n_; ++c)
        if (c != pivot.col) v -= f[pivot.row * n_ + c] * u[c];
      u[pivot.col] = step(v, "u");
    }
    out_.outputs = u;
    for (std::size_t p = 0; p < pivots.size(); ++p) out_.outputs.push_back(step(hoisted.entries[first_pivot + p], "p"));
    for (const ex& d : diagonal) out_.outputs.push_back(d);
    out_.fixed_pivots = pivots.size();
    out_.symmetric_pivots = m;
    return out_;
  }

 private:
  // `value` as one step: numbers and zero stay as they are, anything else is named; a
  // value that does not vary with the state is a constant of the run, computed once.
  ex step(const ex& value, const char* what) {
    if (value.is_zero() || GiNaC::is_a<GiNaC::numeric>(value) || GiNaC::is_a<GiNaC::symbol>(value)) return value;
    const bool constant = !varies(value);
    std::string name = constant ? "solve.c" : "solve.";
    name += what;
    name += std::to_string(steps_++);
    GiNaC::symbol s(name);
    if (constant) {
      out_.constants.emplace_back(s, value);
    } else {
      out_.definitions.emplace_back(s, value);
      state_.push_back(s);  // what depends on it varies too
    }
    return s;
  }

  // A step of the first phase, over the parameters (hoisted once the phase is done).
  ex early_step(const ex& value) {
    if (value.is_zero() || GiNaC::is_a<GiNaC::numeric>(value) || GiNaC::is_a<GiNaC::symbol>(value) || !varies(value))
      return value;
    GiNaC::symbol s("solve.e" + std::to_string(steps_++));
    early_.emplace_back(s, value);
    state_.push_back(s);
    return s;
  }

  bool varies(const ex& v) const { return depends_on(v, state_); }

  bool nonzero_at_parameters(const ex& v) const {
    const ex value = v.subs(parameters_, GiNaC::subs_options::no_pattern).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real()) return false;
    const double x = sym::to_double(GiNaC::ex_to<GiNaC::numeric>(value));
    return std::isfinite(x) && x != 0;
  }

  std::size_t n_;
  std::vector<GiNaC::symbol> state_;  // the state's symbols, then the steps' that vary with it
  const GiNaC::exmap& parameters_;
  std::vector<ex> e_;                 // A's entries as expressions, updated by the first phase
  std::vector<ex> b_;                 // B's
  std::vector<ex> g_;                 // A's entries as the steps compute them: e_ itself or a first-phase step
  std::vector<ex> gb_;                // B's
  std::vector<bool> given_constant_;  // A's entries state-independent as given, not changed since
  std::vector<Definition> early_;     // the first phase's steps
  std::size_t steps_ = 0;
  StaticSolve out_;
};

}  // namespace

Hoisted hoist_parameters(const std::vector<GiNaC::ex>& entries, const std::vector<GiNaC::symbol>& state) {
  // Per entry: its terms grouped by their state-dependent part, each group's parameters
  // summed into one factor.
  std::vector<std::vector<std::pair<ex, ex>>> grouped;  // per entry: (state part, factor)
  for (const ex& entry : entries) {
    const ex e = GiNaC::expand(entry);
    std::vector<std::pair<ex, ex>> groups;
    const std::size_t terms = GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1;
    for (std::size_t k = 0; k < terms; ++k) {
      const ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(k) : e;
      ex varying = 1, fixed = 1;
      const std::size_t factors = GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1;
      for (std::size_t j = 0; j < factors; ++j) {
        const ex f = GiNaC::is_a<GiNaC::mul>(term) ? term.op(j) : term;
        (depends_on(f, state) ? varying : fixed) *= f;
      }
      auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first.is_equal(varying); });
      if (it == groups.end())
        groups.emplace_back(varying, fixed);
      else
        it->second += fixed;
    }
    for (auto& [varying, fixed] : groups) fixed = GiNaC::expand(fixed);
    grouped.push_back(std::move(groups));
  }
  // One symbol per factor up to sign (the one of positive key), numbered in key order.
  std::map<std::string, ex> by_key;
  for (const auto& groups : grouped)
    for (const auto& [varying, fixed] : groups)
      if (!fixed.is_zero() && !GiNaC::is_a<GiNaC::numeric>(fixed)) {
        const std::string key = canonical_key(fixed);
        const ex positive = key[0] == '-' ? GiNaC::expand(-fixed) : fixed;
        const auto [it, fresh] = by_key.emplace(key[0] == '-' ? canonical_key(-fixed) : key, positive);
        // Two different factors of one key would be one symbol: hoist nothing rather.
        if (!fresh && !GiNaC::expand(it->second - positive).is_zero()) return {entries, {}};
      }
  Hoisted out;
  std::map<std::string, ex> symbol_of;
  for (const auto& [key, factor] : by_key) {
    GiNaC::symbol s("hoisted." + std::to_string(out.factors.size()));
    out.factors.emplace_back(s, factor);
    symbol_of.emplace(key, s);
  }
  for (const auto& groups : grouped) {
    ex hoisted = 0;
    for (const auto& [varying, fixed] : groups) {
      if (fixed.is_zero() || GiNaC::is_a<GiNaC::numeric>(fixed)) {
        hoisted += fixed * varying;
        continue;
      }
      const std::string key = canonical_key(fixed);
      hoisted += key[0] == '-' ? -symbol_of.at(canonical_key(-fixed)) * varying : symbol_of.at(key) * varying;
    }
    out.entries.push_back(hoisted);
  }
  return out;
}

PivotCheck::PivotCheck(std::size_t fixed, const std::vector<std::optional<double>>& pivots) {
  for (std::size_t k = 0; k < pivots.size(); ++k) {
    const bool symmetric = k >= fixed;
    if (!pivots[k]) {
      varying_.push_back({k, symmetric});
      continue;
    }
    const double p = *pivots[k], a = std::fabs(p);
    if (!(a > 0) || !std::isfinite(a)) never_ = true;
    largest_ = std::max(largest_, a);
    smallest_ = std::min(smallest_, a);
    if (symmetric) {
      const int s = p > 0 ? 1 : -1;
      if (sign_ == 0) sign_ = s;
      if (s != sign_) never_ = true;
    }
  }
}

std::optional<StaticSolve> plan_static_solve(const std::vector<GiNaC::ex>& entries, std::size_t n,
                                             const std::vector<GiNaC::symbol>& state, const GiNaC::exmap& parameters) {
  for (const Fixed fixed : {Fixed::any, Fixed::numbers, Fixed::parameters, Fixed::none})
    if (std::optional<StaticSolve> plan = Planner(entries, n, state, parameters).run(fixed)) return plan;
  return std::nullopt;
}

}  // namespace linkage::eval
