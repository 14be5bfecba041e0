#pragma once
// Dormand-Prince 5(4) (Dormand & Prince 1980; Hairer, Norsett, Wanner, Solving ODEs I,
// II.5, code DOPRI5), with Shampine's 4th-order dense output.
//
//   0    |
//   1/5  | 1/5
//   3/10 | 3/40        9/40
//   4/5  | 44/45      -56/15       32/9
//   8/9  | 19372/6561 -25360/2187  64448/6561  -212/729
//   1    | 9017/3168  -355/33      46732/5247   49/176   -5103/18656
//   1    | 35/384      0           500/1113     125/192  -2187/6784    11/84
//   -----+--------------------------------------------------------------------------
//   b    | 35/384      0           500/1113     125/192  -2187/6784    11/84     0
//   b-b^ | 71/57600    0          -71/16695     71/1920  -17253/339200 22/525   -1/40
//
// Order 5 propagated (local extrapolation), order 4 for the error estimate
//   err = |h| rms((b - b^) . k / sk).
// The 7th stage is f(t + h, y1): first-same-as-last, so a step costs 6 evaluations.
// Dense output, theta = (s - t0)/h:
//   y(s) = y0 + theta (r1 + (1-theta) (r2 + theta (r3 + (1-theta) r4)))
//   r1 = y1 - y0,  r2 = h k1 - r1,  r3 = r1 - h k7 - r2,  r4 = h sum_j d_j k_j.
#include <array>

#include "integrate/adaptive_rk.hpp"
#include "integrate/tableau.hpp"

namespace linkage::ode {

struct Dopri5Method {
  static constexpr Tableau<7> tableau{
      {0.0L, 1.0L / 5, 3.0L / 10, 4.0L / 5, 8.0L / 9, 1.0L, 1.0L},
      {{{},
        {1.0L / 5},
        {3.0L / 40, 9.0L / 40},
        {44.0L / 45, -56.0L / 15, 32.0L / 9},
        {19372.0L / 6561, -25360.0L / 2187, 64448.0L / 6561, -212.0L / 729},
        {9017.0L / 3168, -355.0L / 33, 46732.0L / 5247, 49.0L / 176, -5103.0L / 18656},
        {35.0L / 384, 0.0L, 500.0L / 1113, 125.0L / 192, -2187.0L / 6784, 11.0L / 84}}},
      {35.0L / 384, 0.0L, 500.0L / 1113, 125.0L / 192, -2187.0L / 6784, 11.0L / 84, 0.0L}};
  static constexpr std::array<long double, 7> error_weights{
      71.0L / 57600, 0.0L, -71.0L / 16695, 71.0L / 1920, -17253.0L / 339200, 22.0L / 525, -1.0L / 40};
  static constexpr std::array<long double, 7> dense_weights{
      -12715105075.0L / 11282082432,  0.0L,
      87487479700.0L / 32700410799,   -10690763975.0L / 1880347072,
      701980252875.0L / 199316789632, -1453857185.0L / 822651844,
      69997945.0L / 29380423};

  static constexpr std::size_t main_stages = 7;
  static constexpr int order = 5;
  static constexpr int error_order = 4;
  static constexpr long double beta = 0.04L, fac_min = 0.2L, fac_max = 10.0L;
  static constexpr std::size_t dense_terms = 4;

  template <class Scalar, int N, std::size_t K>
  [[nodiscard]] static Scalar error_norm(const std::array<State<Scalar, N>, K>& k, Scalar h, const State<Scalar, N>& sk,
                                         State<Scalar, N>& e) {
    return embedded_error_norm<error_weights>(k, h, sk, e);
  }

  /// Fills r1..r4; needs no new evaluations of f (returns 0).
  template <class Scalar, int N, std::size_t K, class F>
  static int dense_prepare(F& /*f*/, Scalar /*t0*/, Scalar h, const State<Scalar, N>& y0, const State<Scalar, N>& y1,
                           std::array<State<Scalar, N>, K>& k, State<Scalar, N>& scratch,
                           std::array<State<Scalar, N>, dense_terms>& r) {
    r[0] = y1 - y0;
    r[1] = h * k[0] - r[0];
    r[2] = r[0] - h * k[6] - r[1];
    weighted_sum<dense_weights>(k, scratch);
    r[3] = h * scratch;
    return 0;
  }

  template <class Scalar, int N>
  static void dense_evaluate(Scalar theta, const State<Scalar, N>& y0,
                             const std::array<State<Scalar, N>, dense_terms>& r, State<Scalar, N>& out) {
    const Scalar theta1 = 1 - theta;
    out = y0 + theta * (r[0] + theta1 * (r[1] + theta * (r[2] + theta1 * r[3])));
  }
};

/// Dormand-Prince 5(4) with dense output, for states of N values of type Scalar.
template <class Scalar, int N>
using Dopri5 = AdaptiveRk<Dopri5Method, Scalar, N>;

}  // namespace linkage::ode
