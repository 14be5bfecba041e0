#pragma once
// The energy balance of a simulate run whose work column carries drivers' or state loads'
// work: shared by the driven and the state-loaded runs' tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace linkage::test {

/// `table` has columns t, work, energy_error_relative: E - E(0) - W within 1e-9 of the
/// energy scale at every row, while |W| reaches 0.1 J (the work counted is not small).
inline void expect_balance_with_real_work(const Table& table, const std::string& what) {
  double largest_work = 0;
  for (const std::vector<double>& row : table.rows) {
    EXPECT_LT(row[2], 1e-9) << what << " t " << row[0];
    largest_work = std::max(largest_work, std::fabs(row[1]));
  }
  EXPECT_GT(largest_work, 0.1) << what;
}

}  // namespace linkage::test
