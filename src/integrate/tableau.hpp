#pragma once
// Explicit Runge-Kutta methods as Butcher tableaus:
//
//   c_1 |                           k_i = f(t + c_i h, y + h sum_{j<i} a_ij k_j)
//   c_2 | a_21                      y_1 = y + h sum_i b_i k_i
//   ... | ...   ...
//   c_s | a_s1  ...  a_s,s-1
//   ----+---------------------
//       | b_1   ...  b_s-1  b_s
//
// A tableau is a compile-time value, so its coefficients are constants in the generated
// code and its zeros cost nothing: `weighted_sum` drops zero weights at compile time.
// Coefficients are long double literals (at least 19 significant digits where the
// method's source gives them), converted once to the Scalar of the run.
#include <array>
#include <cstddef>
#include <utility>

#include "integrate/ode.hpp"

namespace linkage::ode {

/// An explicit s-stage tableau (a is strictly lower triangular).
template <std::size_t S>
struct Tableau {
  std::array<long double, S> c{};
  std::array<std::array<long double, S>, S> a{};
  std::array<long double, S> b{};
  static constexpr std::size_t stages = S;
};

/// base_i + h sum_j w_j k_j,i over the first W.size() entries of k, for a compile-time
/// weight row W. Written per component with a scalar accumulator, so it inlines
/// completely and the compiler vectorizes across components.
template <auto W, class Scalar, int N, std::size_t K, class Base>
inline void combine(const Base& base, Scalar h, const std::array<State<Scalar, N>, K>& k, State<Scalar, N>& out) {
  static_assert(W.size() <= K, "more weights than stages");
  if constexpr (N == Eigen::Dynamic) out.resize(k[0].size());
  const auto n = static_cast<int>(k[0].size());
  for (int i = 0; i < n; ++i) {
    Scalar acc = 0;
    [&]<std::size_t... J>(std::index_sequence<J...>) {
      ((W[J] != 0 ? void(acc += static_cast<Scalar>(W[J]) * k[J][i]) : void()), ...);
    }
    (std::make_index_sequence<W.size()>{});
    out[i] = base(i) + h * acc;
  }
}

/// sum_j w_j k_j for a compile-time weight row W.
template <auto W, class Scalar, int N, std::size_t K>
inline void weighted_sum(const std::array<State<Scalar, N>, K>& k, State<Scalar, N>& sum) {
  combine<W>([](int) { return Scalar(0); }, Scalar(1), k, sum);
}

/// out = y + h sum_j w_j k_j for a compile-time weight row W.
template <auto W, class Scalar, int N, std::size_t K>
inline void add_weighted(const State<Scalar, N>& y, Scalar h, const std::array<State<Scalar, N>, K>& k,
                         State<Scalar, N>& out) {
  combine<W>([&](int i) { return y[i]; }, h, k, out);
}

/// Evaluates stages First..Last-1 of tableau T at (t, y) with step h, given k_0..k_First-1
/// (k_0 = f(t, y) is often known already: first-same-as-last). `stage` is scratch.
template <auto T, std::size_t First, std::size_t Last, class Scalar, int N, std::size_t K, class F>
inline void evaluate_stages(F& f, Scalar t, const State<Scalar, N>& y, Scalar h, std::array<State<Scalar, N>, K>& k,
                            State<Scalar, N>& stage) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (([&] {
       constexpr std::size_t i = First + I;
       add_weighted<T.a[i]>(y, h, k, stage);
       f(t + static_cast<Scalar>(T.c[i]) * h, stage, k[i]);
     }()),
     ...);
  }
  (std::make_index_sequence<Last - First>{});
}

}  // namespace linkage::ode
