// Right-hand-side micro-benchmarks: one evaluation of y' = f(y) per case, and the
// Case 3 4x4 solve alone, ours (Schur on the block layout) against a generic
// fixed-size partial-pivot LU. States cycle through a table of random ones so the
// compiler cannot hoist anything out of the loop.
#include <benchmark/benchmark.h>

#include <array>
#include <random>

#include "bench/closed_form/case3_fast.hpp"
#include "bench/closed_form/linear_solve.hpp"
#include "bench/closed_form/linkage_rhs.hpp"
#include "bench/rhs.hpp"

namespace linkage::bench {
namespace {

constexpr std::size_t kStates = 64;

template <int N>
std::array<Vec<N>, kStates> random_states() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::array<Vec<N>, kStates> out;
  for (auto& y : out)
    for (int i = 0; i < N; ++i) y[i] = u(rng);
  return out;
}

// The right-hand sides the integrators use, from each case's one definition.
template <int N, class Rhs>
void rhs_loop(benchmark::State& state, const Rhs& f) {
  const auto ys = random_states<N>();
  Vec<N> dy;
  std::size_t k = 0;
  for (auto _ : state) {
    f(0.0, ys[k], dy);
    benchmark::DoNotOptimize(dy);
    k = (k + 1) % kStates;
  }
}
void BM_RhsCase1(benchmark::State& state) { rhs_loop<12>(state, MaximalRhs(Params{}, 0.0, 0.0)); }
void BM_RhsCase2(benchmark::State& state) { rhs_loop<8>(state, GeneralizedRhs<Case2>(Params{})); }
void BM_RhsCase3(benchmark::State& state) { rhs_loop<8>(state, GeneralizedRhs<Case3>(Params{})); }
void BM_RhsCase3Definition(benchmark::State& state) { rhs_loop<8>(state, DefinitionCase3Rhs{Params{}}); }
BENCHMARK(BM_RhsCase1)->Name("rhs/case1");
BENCHMARK(BM_RhsCase2)->Name("rhs/case2");
BENCHMARK(BM_RhsCase3)->Name("rhs/case3");  // what Simulation steps with: the closed form
BENCHMARK(BM_RhsCase3Definition)->Name("rhs/case3_definition");

// The same closed form with each input waiting for the previous output, as an explicit
// Runge-Kutta method's stages do (stage i needs k_(i-1)): its latency, not its
// throughput. `+ 0 * dy` is kept by the compiler (no fast-math) and costs one multiply
// and add on the chain. (The integrators' own cost per evaluation is timed on a cheap
// right-hand side instead: overhead/* in step_bench.cpp.)
void BM_RhsCase3Chained(benchmark::State& state) {
  const GeneralizedRhs<Case3> f{Params{}};
  const auto ys = random_states<8>();
  Vec<8> dy = Vec<8>::Zero(), y;
  std::size_t k = 0;
  for (auto _ : state) {
    y = ys[k] + 0.0 * dy;
    f(0.0, y, dy);
    k = (k + 1) % kStates;
  }
  benchmark::DoNotOptimize(dy);
}
BENCHMARK(BM_RhsCase3Chained)->Name("rhs/case3_chained");

void BM_RhsCase3UserLu(benchmark::State& state) {
  const UserConstants c{Params{}};
  const auto ys = random_states<8>();
  Vec<8> dy;
  std::size_t k = 0;
  for (auto _ : state) {
    user_case3_rhs(c, ys[k].data(), dy.data());
    benchmark::DoNotOptimize(dy);
    k = (k + 1) % kStates;
  }
}
BENCHMARK(BM_RhsCase3UserLu)->Name("rhs/case3_user_partial_piv_lu");

template <class T>
void BM_RhsCase3Fast(benchmark::State& state) {
  const FastCase3Rhs<T> f{Params{}};
  const auto ys = random_states<8>();
  std::array<Eigen::Matrix<T, 8, 1>, kStates> yt;
  for (std::size_t i = 0; i < kStates; ++i) yt[i] = ys[i].template cast<T>();
  Eigen::Matrix<T, 8, 1> dy;
  std::size_t k = 0;
  for (auto _ : state) {
    f(T(0), yt[k], dy);
    benchmark::DoNotOptimize(dy);
    k = (k + 1) % kStates;
  }
}
BENCHMARK(BM_RhsCase3Fast<double>)->Name("rhs/case3_fast");
BENCHMARK(BM_RhsCase3Fast<long double>)->Name("rhs/case3_fast_long_double");

// The solve alone, on matrices assembled beforehand.
std::array<LinearSystem<Case3>, kStates> case3_systems() {
  const auto ys = random_states<8>();
  std::array<LinearSystem<Case3>, kStates> out;
  for (std::size_t i = 0; i < kStates; ++i)
    out[i] = assemble<Case3>(make_env(Params{}, ys[i][2], ys[i][3], ys[i][6], ys[i][7]));
  return out;
}

void BM_SolveCase3Blocks(benchmark::State& state) {
  const auto systems = case3_systems();
  Vec<4> q;
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solve_blocks<Case3>(systems[k].A, systems[k].B, q));
    benchmark::DoNotOptimize(q);
    k = (k + 1) % kStates;
  }
}
BENCHMARK(BM_SolveCase3Blocks)->Name("solve/case3_blocks");

void BM_SolveCase3PartialPivLu(benchmark::State& state) {
  const auto systems = case3_systems();
  Eigen::Vector4d q;
  std::size_t k = 0;
  for (auto _ : state) {
    const Eigen::Matrix4d A = systems[k].A;
    q = A.partialPivLu().solve(systems[k].B);
    benchmark::DoNotOptimize(q);
    k = (k + 1) % kStates;
  }
}
BENCHMARK(BM_SolveCase3PartialPivLu)->Name("solve/case3_partial_piv_lu");

}  // namespace
}  // namespace linkage::bench
