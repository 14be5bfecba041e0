#pragma once
// An adaptive explicit Runge-Kutta integrator with dense output, driven by a method
// policy (Dopri5Method, Dop853Method) that supplies:
//   tableau            the stages; the last main stage has c = 1 and a = b, so its input
//                      is y1 and its derivative is f(t + h, y1) (first-same-as-last)
//   main_stages        stages per step, FSAL stage included
//   error_order, beta, fac_min, fac_max        for the step controller (step_control.hpp)
//   error_norm(k, h, sk, scratch)              the scaled error of a step
//   dense_prepare(...), dense_evaluate(...)    the continuous extension of a step
//
// Each call to step() makes one accepted step, retrying rejected attempts with smaller
// h. Output between steps comes from dense(), which never changes the step sequence.
// Nothing here allocates; the state and all stages are fixed-size. A step copies the
// state twice and the FSAL derivative once (into k_0, before its attempts): the end
// state stays in stage_ and the end derivative in k_(s-1) until the next step.
#include <array>
#include <cassert>
#include <limits>

#include "integrate/ode.hpp"
#include "integrate/step_control.hpp"
#include "integrate/tableau.hpp"

namespace linkage::ode {

/// |h| rms((W . k) / sk): the scaled error of a step whose embedded solution differs from
/// the propagated one by the weights W (Dopri5, Vern7).
template <auto W, class Scalar, int N, std::size_t K>
[[nodiscard]] inline Scalar embedded_error_norm(const std::array<State<Scalar, N>, K>& k, Scalar h,
                                                const State<Scalar, N>& sk, State<Scalar, N>& e) {
  weighted_sum<W>(k, e);
  return std::fabs(h) * rms_norm(e, sk);
}

template <class Method, class Scalar, int N>
class AdaptiveRk {
 public:
  using Vector = State<Scalar, N>;
  static constexpr std::size_t stages = Method::tableau.stages;  // including dense-only stages
  static constexpr std::size_t main_stages = Method::main_stages;
  static constexpr int order = Method::order;

  struct Settings {
    Tolerances<Scalar> tolerances{};
    Scalar first_step = 0;  // 0: choose automatically
    Scalar max_step = std::numeric_limits<Scalar>::infinity();
    /// Steps are shortened to end exactly here (not past it); the default never
    /// shortens a step, so output comes from dense() instead.
    Scalar t_stop = std::numeric_limits<Scalar>::infinity();
  };

  explicit AdaptiveRk(const Settings& settings)
      : settings_(settings),
        controller_(Method::error_order, static_cast<Scalar>(Method::beta), static_cast<Scalar>(Method::fac_min),
                    static_cast<Scalar>(Method::fac_max)) {
    // Written by dense_prepare before any read; zeroed once so GCC, which cannot follow
    // dense_ready_, does not see a read of uninitialized values.
    for (Vector& r : dense_) r.setZero();
  }

  /// Starts at (t0, y0); evaluates f there (and picks the first step if not given).
  template <class F>
  requires Derivative<F, Scalar, N>
  void start(F& f, Scalar t0, const Vector& y0) {
    t_ = t_old_ = t0;
    y_ = y_old_ = y0;
    f(t_, y_, f_);
    ++counters_.rhs_evaluations;
    fsal_ = Fsal::in_f;
    h_next_ = settings_.first_step > 0 ? settings_.first_step
                                       : initial_step(f, t_, y_, f_, order, settings_.tolerances, counters_);
    h_ = 0;
    dense_ready_ = step_valid_ = false;
  }

