// The adaptive methods' coefficients against Butcher's order conditions: for every rooted
// tree t up to the order, sum_i b_i Phi_i(t) = 1 / gamma(t), where Phi_i(t) is the product
// over t's subtrees u of (A Phi(u))_i. A single wrong digit in a tableau breaks some of them;
// the next order's conditions must fail, or the method would be of higher order than it says.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "integrate/dop853.hpp"
#include "integrate/dopri5.hpp"
#include "integrate/vern7.hpp"

namespace linkage {
namespace {

/// A rooted tree: its node count, its subtrees (indices into the list), and gamma(t).
struct Tree {
  int size = 1;
  std::vector<std::size_t> children;
  long double gamma = 1;
};

/// Every rooted tree with up to `order` nodes, smaller trees first. Each tree is a root
/// over a multiset of smaller trees, listed once: children in non-increasing index.
std::vector<Tree> trees_up_to(int order) {
  std::vector<Tree> all{Tree{}};
  for (int n = 2; n <= order; ++n) {
    const std::size_t known = all.size();
    std::vector<std::size_t> children;
    auto add = [&](auto& self, int remaining, std::size_t max_index) -> void {
      if (remaining == 0) {
        Tree t{n, children, static_cast<long double>(n)};
        for (std::size_t c : children) t.gamma *= all[c].gamma;
        all.push_back(t);
        return;
      }
      for (std::size_t c = std::min(max_index + 1, known); c-- > 0;) {
        if (all[c].size > remaining) continue;
        children.push_back(c);
        self(self, remaining - all[c].size, c);
        children.pop_back();
      }
    };
    add(add, n - 1, known - 1);
  }
  return all;
}

template <std::size_t S>
using Weights = std::array<long double, S>;

/// Phi(t) for every tree, over the stages of a.
template <std::size_t S>
std::vector<Weights<S>> elementary_weights(const std::vector<Tree>& trees,
                                           const std::array<std::array<long double, S>, S>& a) {
  std::vector<Weights<S>> phi;
  for (const Tree& t : trees) {
    Weights<S> p;
    p.fill(1);
    for (std::size_t c : t.children)
      for (std::size_t i = 0; i < S; ++i) {
        long double sum = 0;
        for (std::size_t j = 0; j < i; ++j) sum += a[i][j] * phi[c][j];
        p[i] *= sum;
      }
    phi.push_back(p);
  }
  return phi;
}

/// The largest |sum_i w_i Phi_i(t) - theta^|t| / gamma(t)| over the trees of `size` nodes.
template <std::size_t S, std::size_t W>
long double residual(const std::vector<Tree>& trees, const std::vector<Weights<S>>& phi,
                     const std::array<long double, W>& w, int size, long double theta = 1) {
  long double worst = 0;
  for (std::size_t k = 0; k < trees.size(); ++k) {
    if (trees[k].size != size) continue;
    long double sum = 0;
    for (std::size_t i = 0; i < W; ++i) sum += w[i] * phi[k][i];
    worst = std::max(worst, std::fabs(sum - std::pow(theta, static_cast<long double>(size)) / trees[k].gamma));
  }
  return worst;
}

/// The weights w meet every condition up to `order` (to round-off in long double) and
/// miss one of order + 1.
template <std::size_t S, std::size_t W>
void expect_order(const std::array<std::array<long double, S>, S>& a, const std::array<long double, W>& w, int order,
                  const char* what) {
  const std::vector<Tree> trees = trees_up_to(order + 1);
  const std::vector<Weights<S>> phi = elementary_weights(trees, a);
  for (int p = 1; p <= order; ++p) EXPECT_LT(residual(trees, phi, w, p), 1e-15L) << what << ", order " << p;
  EXPECT_GT(residual(trees, phi, w, order + 1), 1e-9L) << what << " is of order " << order + 1;
}

/// b - e, where e may cover only the first stages (the rest are 0).
template <std::size_t W, std::size_t E>
std::array<long double, W> minus(const std::array<long double, W>& b, const std::array<long double, E>& e) {
  static_assert(E <= W);
  std::array<long double, W> out = b;
  for (std::size_t i = 0; i < E; ++i) out[i] -= e[i];
  return out;
}

TEST(TableauOrder, CountsTheRootedTrees) {
  std::array<int, 9> count{};
  for (const Tree& t : trees_up_to(8)) ++count[static_cast<std::size_t>(t.size)];
  EXPECT_EQ(count, (std::array<int, 9>{0, 1, 1, 2, 4, 9, 20, 48, 115}));  // OEIS A000081
}

TEST(TableauOrder, RowSumsAreTheNodes) {
  auto expect_rows = [](const auto& tableau, const char* what) {
    for (std::size_t i = 0; i < tableau.stages; ++i) {
      long double sum = 0;
      for (long double v : tableau.a[i]) sum += v;
      EXPECT_NEAR(static_cast<double>(sum), static_cast<double>(tableau.c[i]), 1e-17) << what << " row " << i;
    }
  };
  expect_rows(ode::Dopri5Method::tableau, "Dopri5");
  expect_rows(ode::Dop853Method::tableau, "DOP853");
  expect_rows(ode::Vern7Method::tableau, "Vern7");
}

TEST(TableauOrder, Dopri5IsOfOrderFiveWithAFourthOrderEstimate) {
  const auto& m = ode::Dopri5Method::tableau;
  expect_order(m.a, m.b, 5, "Dopri5");
  expect_order(m.a, minus(m.b, ode::Dopri5Method::error_weights), 4, "Dopri5's embedded solution");
}

TEST(TableauOrder, Dop853IsOfOrderEightWithFifthAndThirdOrderEstimates) {
  const auto& m = ode::Dop853Method::tableau;
  expect_order(m.a, ode::Dop853Method::b, 8, "DOP853");
  expect_order(m.a, minus(ode::Dop853Method::b, ode::Dop853Method::e5), 5, "DOP853's fifth-order solution");
  expect_order(m.a, minus(ode::Dop853Method::b, ode::Dop853Method::e3), 3, "DOP853's third-order solution");
}

TEST(TableauOrder, Vern7IsOfOrderSevenWithASixthOrderEstimate) {
  const auto& m = ode::Vern7Method::tableau;
  expect_order(m.a, ode::Vern7Method::b, 7, "Vern7");
  expect_order(m.a, minus(ode::Vern7Method::b, ode::Vern7Method::error_weights), 6, "Vern7's embedded solution");
}

// b_i(theta) = sum_m r_im theta^m must give theta^|t| / gamma(t): exactly to order 6, and
// to 2e-7 at order 7 (Verner's interpolant is of order 6 with a small seventh-order defect).
TEST(TableauOrder, Vern7DenseOutputIsOfOrderSix) {
  const auto& m = ode::Vern7Method::tableau;
  const std::vector<Tree> trees = trees_up_to(7);
  const std::vector<Weights<16>> phi = elementary_weights(trees, m.a);
  for (long double theta : {0.1L, 0.5L, 0.9L, 1.0L}) {
    std::array<long double, 16> w{};
    long double power = 1;
    for (const auto& row : ode::Vern7Method::dense_weights) {
      power *= theta;
      for (std::size_t i = 0; i < w.size(); ++i) w[i] += row[i] * power;
    }
    for (int p = 1; p <= 6; ++p) EXPECT_LT(residual(trees, phi, w, p, theta), 1e-15L) << "theta " << theta;
    EXPECT_LT(residual(trees, phi, w, 7, theta), 5e-7L) << "theta " << theta;
    if (theta == 1.0L) {
      for (std::size_t i = 0; i < w.size(); ++i)
        EXPECT_NEAR(static_cast<double>(w[i]), static_cast<double>(ode::Vern7Method::b[i]), 1e-15)
            << i;  // r_im up to 1,200
    }
  }
}

}  // namespace
}  // namespace linkage
