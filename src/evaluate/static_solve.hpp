#pragma once
// A u = B of a small system as steps over A's and B's symbolic entries, planned once from
// their structure, so one compiled Program computes A and B and solves (issue 24):
//   1. pivots on entries that do not depend on the state (a number, as the homework's
//      Case 3 force rows' 2, or the parameters' masses of Case 1's M), each eliminated
//      symbolically with the entries it touches, those known to be zero skipped, and the
//      rows it leaves reduced (sin^2 + cos^2 = 1; terms that cancel, as gravity does);
//   2. what remains must be symmetric (checked symbolically: the reduced mass matrix, or
//      J M^-1 J^T): LDL^T on its upper triangle without pivoting.
// Whatever does not vary with the state (each term's parameter factor, a constant pivot's
// inverse) is a constant of the run, computed once, not on every call.
// No row exchanges, so the steps are straight-line code. They are stable while the
// symmetric remainder is definite; the caller checks that from the pivots (all of one
// sign and spread above round-off) and otherwise solves by a pivoting LU.
#include <ginac/ginac.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "evaluate/program.hpp"

namespace linkage::eval {

struct StaticSolve {
  std::vector<Definition> constants;    // the run's constants, in order, over the parameters and earlier ones
  std::vector<Definition> definitions;  // the steps per call, in order, over the state and the constants
  std::vector<GiNaC::ex> outputs;       // u, then the first phase's pivots, then the remainder's
  std::size_t fixed_pivots = 0;         // pivots of the first phase (state independent)
  std::size_t symmetric_pivots = 0;     // pivots of the symmetric remainder's LDL^T
};

/// `entries` with each term's state-independent factor (a product of parameters, or their
/// sum over the terms of one state-dependent part) a symbol of its own, computed once per
/// run instead of on every call: m D sin(th1), expanded to (m L / 2 - m b) sin(th1), is
/// c sin(th1). Numbers stay; a factor and its negative share one symbol.
struct Hoisted {
  std::vector<GiNaC::ex> entries;
  std::vector<Definition> factors;  // each symbol and its expression in the parameters
};
[[nodiscard]] Hoisted hoist_parameters(const std::vector<GiNaC::ex>& entries, const std::vector<GiNaC::symbol>& state);

/// The plan for A (`n` x `n`, row major) and B of `entries`, whose state (and time)
/// symbols are `state`; `parameters` the values of the remaining symbols (a pivot of the
/// first phase must be non-zero there). Its steps' inputs are the entries' symbols, then
/// its constants' (evaluated once, in order). nullopt when no plan leaves a symmetric remainder.
[[nodiscard]] std::optional<StaticSolve> plan_static_solve(const std::vector<GiNaC::ex>& entries, std::size_t n,
                                                           const std::vector<GiNaC::symbol>& state,
                                                           const GiNaC::exmap& parameters);

/// Whether a static solve's pivots at run time (its outputs after u) allow its u: all
/// finite and non-zero, the remainder's of one sign, and the smallest over the largest
/// magnitude above round-off; that ratio, else 0. Inline: it runs on every right-hand side.
[[nodiscard]] inline double static_solve_spread(const double* pivots, std::size_t fixed, std::size_t symmetric) {
  double largest = 0, smallest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < fixed + symmetric; ++k) {
    const double a = std::fabs(pivots[k]);
    if (!(a > 0) || !std::isfinite(a)) return 0;  // zero or NaN
    largest = std::max(largest, a);
    smallest = std::min(smallest, a);
  }
  // A symmetric remainder with pivots of both signs is indefinite: no pivoting there is unsafe.
  for (std::size_t k = 1; k < symmetric; ++k)
    if ((pivots[fixed + k] > 0) != (pivots[fixed] > 0)) return 0;
  const double spread = smallest / largest;
  return spread > std::numeric_limits<double>::epsilon() ? spread : 0;
}

/// static_solve_spread(...) > 0, with the pivots that are constants of the run (known
/// here, nullopt for those that vary with the state) folded in once: on every call only
/// the varying ones are read.
class PivotCheck {
 public:
  PivotCheck() = default;
  PivotCheck(std::size_t fixed, const std::vector<std::optional<double>>& pivots);
  [[nodiscard]] bool accepts(const double* pivots) const {
    if (never_) return false;
    double largest = largest_, smallest = smallest_;
    int sign = sign_;
    for (const Varying& v : varying_) {
      const double p = pivots[v.index];
      const double a = std::fabs(p);
      if (!(a > 0) || !std::isfinite(a)) return false;  // zero or NaN
      largest = std::max(largest, a);
      smallest = std::min(smallest, a);
      if (v.symmetric) {
        const int s = p > 0 ? 1 : -1;
        if (sign == 0) sign = s;
        if (s != sign) return false;  // indefinite
      }
    }
    return smallest / largest > std::numeric_limits<double>::epsilon();
  }

 private:
  struct Varying {
    std::size_t index;
    bool symmetric;
  };
  std::vector<Varying> varying_;
  double largest_ = 0, smallest_ = std::numeric_limits<double>::infinity();
  int sign_ = 0;        // the constant symmetric pivots' sign (0: none)
  bool never_ = false;  // a constant pivot already rejects
};

}  // namespace linkage::eval
