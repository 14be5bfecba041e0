// The general path's right-hand side, y' of MechanismDynamics, interpreted against native
// code (evaluate/native_library.hpp): the same programs, the interpreter's register walk
// against straight-line compiled code. The homework (two-blocks) in every case, the
// four-bar's Cases 1 and 3, and Case 3 of pendulum chains of 8, 32 and 64 links (the O(n)
// recursion beyond 8 rows). The native code is compiled (or taken from the user's cache) before timing
// starts.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <array>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench/double_pendulum_user.hpp"
#include "bench/mechanisms_bench.hpp"
#include "bench/rhs.hpp"
#include "bench/timing.hpp"
#include "evaluate/mechanism_dynamics.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/loop_closure.hpp"
#include "symbolic/system.hpp"

namespace linkage::bench {
namespace {

void general_rhs_of(benchmark::State& state, const sym::System& system, CaseId id, bool native,
                    bool derivative_only = false) {
  eval::MechanismDynamics dynamics(system, id);
  if (native) {
    const eval::NativeAttachment a = derivative_only ? dynamics.attach_native_derivative() : dynamics.attach_native();
    if (!a.attached) {
      state.SkipWithError(("no native code: " + a.reason).c_str());
      return;
    }
    dynamics.solve_by_structure(true);
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::vector<Eigen::VectorXd> ys(64, Eigen::VectorXd(dynamics.state_size()));
  for (Eigen::VectorXd& y : ys)
    for (Eigen::Index i = 0; i < y.size(); ++i) y[i] = u(rng);
  Eigen::VectorXd dy(dynamics.state_size());
  std::size_t k = 0;
  for (auto _ : state) {
    dynamics.derivative(0.0, ys[k], dy);
    benchmark::DoNotOptimize(dy.data());
    k = (k + 1) % ys.size();
  }
}

void general_rhs(benchmark::State& state, CaseId id, bool native) {
  static const sym::System system(load_mechanism("two-blocks"));
  general_rhs_of(state, system, id, native);
}

void four_bar_rhs(benchmark::State& state, CaseId id, bool native) {
  static const sym::System system(load_mechanism("four-bar"));
  general_rhs_of(state, system, id, native);
}

const sym::System& chain(int links) {
  static std::map<int, std::unique_ptr<sym::System>> systems;
  std::unique_ptr<sym::System>& system = systems[links];
  if (!system) system = std::make_unique<sym::System>(read_mechanism(pendulum_chain_toml(links), "chain.toml"));
  return *system;
}

void chain_rhs(benchmark::State& state, int links, bool native) {
  general_rhs_of(state, chain(links), CaseId::reduced, native);
}

/// The chain's right-hand side as `linkage bench mechanisms` times its compiled row: the
/// programs derivative() runs native (attach_native_derivative), the recursion's included.
void chain_rhs_derivative(benchmark::State& state, int links) {
  general_rhs_of(state, chain(links), CaseId::reduced, true, true);
}

// At a shipped mechanism's initial state, as `linkage bench mechanisms` times its rows: one
// state, an angle nudged by round-off each call, one entry of y' kept. The homework's angles
// (0.1, 0.2 rad) take sincos's short path, so what the path spends besides the arithmetic
// weighs more than at the random states above; the double pendulum's (-0.8, -1.2 rad) do not.
void case3_at_start(benchmark::State& state, const char* mechanism, Eigen::Index nudged) {
  static std::map<std::string, std::unique_ptr<sym::System>> systems;
  std::unique_ptr<sym::System>& system = systems[mechanism];
  if (!system) system = std::make_unique<sym::System>(load_mechanism(mechanism));
  eval::MechanismDynamics dynamics(*system, CaseId::reduced);
  if (const eval::NativeAttachment a = dynamics.attach_native(); !a.attached) {
    state.SkipWithError(("no native code: " + a.reason).c_str());
    return;
  }
  Eigen::VectorXd y = dynamics.initial_state(sym::checked_initial_state(*system).state), dy(y.size());
  const double base = y[nudged];
  double sink = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    y[nudged] = base + 1e-15 * static_cast<double>(i++ & 7U);
    dynamics.derivative(0.0, y, dy);
    sink += dy[dy.size() - 1];
  }
  benchmark::DoNotOptimize(sink);
}
BENCHMARK_CAPTURE(case3_at_start, homework, "two-blocks", 3)->Name("rhs/general_case3_native_at_start");
BENCHMARK_CAPTURE(case3_at_start, double_pendulum, "double-pendulum", 1)
    ->Name("rhs/double_pendulum_case3_native_at_start");

/// The double pendulum's right-hand side as a user writes it for Odeint
/// (bench/double_pendulum_user.hpp), at the same state: what `bench mechanisms` holds ours to.
void double_pendulum_user_at_start(benchmark::State& state) {
  const DoublePendulumUser f{0.3, 0.2, 0.25, 0.15, 9.81};  // mechanisms/double-pendulum.toml's
  std::array<double, 4> x{-0.8, -1.2, 0, 0}, dx{};
  double sink = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    x[1] = -1.2 + 1e-15 * static_cast<double>(i++ & 7U);
    forget(x);
    f(x, dx, 0.0);
    forget(dx);
    sink += dx[3];
  }
  benchmark::DoNotOptimize(sink);
}
BENCHMARK(double_pendulum_user_at_start)->Name("rhs/double_pendulum_user_at_start");

void case3_fast_at_start(benchmark::State& state) {
  static const sym::System system(load_mechanism("two-blocks"));
  const eval::MechanismDynamics dynamics(system, CaseId::reduced);
  const Eigen::VectorXd start = dynamics.initial_state(sym::checked_initial_state(system).state);
  const FastCase3Rhs<double> f{Params{}};
  Vec<8> y = start.head<8>(), dy;
  const double base = y[3];
  double sink = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    y[3] = base + 1e-15 * static_cast<double>(i++ & 7U);
    forget(y);  // as bench mechanisms: theta1's sincos not hoisted out of the loop
    f(0.0, y, dy);
    forget(dy);
    sink += dy[7];
  }
  benchmark::DoNotOptimize(sink);
}
BENCHMARK(case3_fast_at_start)->Name("rhs/case3_fast_at_start");

