#pragma once
// Checks of simulate runs shared by the simulate tests: a tight run of one case, the energy
// balance with real work, and the three cases agreeing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace linkage::test {

/// One case of `linkage simulate` at rtol = atol = 1e-12 (`more` flags after), sampled
/// every `every` s over `duration` s, as a table; a run that fails is a test failure.
inline Table simulate_tight(const std::string& file, int case_id, const std::string& columns, double duration,
                            double every, const std::vector<std::string>& more = {}) {
  std::vector<std::string> args{"simulate", "--mechanism", file,     "--case", std::to_string(case_id),
                                "--rtol",   "1e-12",       "--atol", "1e-12"};
  args.insert(args.end(), more.begin(), more.end());
  for (const std::string& a : {std::string("--duration"), std::to_string(duration), std::string("--every"),
                               std::to_string(every), std::string("--columns"), columns})
    args.push_back(a);
  const RunResult r = run_linkage(args);
  EXPECT_EQ(r.exit_code, 0) << file << " Case " << case_id << ": " << r.err;
  return parse_csv(r.out);
}

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

/// `tables` are one run's columns in Cases 1, 2 and 3 (t first): every other column of
/// Cases 1 and 2 equals Case 3's to `tolerance` at every row. Returns the largest |value|
/// of Case 3's column 1, for the caller to check it is not trivially small.
inline double expect_cases_agree(const std::vector<Table>& tables, double tolerance) {
  double largest = 0;
  const Table& three = tables.at(2);
  for (const std::vector<double>& row : three.rows) largest = std::max(largest, std::fabs(row.at(1)));
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(tables[k].rows.size(), three.rows.size()) << "Case " << k + 1;
    for (std::size_t i = 0; i < std::min(tables[k].rows.size(), three.rows.size()); ++i)
      for (std::size_t c = 1; c < three.columns.size(); ++c)
        EXPECT_NEAR(tables[k].rows[i][c], three.rows[i][c], tolerance)
            << "Case " << k + 1 << " against Case 3: " << three.columns[c] << " at t " << three.rows[i][0];
  }
  return largest;
}

}  // namespace linkage::test
