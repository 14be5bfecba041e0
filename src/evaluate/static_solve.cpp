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

class Planner {
 public:
  Planner(const std::vector<ex>& entries, std::size_t n, const std::vector<GiNaC::symbol>& state,
          const GiNaC::exmap& parameters)
      : n_(n), state_(state), parameters_(parameters), e_(entries.begin(), entries.begin() + n * n) {
    for (std::size_t k = 0; k < n * n; ++k) f_.push_back(step(e_[k], "a"));
    for (std::size_t i = 0; i < n; ++i) b_.push_back(step(entries[n * n + i], "b"));
  }

  std::optional<StaticSolve> run(Fixed fixed) {
    std::vector<bool> row_done(n_, false), col_done(n_, false);
    struct Pivot {
      std::size_t row, col;
      ex value, inverse;
    };
    std::vector<Pivot> pivots;
    while (fixed != Fixed::none) {
      // The cheapest state-independent pivot by Markowitz's count, numbers first under `any`.
      std::optional<std::tuple<int, std::size_t, std::size_t, std::size_t>> best;
      for (std::size_t i = 0; i < n_; ++i)
        for (std::size_t j = 0; j < n_; ++j) {
          if (row_done[i] || col_done[j] || e_[i * n_ + j].is_zero()) continue;
          const ex& v = e_[i * n_ + j];
          const bool number = GiNaC::is_a<GiNaC::numeric>(v);
          if (!number && !state_free(v)) continue;
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
      const ex pivot = e_[i * n_ + j];
      const ex inverse = step(1 / f_[i * n_ + j], "inv");
      for (std::size_t r = 0; r < n_; ++r) {
        if (row_done[r] || r == i || e_[r * n_ + j].is_zero()) continue;
        const ex l = step(f_[r * n_ + j] * inverse, "l");
        for (std::size_t c = 0; c < n_; ++c) {
          if (col_done[c] || c == j || e_[i * n_ + c].is_zero()) continue;
          ex& target = e_[r * n_ + c];
          target = GiNaC::expand(target - e_[r * n_ + j] * e_[i * n_ + c] / pivot);
          f_[r * n_ + c] = target.is_zero() ? ex(0) : step(f_[r * n_ + c] - l * f_[i * n_ + c], "a");
        }
        b_[r] = step(b_[r] - l * b_[i], "b");
        e_[r * n_ + j] = 0;
        f_[r * n_ + j] = 0;
      }
      pivots.push_back({i, j, f_[i * n_ + j], inverse});
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
        if (!GiNaC::expand(e_[rows[a] * n_ + cols[b]] - e_[rows[b] * n_ + cols[a]]).is_zero()) return std::nullopt;
    // LDL^T by elimination on the upper triangle: S_bc -= (S_ab / d_a) S_ac for a < b <= c.
    const auto s = [&](std::size_t a, std::size_t b) -> ex& { return f_[rows[a] * n_ + cols[b]]; };
    std::vector<ex> inverses;
    std::vector<ex> diagonal;
    for (std::size_t a = 0; a < m; ++a) {
      if (s(a, a).is_zero()) return std::nullopt;  // structurally singular
      diagonal.push_back(s(a, a));
      inverses.push_back(step(1 / s(a, a), "inv"));
      for (std::size_t b = a + 1; b < m; ++b) {
        if (s(a, b).is_zero()) continue;
        const ex l = step(s(a, b) * inverses[a], "l");
        for (std::size_t c = b; c < m; ++c)
          if (!s(a, c).is_zero()) s(b, c) = step(s(b, c) - l * s(a, c), "a");
        b_[rows[b]] = step(b_[rows[b]] - l * b_[rows[a]], "b");
      }
    }
    // Back substitution: the remainder's unknowns, then the first phase's in reverse.
    std::vector<ex> u(n_, 0);
    for (std::size_t a = m; a-- > 0;) {
      ex v = b_[rows[a]];
      for (std::size_t b = a + 1; b < m; ++b) v -= s(a, b) * u[cols[b]];
      u[cols[a]] = step(v * inverses[a], "u");
    }
    for (std::size_t p = pivots.size(); p-- > 0;) {
      const Pivot& pivot = pivots[p];
      ex v = b_[pivot.row];
      for (std::size_t c = 0; c < n_; ++c)
        if (c != pivot.col) v -= f_[pivot.row * n_ + c] * u[c];
      u[pivot.col] = step(v * pivot.inverse, "u");
    }
    out_.outputs = u;
    for (const Pivot& p : pivots) out_.outputs.push_back(p.value);
    for (const ex& d : diagonal) out_.outputs.push_back(d);
    out_.fixed_pivots = pivots.size();
    out_.symmetric_pivots = m;
    return out_;
  }

 private:
  // `value` as one step: numbers and zero stay as they are, anything else is named.
  ex step(const ex& value, const char* what) {
    if (value.is_zero() || GiNaC::is_a<GiNaC::numeric>(value) || GiNaC::is_a<GiNaC::symbol>(value)) return value;
    std::string name = "solve.";
    name += what;
    name += std::to_string(out_.definitions.size());
    GiNaC::symbol s(name);
    out_.definitions.emplace_back(s, value);
    return s;
  }

  bool state_free(const ex& v) const { return !depends_on(v, state_); }

  bool nonzero_at_parameters(const ex& v) const {
    const ex value = v.subs(parameters_, GiNaC::subs_options::no_pattern).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real()) return false;
    const double x = sym::to_double(GiNaC::ex_to<GiNaC::numeric>(value));
    return std::isfinite(x) && x != 0;
  }

  std::size_t n_;
  const std::vector<GiNaC::symbol>& state_;
  const GiNaC::exmap& parameters_;
  std::vector<ex> e_;  // A's entries as expressions, updated by the first phase
  std::vector<ex> f_;  // A's entries as steps: zero, a number or a named step
  std::vector<ex> b_;  // B's, as steps
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

std::optional<StaticSolve> plan_static_solve(const std::vector<GiNaC::ex>& entries, std::size_t n,
                                             const std::vector<GiNaC::symbol>& state, const GiNaC::exmap& parameters) {
  for (const Fixed fixed : {Fixed::any, Fixed::numbers, Fixed::parameters, Fixed::none})
    if (std::optional<StaticSolve> plan = Planner(entries, n, state, parameters).run(fixed)) return plan;
  return std::nullopt;
}

}  // namespace linkage::eval