BENCHMARK_CAPTURE(general_rhs, case1_interpreted, CaseId::maximal, false)->Name("rhs/general_case1_interpreted");
BENCHMARK_CAPTURE(general_rhs, case1_native, CaseId::maximal, true)->Name("rhs/general_case1_native");
BENCHMARK_CAPTURE(general_rhs, case3_interpreted, CaseId::reduced, false)->Name("rhs/general_case3_interpreted");
BENCHMARK_CAPTURE(general_rhs, case3_native, CaseId::reduced, true)->Name("rhs/general_case3_native");
BENCHMARK_CAPTURE(general_rhs, case2_interpreted, CaseId::generalized, false)->Name("rhs/general_case2_interpreted");
BENCHMARK_CAPTURE(general_rhs, case2_native, CaseId::generalized, true)->Name("rhs/general_case2_native");
BENCHMARK_CAPTURE(four_bar_rhs, case1_interpreted, CaseId::maximal, false)->Name("rhs/four_bar_case1_interpreted");
BENCHMARK_CAPTURE(four_bar_rhs, case1_native, CaseId::maximal, true)->Name("rhs/four_bar_case1_native");
BENCHMARK_CAPTURE(four_bar_rhs, case3_interpreted, CaseId::reduced, false)->Name("rhs/four_bar_case3_interpreted");
BENCHMARK_CAPTURE(four_bar_rhs, case3_native, CaseId::reduced, true)->Name("rhs/four_bar_case3_native");
// attach_native() expands a chain's A and B first, which takes minutes for 32 and more
// links: the long chains are timed on the recursion without native code (its one program,
// the loads, is the same either way).
BENCHMARK_CAPTURE(chain_rhs, chain8_interpreted, 8, false)->Name("rhs/chain8_case3_interpreted");
BENCHMARK_CAPTURE(chain_rhs, chain8_native, 8, true)->Name("rhs/chain8_case3_native");
BENCHMARK_CAPTURE(chain_rhs, chain32_interpreted, 32, false)->Name("rhs/chain32_case3_interpreted");
BENCHMARK_CAPTURE(chain_rhs, chain64_interpreted, 64, false)->Name("rhs/chain64_case3_interpreted");
BENCHMARK_CAPTURE(chain_rhs_derivative, chain8_compiled, 8)->Name("rhs/chain8_case3_compiled");
BENCHMARK_CAPTURE(chain_rhs_derivative, chain32_compiled, 32)->Name("rhs/chain32_case3_compiled");
BENCHMARK_CAPTURE(chain_rhs_derivative, chain64_compiled, 64)->Name("rhs/chain64_case3_compiled");

}  // namespace
}  // namespace linkage::bench
