// Each printed symbolic entry, evaluated, equals the numeric entry: the ASCII spelling
// of symbolic_system() is parsed back (ascii_math.hpp) and evaluated at random states,
// then compared with solve_case()'s A and B. The same for the labelled equations the
// reports print, row by row: their left side at random unknowns must be (A u)_r.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "formulations/formulation.hpp"
#include "report/ascii_math.hpp"
#include "report/notation.hpp"
#include "report/random_inputs.hpp"
#include "report/text_layout.hpp"

namespace linkage {
namespace {

using test::random_samples;
using test::Sample;

std::map<std::string, double> entry_symbols(const Sample& x) {
  return {
      {"m", x.p.m},        {"I", x.p.inertia_centroidal()}, {"D", x.p.pin_offset()}, {"g", x.p.g}, {"th1", x.s.theta1},
      {"th2", x.s.theta2}, {"th1'", x.s.theta1_dot},        {"th2'", x.s.theta2_dot}};
}

// Round-off of one evaluation, relative to the size of the row it sits in.
double row_tolerance(const CaseSolution& c, Eigen::Index r) {
  return 8 * std::numeric_limits<double>::epsilon() * (c.A.row(r).cwiseAbs().sum() + std::fabs(c.B[r]) + 1);
}

TEST(SymbolicEntries, EveryPrintedEntryEvaluatesToTheNumericEntry) {
  int compared = 0;
  for (const Sample& x : random_samples(200, 20260521)) {
    test::AsciiMath math(entry_symbols(x));
    for (int id : kCaseIds) {
      const CaseSolution c = solve_case(id, x.p, x.s);
      const SymbolicSystem printed = symbolic_system(id, expr::Style::ascii);
      ASSERT_EQ(printed.A.size(), static_cast<std::size_t>(c.A.rows()));
      ASSERT_EQ(printed.B.size(), static_cast<std::size_t>(c.B.size()));
      for (Eigen::Index r = 0; r < c.A.rows(); ++r) {
        const auto row = static_cast<std::size_t>(r);
        ASSERT_EQ(printed.A[row].size(), static_cast<std::size_t>(c.A.cols()));
        for (Eigen::Index col = 0; col < c.A.cols(); ++col) {
          const std::string& entry = printed.A[row][static_cast<std::size_t>(col)];
          EXPECT_NEAR(math.eval(entry), c.A(r, col), row_tolerance(c, r))
              << "Case " << id << " A(" << r << ", " << col << ") = " << entry;
          ++compared;
        }
        EXPECT_NEAR(math.eval(printed.B[row]), c.B[r], row_tolerance(c, r))
            << "Case " << id << " B(" << r << ") = " << printed.B[row];
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 200 * (8 * 9 + 6 * 7 + 4 * 5));
}

TEST(SymbolicEntries, PrintedEquationsAreTheRowsOfAqEqualsB) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unknown(-3, 3);
  for (const Sample& x : random_samples(50, 20260522)) {
    for (int id : kCaseIds) {
      const CaseSolution c = solve_case(id, x.p, x.s);
      const SymbolicSystem printed = symbolic_system(id, expr::Style::ascii);
      std::map<std::string, double> symbols = entry_symbols(x);
      Eigen::VectorXd u(c.A.cols());
      for (std::size_t k = 0; k < c.unknowns.size(); ++k) {
        u[static_cast<Eigen::Index>(k)] = unknown(rng);
        symbols[std::string(info(c.unknowns[k]).ascii)] = u[static_cast<Eigen::Index>(k)];
      }
      test::AsciiMath math(symbols);
      const Eigen::VectorXd Au = c.A * u;
      for (Eigen::Index r = 0; r < c.A.rows(); ++r) {
        const auto row = static_cast<std::size_t>(r);
        const EquationSides eq = equation_sides(printed.A[row], printed.B[row], c.unknowns, expr::Style::ascii);
        const double scale = c.A.row(r).cwiseAbs().sum() * 3 + 1;
        EXPECT_NEAR(math.eval(strip_marks(eq.lhs)), Au[r], 16 * std::numeric_limits<double>::epsilon() * scale)
            << "Case " << id << " equation " << c.equations[row] << ": " << strip_marks(eq.lhs);
        EXPECT_NEAR(math.eval(eq.rhs), c.B[r], row_tolerance(c, r));
      }
    }
  }
}

TEST(SymbolicEntries, ParserRejectsWhatItDoesNotUnderstand) {
  test::AsciiMath math({{"m", 2.0}, {"th1'", 3.0}, {"I_zz^C", 5.0}});
  EXPECT_DOUBLE_EQ(math.eval("m th1'^2 - 1/m + I_zz^C (m + 1)"), 2 * 9 - 0.5 + 5 * 3);
  EXPECT_DOUBLE_EQ(math.eval("2 * (-0.5)^2 / 4 + cos(0) - 1.5e-1"), 0.125 + 1 - 0.15);
  EXPECT_THROW((void)math.eval("m D"), std::runtime_error);  // D is not bound
  EXPECT_THROW((void)math.eval("m +"), std::runtime_error);
  EXPECT_THROW((void)math.eval("(m"), std::runtime_error);
  EXPECT_THROW((void)math.eval("m^3"), std::runtime_error);
  EXPECT_THROW((void)math.eval("m ] 2"), std::runtime_error);
}

}  // namespace
}  // namespace linkage
