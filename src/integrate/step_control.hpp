#pragma once
// Error-controlled step size selection (Hairer, Norsett, Wanner, Solving ODEs I, II.4,
// as in their codes DOPRI5 and DOP853).
//
//   sk_i = atol + rtol max(|y_i|, |y1_i|)          scale of component i
//   err  = sqrt(1/N sum_i (e_i / sk_i)^2)          a step is accepted when err <= 1
//   h_new = h / clamp(err^(1/(q+1) - 0.75 beta) / err_prev^beta / safety, 1/fac_max, 1/fac_min)
//         = h clamp(safety err_prev^beta / err^(1/(q+1) - 0.75 beta), fac_min, fac_max)
// (the first form with beta = 0, as DOP853; the second with a PI term, as DOPRI5)
//
// q is the order of the error estimator's lower method; beta > 0 adds the PI
// ("Lund stabilization") term that damps oscillating step sequences (DOPRI5 uses 0.04,
// DOP853 0). After a rejection the next accepted step may not grow. A step below
// 16 eps |t| cannot change t: that is an underflow and ends the run.
#include <algorithm>
#include <cmath>
#include <limits>

#include "integrate/ode.hpp"

namespace linkage::ode {

/// Tolerances of an adaptive run.
template <class Scalar>
struct Tolerances {
  Scalar rtol = Scalar(1e-10);
  Scalar atol = Scalar(1e-10);
};

/// sk_i = atol + rtol max(|a_i|, |b_i|).
template <class Scalar, int N>
inline void error_scale(const Tolerances<Scalar>& tol, const State<Scalar, N>& a, const State<Scalar, N>& b,
                        State<Scalar, N>& sk) {
  sk = (tol.atol + tol.rtol * a.cwiseAbs().cwiseMax(b.cwiseAbs()).array()).matrix();
}

/// sqrt(1/N sum (e_i / sk_i)^2).
template <class Scalar, int N>
[[nodiscard]] inline Scalar rms_norm(const State<Scalar, N>& e, const State<Scalar, N>& sk) {
  return std::sqrt(e.cwiseQuotient(sk).squaredNorm() / static_cast<Scalar>(e.size()));
}

/// Hairer's step size controller with an optional PI term.
///
/// Its powers cost one `log` and one `exp` per step (the previous error's log is kept),
/// or, when 1/(q+1) is 1/2^n and there is no PI term (DOP853: err^(1/8)), n square
/// roots: `pow` twice per step was a noticeable share of a DOPRI5 step.
template <class Scalar>
class StepController {
 public:
  /// `order` is q, the lower order of the embedded pair (4 for DOPRI5, 7 for DOP853).
  StepController(int order, Scalar beta, Scalar fac_min, Scalar fac_max, Scalar safety = Scalar(0.9))
      : exponent_(Scalar(1) / static_cast<Scalar>(order + 1) - Scalar(0.75) * beta),
        beta_(beta),
        safety_(safety),
        fac_min_(fac_min),
        fac_max_(fac_max),
        inv_fac_min_(Scalar(1) / fac_min),
        inv_fac_max_(Scalar(1) / fac_max),
        square_roots_(beta == 0 ? square_roots_for(order + 1) : -1) {}

  /// Decides on a step of size h with scaled error err. Returns true to accept; `h_next`
  /// is the size of the next attempt either way.
  bool decide(Scalar err, Scalar h, Scalar& h_next) {
    if (!(err <= Scalar(1))) {  // rejected, or err is NaN
      const Scalar fac = std::isfinite(err) ? power(err) / safety_ : inv_fac_min_;
      h_next = h / std::min(inv_fac_min_, fac);
      rejected_last_ = true;
      return false;
    }
    if (beta_ == 0) {
      const Scalar fac = std::clamp(power(err) / safety_, inv_fac_max_, inv_fac_min_);
      h_next = h / fac;
    } else {
      // The growth h_next / h = safety err_prev^beta / err^exponent, with err_prev's log
      // kept from the last accepted step: multiplied, so no division waits on the exp.
      const Scalar log_err = std::log(err);
      const Scalar growth = safety_ * std::exp(beta_ * log_err_prev_ - exponent_ * log_err);
      h_next = h * std::clamp(growth, fac_min_, fac_max_);
      log_err_prev_ = std::max(log_err, kLogErrFloor);
    }
    if (rejected_last_) h_next = std::min(h_next, h);
    rejected_last_ = false;
    return true;
  }

 private:
  /// n when p = 2^n (n >= 1), else -1.
  static int square_roots_for(int p) {
    int n = 0;
    while (p > 1 && p % 2 == 0) {
      p /= 2;
      ++n;
    }
    return p == 1 && n > 0 ? n : -1;
  }

  /// err^exponent for err > 0 (0 for err = 0).
  [[nodiscard]] Scalar power(Scalar err) const {
    if (square_roots_ > 0) {
      for (int i = 0; i < square_roots_; ++i) err = std::sqrt(err);
      return err;
    }
    return std::exp(exponent_ * std::log(err));
  }

  Scalar exponent_, beta_, safety_;
  Scalar fac_min_, fac_max_;          // the bounds of h_next / h
  Scalar inv_fac_min_, inv_fac_max_;  // 1 / fac_min, 1 / fac_max: divided once, not per step
  int square_roots_;                  // > 0: power() is that many square roots
  static constexpr Scalar kLogErrFloor = Scalar(-9.21034037197618273607196581873745L);  // log(1e-4): err_prev >= 1e-4
  Scalar log_err_prev_ = kLogErrFloor;  // log of the last accepted step's err_prev
  bool rejected_last_ = false;
};

/// True when h is too small to move t (16 units of round-off at t).
template <class Scalar>
[[nodiscard]] inline bool step_underflows(Scalar t, Scalar h) {
  return std::fabs(h) <= 16 * std::numeric_limits<Scalar>::epsilon() * std::max(std::fabs(t), Scalar(1e-3));
}

/// Hairer's starting step guess (HINIT): a step whose explicit-Euler error is about
/// the tolerance, and no larger than 100 |y0|' / |y0|''. Costs two evaluations of f.
template <class Scalar, int N, class F>
[[nodiscard]] Scalar initial_step(F& f, Scalar t0, const State<Scalar, N>& y0, const State<Scalar, N>& f0, int order,
                                  const Tolerances<Scalar>& tol, Counters& counters) {
  State<Scalar, N> sk;
  error_scale(tol, y0, y0, sk);
  const Scalar d0 = rms_norm(y0, sk), d1 = rms_norm(f0, sk);
  Scalar h0 = (d0 < Scalar(1e-5) || d1 < Scalar(1e-5)) ? Scalar(1e-6) : Scalar(0.01) * d0 / d1;
  const State<Scalar, N> y1 = y0 + h0 * f0;
  State<Scalar, N> f1;
  f(t0 + h0, y1, f1);
  ++counters.rhs_evaluations;
  const State<Scalar, N> df = f1 - f0;
  const Scalar d2 = rms_norm(df, sk) / h0;
  const Scalar dmax = std::max(d1, d2);
  const Scalar h1 = dmax <= Scalar(1e-15) ? std::max(Scalar(1e-6), h0 * Scalar(1e-3))
                                          : std::pow(Scalar(0.01) / dmax, Scalar(1) / static_cast<Scalar>(order + 1));
  return std::min(Scalar(100) * h0, h1);
}

}  // namespace linkage::ode