  /// Makes one accepted step from t() (none once t() reaches Settings::t_stop). On
  /// failure the state is left at the last accepted step and the status says why.
  template <class F>
  requires Derivative<F, Scalar, N> StepStatus step(F& f) {
    bool last_non_finite = false;
    step_valid_ = false;  // the attempts below overwrite the last step's stages
    dense_ready_ = false;
    if (t_ >= settings_.t_stop) return StepStatus::ok;  // nothing left to do
    // k_0 = f(t, y), once: the attempts leave it
    switch (fsal_) {
      case Fsal::in_f:
        copy_state(f_, k_[0]);
        break;
      case Fsal::in_k_last:
        copy_state(k_[main_stages - 1], k_[0]);
        break;
      case Fsal::in_k_first:
        break;
    }
    fsal_ = Fsal::in_k_first;
    for (;;) {
      const bool last = t_ + std::min(h_next_, settings_.max_step) >= settings_.t_stop;
      const Scalar h = last ? settings_.t_stop - t_ : std::min(h_next_, settings_.max_step);
      if (step_underflows(t_, h)) {
        h_next_ = h;
        return last_non_finite ? StepStatus::non_finite : StepStatus::step_underflow;
      }
      evaluate_stages<Method::tableau, 1, main_stages>(f, t_, y_, h, k_, stage_);  // stage_ = y1
      counters_.rhs_evaluations += static_cast<std::int64_t>(main_stages - 1);
      error_scale(settings_.tolerances, y_, stage_, sk_);
      Scalar err = Method::error_norm(k_, h, sk_, e_);
      last_non_finite = !all_finite(stage_) || !std::isfinite(err);
      if (last_non_finite) err = std::numeric_limits<Scalar>::quiet_NaN();
      if (controller_.decide(err, h, h_next_)) {
        t_old_ = t_;
        copy_state(y_, y_old_);
        t_ = last ? settings_.t_stop : t_old_ + h;
        copy_state(stage_, y_);  // stage_ keeps y1 for dense(), k_ the end derivative for the next step
        fsal_ = Fsal::in_k_last;
        h_ = h;
        step_valid_ = true;
        ++counters_.steps_accepted;
        return StepStatus::ok;
      }
      ++counters_.steps_rejected;
    }
  }

  /// The dense-output state at time s in [t_previous(), t()], of the method's dense
  /// order. May evaluate f (DOP853's extra stages, once per step).
  template <class F>
  requires Derivative<F, Scalar, N>
  void dense(F& f, Scalar s, Vector& out) {
    assert(s >= t_old_ && s <= t_);
    if (s == t_ || !step_valid_) {  // at the end of the step, or before the first step
      out = y_;
      return;
    }
    if (!dense_ready_) {
      counters_.rhs_evaluations += Method::dense_prepare(f, t_old_, h_, y_old_, stage_, k_, sk_, dense_);
      dense_ready_ = true;
    }
    Method::dense_evaluate((s - t_old_) / h_, y_old_, dense_, out);
  }

  /// Replaces the current state (e.g. after a projection onto a constraint manifold) and
  /// re-evaluates f there, so the next step starts from it. Dense output of the last
  /// step still describes the step as taken.
  template <class F>
  requires Derivative<F, Scalar, N>
  void replace_state(F& f, const Vector& y) {
    y_ = y;
    f(t_, y_, f_);
    ++counters_.rhs_evaluations;
    fsal_ = Fsal::in_f;
  }

  [[nodiscard]] Scalar t() const { return t_; }
  [[nodiscard]] const Vector& y() const { return y_; }
  [[nodiscard]] Scalar t_previous() const { return t_old_; }
  /// The size of the last accepted step, and of the next attempt.
  [[nodiscard]] Scalar last_step() const { return h_; }
  [[nodiscard]] Scalar next_step() const { return h_next_; }
  [[nodiscard]] const Counters& counters() const { return counters_; }

 private:
  Settings settings_;
  StepController<Scalar> controller_;
  Scalar t_ = 0, t_old_ = 0, h_ = 0, h_next_ = 0;
  Vector y_, y_old_, f_, stage_, sk_;  // stage_: y1 of the last step; sk_: also dense scratch
  Vector e_;                           // error_norm's scratch: sized once, not per attempt
  std::array<Vector, stages> k_;
  std::array<Vector, Method::dense_terms> dense_;
  bool step_valid_ = false;   // k_ holds the stages of the last accepted step
  bool dense_ready_ = false;  // dense_ holds its continuous extension
  // Where f(t, y) is: f_ (after start, replace_state), k_(s-1) (the last step's end), or
  // k_0 already (after a step that failed, whose attempts left k_0 alone).
  enum class Fsal { in_f, in_k_last, in_k_first };
  Fsal fsal_ = Fsal::in_f;
  Counters counters_;
};

}  // namespace linkage::ode
