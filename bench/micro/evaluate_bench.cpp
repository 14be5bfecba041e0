// The compiled evaluator (src/evaluate) on a mechanism-like expression set, the
// homework's Case 3 A (4x4) and B (4x1) written in GiNaC over the parameters and the
// state, against the same twenty entries written by hand in C++: the ratio of the two
// is what the register program costs over straight-line code. States cycle through a
// table of random ones so that nothing can be hoisted out of the loop.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "evaluate/program.hpp"

namespace linkage::bench {
namespace {

constexpr std::size_t kStates = 64;
constexpr std::size_t kInputs = 9;  // L, w, b, m, g, th1, th2, th1', th2'
constexpr std::size_t kEntries = 20;
using Inputs = std::array<double, kInputs>;

std::array<Inputs, kStates> random_inputs() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  std::array<Inputs, kStates> out;
  for (Inputs& in : out) in = {0.3, 0.05, 0.04, 0.1, 9.81, angle(rng), angle(rng), angle(rng), angle(rng)};
  return out;
}

struct Case3Expressions {
  std::vector<GiNaC::symbol> inputs;
  std::vector<GiNaC::ex> entries;  // A row by row, then B
};

Case3Expressions case3_expressions() {
  const GiNaC::symbol L("L"), w("w"), b("b"), m("m"), g("g"), th1("th1"), th2("th2"), om1("om1"), om2("om2");
  const GiNaC::ex D = L / 2 - b, I = m * (L * L + w * w) / 12;
  const GiNaC::matrix A = {{m * D * sin(th1), -m * D * cos(th1), I, 0},
                           {m * D * sin(th2), -m * D * cos(th2), 0, I},
                           {2, 0, -D * sin(th1), -D * sin(th2)},
                           {0, 2, D * cos(th1), D * cos(th2)}};
  const GiNaC::matrix B = {{m * g * D * cos(th1)},
                           {m * g * D * cos(th2)},
                           {D * (om1 * om1 * cos(th1) + om2 * om2 * cos(th2))},
                           {D * (om1 * om1 * sin(th1) + om2 * om2 * sin(th2)) - 2 * g}};
  Case3Expressions out{{L, w, b, m, g, th1, th2, om1, om2}, eval::flatten(A)};
  for (const GiNaC::ex& e : eval::flatten(B)) out.entries.push_back(e);
  return out;
}

// The same entries as a person would write them.
void case3_by_hand(const double* in, double* out) {
  const double L = in[0], w = in[1], b = in[2], m = in[3], g = in[4];
  const double D = L / 2 - b, I = m * (L * L + w * w) / 12;
  const double s1 = std::sin(in[5]), c1 = std::cos(in[5]), s2 = std::sin(in[6]), c2 = std::cos(in[6]);
  const double om1 = in[7] * in[7], om2 = in[8] * in[8], mD = m * D;
  const double A[16] = {mD * s1, -mD * c1, I, 0, mD * s2, -mD * c2, 0, I, 2, 0, -D * s1, -D * s2, 0, 2, D * c1, D * c2};
  for (int k = 0; k < 16; ++k) out[k] = A[k];
  out[16] = mD * g * c1;
  out[17] = mD * g * c2;
  out[18] = D * (om1 * c1 + om2 * c2);
  out[19] = D * (om1 * s1 + om2 * s2) - 2 * g;
}

void BM_EvaluateCase3Program(benchmark::State& state) {
  const Case3Expressions e = case3_expressions();
  const eval::Program program = eval::compile(e.entries, e.inputs);
  const auto inputs = random_inputs();
  std::vector<double> scratch(program.scratch_size());
  std::array<double, kEntries> out{}, by_hand{};
  // Both benchmarks compute the same numbers, or the ratio means nothing.
  program.run(inputs[0].data(), out.data(), scratch.data());
  case3_by_hand(inputs[0].data(), by_hand.data());
  for (std::size_t i = 0; i < kEntries; ++i)
    if (std::fabs(out[i] - by_hand[i]) > 1e-12 * (1 + std::fabs(by_hand[i])))
      state.SkipWithError("the program and the hand-written entries differ");
  std::size_t k = 0;
  for (auto _ : state) {
    program.run(inputs[k].data(), out.data(), scratch.data());
    benchmark::DoNotOptimize(out);
    k = (k + 1) % kStates;
  }
  state.counters["instructions"] = static_cast<double>(program.instruction_count());
  state.counters["registers"] = static_cast<double>(program.scratch_size());
}
BENCHMARK(BM_EvaluateCase3Program)->Name("evaluate/case3_program");

void BM_EvaluateCase3ByHand(benchmark::State& state) {
  const auto inputs = random_inputs();
  std::array<double, kEntries> out{};
  std::size_t k = 0;
  for (auto _ : state) {
    case3_by_hand(inputs[k].data(), out.data());
    benchmark::DoNotOptimize(out);
    k = (k + 1) % kStates;
  }
}
BENCHMARK(BM_EvaluateCase3ByHand)->Name("evaluate/case3_by_hand");

// What compiling costs, once per mechanism.
void BM_CompileCase3(benchmark::State& state) {
  const Case3Expressions e = case3_expressions();
  for (auto _ : state) benchmark::DoNotOptimize(eval::compile(e.entries, e.inputs));
}
BENCHMARK(BM_CompileCase3)->Name("evaluate/case3_compile")->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace linkage::bench
