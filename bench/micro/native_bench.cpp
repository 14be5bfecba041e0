// The general path's right-hand side, y' of MechanismDynamics for the homework
// (two-blocks), interpreted against native code (evaluate/native_library.hpp): the same
// programs, the interpreter's register walk against straight-line compiled code. Case 3
// of this free tree runs the O(n) recursion, whose only program (the loads) is constant
// here, so native code cannot help it; Case 2 solves the compiled rows by LU and shows
// what the programs themselves cost. The native code is compiled (or taken from the
// user's cache) before timing starts.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <random>
#include <vector>

#include "evaluate/mechanism_dynamics.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/system.hpp"

namespace linkage::bench {
namespace {

void general_rhs(benchmark::State& state, CaseId id, bool native) {
  static const sym::System system(load_mechanism("two-blocks"));
  eval::MechanismDynamics dynamics(system, id);
  if (native) {
    const eval::NativeAttachment a = dynamics.attach_native();
    if (!a.attached) {
      state.SkipWithError(("no native code: " + a.reason).c_str());
      return;
    }
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

BENCHMARK_CAPTURE(general_rhs, case3_interpreted, CaseId::reduced, false)->Name("rhs/general_case3_interpreted");
BENCHMARK_CAPTURE(general_rhs, case3_native, CaseId::reduced, true)->Name("rhs/general_case3_native");
BENCHMARK_CAPTURE(general_rhs, case2_interpreted, CaseId::generalized, false)->Name("rhs/general_case2_interpreted");
BENCHMARK_CAPTURE(general_rhs, case2_native, CaseId::generalized, true)->Name("rhs/general_case2_native");

}  // namespace
}  // namespace linkage::bench
