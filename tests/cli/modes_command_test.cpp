// `linkage modes`: the JSON contract of issue 26 (equilibrium, coordinates, M, C, K, modes
// by increasing frequency, stable), the text's sections, each body's motion through a
// loop, the Markdown's numbers against the JSON's, an unstable equilibrium's growth rates,
// and bad input in one line (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <sstream>

#include "support/test_support.hpp"

namespace linkage {
namespace {

void expect_one_line_error(const test::RunResult& r, const std::vector<std::string>& pieces) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const std::string& piece : pieces) EXPECT_NE(r.err.find(piece), std::string::npos) << piece << "\n" << r.err;
}

nlohmann::json modes_json(const std::vector<std::string>& more) {
  std::vector<std::string> args{"modes", "--format", "json"};
  args.insert(args.end(), more.begin(), more.end());
  const test::RunResult r = test::run_linkage(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(ModesCommand, JsonFollowsTheContract) {
  const nlohmann::json j = modes_json({"--mechanism", "double-pendulum"});
  EXPECT_EQ(j["mechanism"], "double-pendulum");
  EXPECT_NEAR(j["equilibrium"]["1.theta"].get<double>(), -std::numbers::pi / 2, 1e-13);
  EXPECT_NEAR(j["equilibrium"]["2.theta"].get<double>(), -std::numbers::pi / 2, 1e-13);
  EXPECT_EQ(j["coordinates"], nlohmann::json({"1.theta", "2.theta"}));
  for (const char* key : {"M", "C", "K"}) {
    ASSERT_EQ(j[key].size(), 2U) << key;
    ASSERT_EQ(j[key][0].size(), 2U) << key;
  }
  EXPECT_TRUE(j["stable"].get<bool>());
  ASSERT_EQ(j["modes"].size(), 2U);
  double last = 0;
  for (const auto& mode : j["modes"]) {
    const double omega = mode["omega"].get<double>();
    EXPECT_GT(omega, last);  // increasing
    last = omega;
    EXPECT_NEAR(mode["frequency_hz"].get<double>() * 2 * std::numbers::pi / omega, 1, 1e-15);
    EXPECT_EQ(mode["damping_ratio"].get<double>(), 0);
    double largest = 0;
    for (const auto& [name, value] : mode["shape"].items()) largest = std::max(largest, std::fabs(value.get<double>()));
    EXPECT_EQ(largest, 1.0);
    // omega^2 M v = K v with the printed matrices, to their round-trip digits.
    for (std::size_t i = 0; i < 2; ++i) {
      double mv = 0, kv = 0;
      const std::array<std::string, 2> names{"1.theta", "2.theta"};
      for (std::size_t c = 0; c < 2; ++c) {
        mv += j["M"][i][c].get<double>() * mode["shape"][names[c]].get<double>();
        kv += j["K"][i][c].get<double>() * mode["shape"][names[c]].get<double>();
      }
      EXPECT_NEAR(omega * omega * mv, kv, 1e-12 * std::fabs(kv) + 1e-15);
    }
  }
}

TEST(ModesCommand, AnUprightPendulumIsUnstableWithGrowthRatesNotFrequencies) {
  const nlohmann::json j =
      modes_json({"--mechanism", "double-pendulum", "--set", "1.theta=1.4", "--set", "2.theta=1.7"});
  EXPECT_FALSE(j["stable"].get<bool>());
  for (const auto& mode : j["modes"]) {
    EXPECT_EQ(mode["kind"], "unstable");
    EXPECT_GT(mode["growth_rate"].get<double>(), 0);
    EXPECT_FALSE(mode.contains("omega"));
    EXPECT_FALSE(mode.contains("frequency_hz"));
  }
}

TEST(ModesCommand, TextShowsTheEquilibriumTheExpansionTheMatricesAndTheModes) {
  const test::RunResult r = test::run_linkage({"modes", "--mechanism", "four-bar", "--set", "2.theta=-1.5", "--ascii"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string& piece : {std::string("1. The equilibrium\n"), std::string("2. The expansion\n"),
                                   std::string("3. The linearized equations M z'' + C z' + K z = 0\n"),
                                   std::string("4. The modes"), std::string("independent coordinates z = (2.theta)"),
                                   std::string("The equilibrium is stable"), std::string("oscillation")})
    EXPECT_NE(r.out.find(piece), std::string::npos) << piece << "\n" << r.out;
  for (const std::string& line : test::lines_of(r.out)) EXPECT_LE(line.size(), 80U) << line;
}

TEST(ModesCommand, VerifyComparesEachModeWithTheMotion) {
  const nlohmann::json j = modes_json({"--mechanism", "double-pendulum", "--verify"});
  ASSERT_EQ(j["verify"].size(), 2U);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& check = j["verify"][k];
    EXPECT_EQ(check["mode"], k + 1);
    EXPECT_EQ(check["predicted"], j["modes"][k]["omega"]);
    EXPECT_LE(check["relative_error"].get<double>(), 1e-5);
  }
  const test::RunResult r = test::run_linkage({"modes", "--mechanism", "double-pendulum", "--verify", "--ascii"});
  EXPECT_NE(r.out.find("5. The check: the full equations"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Every mode agrees with the motion to 1e-05."), std::string::npos) << r.out;
}

TEST(ModesCommand, ThroughALoopTheTextShowsEachBodysMotion) {
  const nlohmann::json j = modes_json({"--mechanism", "four-bar-spring"});
  const test::RunResult r = test::run_linkage({"modes", "--mechanism", "four-bar-spring", "--ascii"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t at = r.out.find("Each body's motion: the mode in every coordinate of the spanning tree");
  ASSERT_NE(at, std::string::npos) << r.out;
  // "mode 1  1  -0.502522  -0.447905": R v scaled to its largest component, as the JSON's tree_shape.
  const auto& tree = j["modes"][0]["tree_shape"];
  double largest = 0;
  for (const auto& [name, v] : tree.items()) largest = std::max(largest, std::fabs(v.get<double>()));
  std::string row = "  mode 1";
  for (const auto& [name, v] : tree.items()) {
    std::ostringstream number;
    number.precision(6);
    number << v.get<double>() / largest;
    row += " +";
    row += std::regex_replace(number.str(), std::regex(R"(\.)"), R"(\.)");
  }
  EXPECT_TRUE(std::regex_search(r.out.substr(at), std::regex(row + "\n"))) << row << "\n" << r.out;
  // A tree without loops: the shapes are the bodies' motion already, printed once.
  const test::RunResult tree_only = test::run_linkage({"modes", "--mechanism", "double-pendulum", "--ascii"});
  EXPECT_EQ(tree_only.out.find("Each body's motion"), std::string::npos) << tree_only.out;
}

// A number as the Markdown prints it: plain ("-1.5e-05") in tables and prose, LaTeX
// ("-1.5 \times 10^{-5}") in the matrices.
double printed_number(std::string text) {
  const std::smatch m = [&] {
    std::smatch found;
    std::regex_match(text, found, std::regex(R"((-?[0-9.]+)?(?: \\times )?(-?)10\^\{(-?[0-9]+)\})"));
    return found;
  }();
  if (m.empty()) return std::stod(text);
  const double mantissa = m[1].matched ? std::stod(m[1]) : (m[2].length() > 0 ? -1.0 : 1.0);
  return mantissa * std::pow(10.0, std::stod(m[3]));
}

// `printed` is `value` to `digits` significant digits: within half a unit of the last.
void expect_printed(const std::string& printed, double value, int digits, const std::string& what) {
  const double p = printed_number(printed);
  const double unit = value == 0 ? 0 : std::pow(10.0, std::floor(std::log10(std::fabs(value))) - (digits - 1));
  EXPECT_LE(std::fabs(p - value), 0.5 * unit * (1 + 1e-9) + 1e-300)
      << what << ": printed " << printed << ", JSON " << value;
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line.substr(1));
  while (std::getline(in, cell, '|')) {
    const std::size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
    cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
  }
  return cells;
}

// Every number of the Markdown against the JSON's: the residual, the equilibrium, M, C and
// K, each mode's omega, f, period, damping ratio or growth rate and shape, each body's
// motion, and R (through R v = tree_shape); counts what it checked.
std::size_t check_markdown_against_json(const std::vector<std::string>& args) {
  std::vector<std::string> markdown_args{"modes"};
  markdown_args.insert(markdown_args.end(), args.begin(), args.end());
  markdown_args.insert(markdown_args.end(), {"--format", "markdown"});
  const test::RunResult md = test::run_linkage(markdown_args);
  EXPECT_EQ(md.exit_code, 0) << md.err;
  const nlohmann::json j = modes_json(args);
  const std::vector<std::string> lines = test::lines_of(md.out);
  const std::vector<std::string> coordinates = j["coordinates"];
  std::size_t checked = 0;
  std::smatch m;
  if (std::regex_search(md.out, m, std::regex(R"(left is ([^ ]+) \(N or N m\))"))) {
    expect_printed(m[1], j["residual"], 3, "residual");
    ++checked;
  }
  std::vector<std::string> header;
  std::vector<std::vector<double>> R;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    // "NAME =" and its rows, or R's "dq = R dz" with the rows of the tree coordinates (its
    // "=" written "{}=", not a Markdown heading's underline).
    const bool named = line == "$$" && i + 2 < lines.size() && lines[i + 2] == "\\begin{bmatrix}";
    const bool reduction = line == "$$" && i + 3 < lines.size() && lines[i + 2] == "{}=";
    if (named || reduction) {
      const std::string name = reduction ? "R" : lines[i + 1].substr(0, lines[i + 1].find(' '));
      std::vector<std::vector<double>> rows;
      for (std::size_t k = i + (reduction ? 4 : 3); k < lines.size() && lines[k] != "\\end{bmatrix}"; ++k) {
        rows.emplace_back();
        std::string row = lines[k];
        row = row.substr(0, row.find(" \\\\"));
        std::istringstream entries(row);
        for (std::string entry; std::getline(entries, entry, '&');) {
          entry = entry.substr(entry.find_first_not_of(' '));
          entry = entry.substr(0, entry.find_last_not_of(' ') + 1);
          if (name == "R") {
            rows.back().push_back(printed_number(entry));
            continue;
          }
          const std::size_t r = rows.size() - 1, c = rows.back().size();
          expect_printed(entry, j[name][r][c], 6, name);
          rows.back().push_back(0);
          ++checked;
        }
      }
      if (name == "R") R = rows;
      continue;
    }
    if (!line.starts_with("| ")) continue;
    const std::vector<std::string> cells = cells_of(line);
    if (i + 1 < lines.size() && lines[i + 1].starts_with("| :--")) {
      header = cells;
      continue;
    }
    if (cells.size() == 4 && j["equilibrium"].contains(cells[1])) {
      expect_printed(cells[2], j["equilibrium"][cells[1]], 6, cells[1]);
      ++checked;
      continue;
    }
    if (!cells[0].starts_with("mode ")) continue;
    const auto& mode = j["modes"][std::stoul(cells[0].substr(5)) - 1];
    if (cells[1] == mode["kind"]) {  // the modes table
      for (std::size_t c = 2; c < cells.size(); ++c) {
        const std::string& h = header[c];
        const std::size_t shape = cells.size() - coordinates.size();
        if (cells[c] == "-") continue;
        if (c >= shape)
          expect_printed(cells[c], mode["shape"][coordinates[c - shape]], 6, "shape");
        else if (h.starts_with("$\\omega$"))
          expect_printed(cells[c], mode["omega"], 6, h);
        else if (h.starts_with("$f$"))
          expect_printed(cells[c], mode["frequency_hz"], 6, h);
        else if (h.starts_with("$T$"))
          expect_printed(cells[c], 2 * std::numbers::pi / mode["omega"].get<double>(), 6, h);
        else if (h.starts_with("$\\zeta$"))
          expect_printed(cells[c], mode["damping_ratio"], 6, h);
        else if (h.starts_with("$\\sigma$"))
          expect_printed(cells[c], mode["growth_rate"], 6, h);
        else
          ADD_FAILURE() << "unknown column " << h;
        ++checked;
      }
    } else {  // each body's motion: the tree shape scaled to its largest component
      double largest = 0;
      for (const auto& [name, v] : mode["tree_shape"].items()) largest = std::max(largest, std::fabs(v.get<double>()));
      std::size_t c = 1;
      for (const auto& [name, v] : mode["tree_shape"].items()) {
        expect_printed(cells[c++], v.get<double>() / largest, 6, "tree shape " + name);
        ++checked;
      }
    }
  }
  // R v = tree_shape, to R's printed digits.
  for (const auto& mode : j["modes"]) {
    if (R.empty()) break;
    std::size_t i = 0;
    for (const auto& [name, v] : mode["tree_shape"].items()) {
      double Rv = 0;
      for (std::size_t k = 0; k < coordinates.size(); ++k) Rv += R[i][k] * mode["shape"][coordinates[k]].get<double>();
      EXPECT_NEAR(Rv, v.get<double>(), 1e-5 * (1 + std::fabs(v.get<double>()))) << "R v, " << name;
      ++i;
      ++checked;
    }
  }
  return checked;
}

TEST(ModesCommand, EveryNumberOfTheMarkdownIsTheJsonsToThePrintedDigits) {
  // Hanging: residual 1, equilibrium 2, M and K 8, modes 2 x 5.
  EXPECT_EQ(check_markdown_against_json({"--mechanism", "double-pendulum"}), 21U);
  // Through a loop: residual, equilibrium 3, R (through R v), M and K, mode 1 (4), body motion 3.
  EXPECT_EQ(check_markdown_against_json({"--mechanism", "four-bar-spring"}), 1U + 3 + 2 + 4 + 3 + 3);
  // Upright: growth rates instead of frequencies (modes 2 x 3).
  EXPECT_EQ(
      check_markdown_against_json({"--mechanism", "double-pendulum", "--set", "1.theta=1.4", "--set", "2.theta=1.7"}),
      17U);
  // Damped, with a neutral mode: residual, equilibrium 3, M, C, K 27, the neutral mode's shape 3, two
  // oscillations 2 x 7.
  EXPECT_EQ(check_markdown_against_json({"--mechanism", "spring-pendulum"}), 48U);
}

TEST(ModesCommand, LatexAndMarkdownHoldTheTextsSectionsInMath) {
  const test::RunResult tex = test::run_linkage({"modes", "--mechanism", "four-bar-spring", "--format", "latex"});
  ASSERT_EQ(tex.exit_code, 0) << tex.err;
  for (const std::string& piece :
       {std::string("\\textbf{1. The equilibrium.}"), std::string("\\textbf{2. The expansion.}"),
        std::string("K_0[\\theta_4, \\theta_4] &= k - "), std::string("\\begin{bmatrix} \\delta\\theta_2 \\\\ "),
        std::string("\\textbf{3. The linearized equations $M \\ddot z + C \\dot z + K z = 0$.}"),
        std::string("$\\omega$ (rad/s) & $f$ (Hz) & $T$ (s)"), std::string("Each body's motion")})
    EXPECT_NE(tex.out.find(piece), std::string::npos) << piece << "\n" << tex.out;
  // No Unicode: the expressions through the LaTeX printer.
  for (unsigned char c : tex.out) EXPECT_LT(c, 0x80) << tex.out;
}

TEST(ModesCommand, BadInputIsOneLine) {
  expect_one_line_error(test::run_linkage({"modes"}), {"--mechanism", "double-pendulum"});
  expect_one_line_error(test::run_linkage({"modes", "--mechanism", "double-pendulum", "--format", "csv"}),
                        {"--format", "csv", "text, latex, markdown, json"});
  expect_one_line_error(test::run_linkage({"modes", "--mechanism", "engine"}), {"engine.toml:", "moves with t"});
  expect_one_line_error(test::run_linkage({"modes", "--mechanism", "two-blocks"}), {"no equilibrium"});
  expect_one_line_error(test::run_linkage({"modes", "--mechanism", "double-pendulum", "--digits", "0"}),
                        {"--digits", "1 to 17"});
}

}  // namespace
}  // namespace linkage
