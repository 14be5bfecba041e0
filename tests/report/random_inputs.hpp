#pragma once
// Reproducible random parameters and states for the report tests: masses over six
// decades, long and short blocks, the pin anywhere on the block, angles over several
// turns, fast spins.
#include <cmath>
#include <random>
#include <vector>

#include "model/params.hpp"
#include "model/state.hpp"

namespace linkage::test {

struct Sample {
  Params p;
  State s;
};

inline std::vector<Sample> random_samples(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  std::vector<Sample> samples;
  for (int i = 0; i < count; ++i) {
    Sample x;
    x.p.m = std::pow(10.0, uniform(-3, 3));
    x.p.L = uniform(0.05, 5);
    x.p.w = uniform(0.01, 1);
    x.p.b = uniform(0, x.p.L);
    x.p.g = uniform(0, 30);
    x.s = {uniform(-10, 10), uniform(-10, 10), uniform(-20, 20), uniform(-20, 20),
           uniform(-5, 5),   uniform(-5, 5),   uniform(-60, 60), uniform(-60, 60)};
    samples.push_back(x);
  }
  return samples;
}

}  // namespace linkage::test
