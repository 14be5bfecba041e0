// Every shipped mechanism runs in every case with every integrator: a short run from its
// [initial] state exits 0, writes finite numbers only, and Cases 1 and 2 agree with Case 3
// to the integrator's error. (Gauss-Legendre's Newton iteration once failed at t = 0 in
// Case 1 of every mechanism on a cart, which no test ran.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "model/mechanism_toml.hpp"
#include "run_checks.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

class SimulateEveryIntegrator : public testing::TestWithParam<std::string> {};

TEST_P(SimulateEveryIntegrator, EveryCaseRunsAndAgrees) {
  for (const std::string integrator : {"euler", "symplectic-euler", "rk4", "dopri5", "dop853", "gauss-legendre"}) {
    std::vector<Table> tables;
    for (const char* case_id : {"1", "2", "3"}) {
      const RunResult r = run_linkage({"simulate", "--mechanism", GetParam(), "--case", case_id, "--integrator",
                                       integrator, "--duration", "0.1", "--every", "0.02"});
      ASSERT_EQ(r.exit_code, 0) << integrator << " Case " << case_id << ": " << r.err;
      tables.push_back(parse_csv(r.out));
      for (const std::vector<double>& row : tables.back().rows)
        for (double v : row) ASSERT_TRUE(std::isfinite(v)) << integrator << " Case " << case_id << " t " << row[0];
    }
    // The cases integrate different equations of one motion: they differ by the
    // integrator's error, O(h) = 1e-3 for the first-order methods at the default step.
    const bool first_order = integrator == "euler" || integrator == "symplectic-euler";
    SCOPED_TRACE(integrator);
    (void)expect_cases_agree(tables, first_order ? 2e-3 : 1e-7);
  }
}

INSTANTIATE_TEST_SUITE_P(Shipped, SimulateEveryIntegrator, testing::ValuesIn(shipped_mechanism_names()),
                         [](const testing::TestParamInfo<std::string>& p) { return test_name(p.param); });

}  // namespace
}  // namespace linkage::test
