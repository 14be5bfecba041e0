// The exported cases (report/code_export.hpp): the Python file runs and prints the A, B
// and solution that solve_numbers computes from the same GiNaC entries, at the file's
// state and at other parameters, state and time; the MATLAB file (not run: no Octave
// here) has one function per case, balanced blocks and every name defined before use.
#include "report/code_export.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "core/number_format.hpp"
#include "report/code_printer.hpp"
#include "support/mechanisms_in_code.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

using built::q;

// A disc on a spring-damper from a ground point placed by a definition, driven by a force
// and a torque that change with t: its entries hold sqrt, tan, exp and divisions.
Mechanism sprung_disc() {
  Mechanism m;
  m.name = "sprung-disc";
  m.gravity = q("g");
  m.parameters = {{"r", 0.05, {}}, {"m", 0.2, {}},    {"k", 40, {}},    {"l0", 0.3, {}},
                  {"c", 0.4, {}},  {"F0", 0.5, {}},   {"Omega", 3, {}}, {"tau0", 0.02, {}},
                  {"T", 1.5, {}},  {"beta", 0.3, {}}, {"g", 9.81, {}}};
  m.definitions = {{"h", q("l0*tan(beta)"), {}}};
  m.ground_points = {{"O", {q("0"), q("h")}, {}}};
  m.bodies = {built::disc("1", "m", "r", {{"A", {"0", "r"}}})};
  m.springs = {built::spring("k1", "ground.O", "1.A", "k", "l0", "c")};
  m.forces = {{"1", "A", {q("F0*sin(Omega*t)"), q("0")}, {}}};
  m.torques = {{"1", q("tau0*exp(-t/T)"), {}}};
  m.initial = {{"1.x", 0.1, {}},     {"1.y", -0.35, {}},    {"1.theta", 0.2, {}},
               {"1.x_dot", 0.3, {}}, {"1.y_dot", -0.1, {}}, {"1.theta_dot", 0.5, {}}};
  return m;
}

// The homework, the three mechanisms beyond it, and ones with every kind of load.
const std::vector<built::Named> kMechanisms{
    {"homework", built::homework},
    {"double_pendulum", built::double_pendulum},
    {"four_bar", built::four_bar},
    {"slider_crank", built::slider_crank},
    {"double_pendulum_loaded", built::double_pendulum_loaded},
    {"four_bar_loaded", built::four_bar_loaded},
    {"cart_pendulum", built::cart_pendulum},
    {"driven_spring_pendulum",
     [] {
       Mechanism m = built::spring_pendulum(true);  // away from the spring's anchor
       m.initial = {{"1.x", 0.2, {}}, {"1.y", -0.4, {}}, {"1.x_dot", 0.5, {}}, {"1.y_dot", -0.3, {}}};
       return m;
     }},
    {"sprung_disc", sprung_disc},
};

std::string test_name(const testing::TestParamInfo<built::Named>& info) { return info.param.name; }

const std::vector<CaseId> kCases(kAllCases.begin(), kAllCases.end());

// ---------------------------------------------------------------- running Python

// The first of `python3` (PATH) and Debian's /usr/bin/python3 that imports NumPy.
std::optional<std::string> python_with_numpy() {
  for (const std::string candidate : {"python3", "/usr/bin/python3"})
    if (std::system((candidate + " -c 'import numpy' >/dev/null 2>&1").c_str()) == 0) return candidate;
  return std::nullopt;
}

std::string run(const std::string& command, int& status) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return {};
  std::string out;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  status = pclose(pipe);
  return out;
}

// One case as the demo prints it.
struct PrintedCase {
  std::string title;
  std::vector<std::string> labels;
  std::vector<std::vector<double>> A;
  std::vector<double> B;
  std::vector<std::string> unknowns;
  std::vector<double> solution;
};

std::vector<PrintedCase> parse_demo(const std::string& text) {
  std::vector<PrintedCase> cases;
  std::istringstream lines(text);
  std::string line;
  const std::regex row(R"(  \(([^)]*)\)  A = (.*) \| B = (\S+))");
  const std::regex value(R"(  (\w+) = (\S+))");
  std::smatch m;
  while (std::getline(lines, line)) {
    if (line.rfind("Case ", 0) == 0) {
      cases.push_back({line, {}, {}, {}, {}, {}});
    } else if (!cases.empty() && std::regex_match(line, m, row)) {
      cases.back().labels.push_back(m[1]);
      std::istringstream numbers(m[2]);
      std::vector<double> entries;
      for (std::string n; numbers >> n;) entries.push_back(std::stod(n));
      cases.back().A.push_back(entries);
      cases.back().B.push_back(std::stod(m[3]));
    } else if (!cases.empty() && std::regex_match(line, m, value)) {
      cases.back().unknowns.push_back(m[1]);
      cases.back().solution.push_back(std::stod(m[2]));
    } else {
      ADD_FAILURE() << "unexpected line in the demo's output: " << line;
    }
  }
  return cases;
}

// Each entry to 1e-12 of the larger of itself and its row's largest entry: the Python
// file evaluates the same terms in double precision, so it differs from the exact
// substitution by a few roundings of the row's largest term (a cancelling entry can be
// far smaller than its terms). The solution to 1e-12 of its largest component.
void expect_same(const PrintedCase& printed, const CaseSystem& c, const CaseNumbers& numbers,
                 const std::string& where) {
  SCOPED_TRACE(where + ", " + printed.title);
  EXPECT_EQ(printed.title, "Case " + std::to_string(case_number(c.id)) + ": " + c.title);
  EXPECT_EQ(printed.labels, c.labels);
  ASSERT_EQ(printed.A.size(), static_cast<std::size_t>(numbers.A.rows()));
  for (Eigen::Index i = 0; i < numbers.A.rows(); ++i) {
    const auto& row = printed.A[static_cast<std::size_t>(i)];
    ASSERT_EQ(row.size(), static_cast<std::size_t>(numbers.A.cols()));
    const double scale = std::max(numbers.A.row(i).cwiseAbs().maxCoeff(), std::abs(numbers.B(i)));
    for (Eigen::Index j = 0; j < numbers.A.cols(); ++j) {
      const double expected = numbers.A(i, j);
      EXPECT_NEAR(row[static_cast<std::size_t>(j)], expected, 1e-12 * std::max(std::abs(expected), scale))
          << "A(" << i << ", " << j << ") of (" << c.labels[static_cast<std::size_t>(i)] << ")";
    }
    EXPECT_NEAR(printed.B[static_cast<std::size_t>(i)], numbers.B(i), 1e-12 * scale)
        << "B of (" << c.labels[static_cast<std::size_t>(i)] << ")";
  }
  ASSERT_EQ(printed.solution.size(), static_cast<std::size_t>(numbers.solution.size()));
  const double largest = numbers.solution.cwiseAbs().maxCoeff();
  for (Eigen::Index j = 0; j < numbers.solution.size(); ++j)
    EXPECT_NEAR(printed.solution[static_cast<std::size_t>(j)], numbers.solution(j), 1e-12 * largest)
        << printed.unknowns[static_cast<std::size_t>(j)];
}

std::string python_list(const std::vector<double>& values) {
  std::string out = "[";
  for (double v : values) out += (out.size() > 1 ? ", " : "") + format_roundtrip(v);
  return out + "]";
}

// Elsewhere: every parameter, coordinate and rate of the file's state moved, at t = 0.7.
struct Elsewhere {
  std::vector<double> parameters, q, qd;
  double t = 0.7;
  std::unique_ptr<sym::System> system;
  GiNaC::exmap values;
};

Elsewhere elsewhere(const Mechanism& mechanism, const MechanismSolution& s) {
  Elsewhere e;
  Mechanism other = mechanism;
  for (std::size_t i = 0; i < other.parameters.size(); ++i) {
    other.parameters[i].value *= 1 + 0.03 * static_cast<double>(i + 1);
    e.parameters.push_back(other.parameters[i].value);
  }
  other.initial.clear();
  for (std::size_t k = 0; k < s.system->coordinates().size(); ++k) {
    const sym::GeneralizedCoordinate& g = s.system->coordinates()[k];
    e.q.push_back(sym::to_double(s.state.at(g.symbols.q)) + 0.05 * static_cast<double>(k + 1));
    e.qd.push_back(sym::to_double(s.state.at(g.symbols.q_dot)) + 0.1 * static_cast<double>(k + 1) - 0.2);
    other.initial.push_back({g.coordinate.key, e.q.back(), {}});
    other.initial.push_back({g.coordinate.key + "_dot", e.qd.back(), {}});
  }
  e.system = std::make_unique<sym::System>(other);
  e.values = state_values(*e.system, e.system->initial_state(), e.t);
  return e;
}

// Exports `mechanism`, runs the file's demo at its state and at other parameters, state
// and time (appended to the file), and compares both with solve_numbers.
void expect_python_agrees(const Mechanism& mechanism) {
  const auto python = python_with_numpy();
  if (!python)
    GTEST_SKIP() << "no python3 with NumPy (tried python3 and /usr/bin/python3); "
                    "./scripts/install-deps --tests installs python3-numpy";
  const MechanismSolution s = work_out_mechanism(mechanism, kCases);

  // Elsewhere: every parameter, coordinate and rate moved, at t = 0.7.
  const Elsewhere e = elsewhere(mechanism, s);
  const std::vector<double>&parameters = e.parameters, &q = e.q, &qd = e.qd;
  const double t = e.t;
  const sym::System& other_system = *e.system;
  const GiNaC::exmap& other_values = e.values;

  const test::TempDir dir;
  const auto file = dir / (export_stem(s) + ".py");
  test::write_text(file, python_export(s) + "\ndemo(dict(zip(PARAMETERS, " + python_list(parameters) + ")), " +
                             python_list(q) + ", " + python_list(qd) + ", " + format_roundtrip(t) + ")\n");
  int status = -1;
  const std::string out = run(*python + " '" + file.string() + "'", status);
  ASSERT_EQ(status, 0) << out;
  const std::vector<PrintedCase> printed = parse_demo(out);
  ASSERT_EQ(printed.size(), 2 * s.cases.size()) << out;
  for (std::size_t k = 0; k < s.cases.size(); ++k) {
    expect_same(printed[k], s.cases[k].system, s.cases[k].numbers, "at the file's state");
    const CaseSystem c = derive_case(other_system, s.cases[k].system.id);
    expect_same(printed[s.cases.size() + k], c, solve_numbers(c, other_values), "elsewhere");
  }
}

// ---------------------------------------------------------------- running MATLAB (GNU Octave)

// The MATLAB file run by GNU Octave (octave-cli): its demo at the file's state, and at
// other parameters, state and time through the model's functions, compared with
// solve_numbers as the Python file is.
void expect_matlab_agrees(const Mechanism& mechanism) {
  if (std::system("octave-cli --version >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "no octave-cli; ./scripts/install-deps --tests installs octave";
  const MechanismSolution s = work_out_mechanism(mechanism, kCases);
  const Elsewhere e = elsewhere(mechanism, s);
  const std::vector<double>&parameters = e.parameters, &q = e.q, &qd = e.qd;
  const double t = e.t;
  const sym::System& other_system = *e.system;
  const GiNaC::exmap& other_values = e.values;

  const test::TempDir dir;
  const std::string stem = export_stem(s);
  test::write_text(dir / (stem + ".m"), matlab_export(s));
  auto column = [](const std::vector<double>& v) {
    std::string out = "[";
    for (double x : v) out += (out.size() > 1 ? "; " : "") + format_roundtrip(x);
    return out + "]";
  };
  // parameters() lists the fields in the file's order.
  std::string row = "[";
  for (double x : parameters) row += (row.size() > 1 ? " " : "") + format_roundtrip(x);
  row += "]";
  const std::string script = stem + "; m = " + stem + "(); p = m.parameters(); f = fieldnames(p); v = " + row +
                             "; for i = 1:numel(f), p.(f{i}) = v(i); end; m.demo(p, " + column(q) + ", " + column(qd) +
                             ", " + format_roundtrip(t) + ")";
  int status = -1;
  const auto errors = dir / "stderr.txt";
  const std::string out = run("(cd '" + dir.path().string() + "' && octave-cli --no-gui --quiet --norc --eval '" +
                                  script + "' 2>'" + errors.string() + "')",
                              status);
  ASSERT_EQ(status, 0) << out << test::read_text(errors);
  // Octave 7 says this on its way out when its output is not a terminal, after a
  // successful run (exit status 0); anything else on stderr is a fault of the file.
  std::istringstream error_lines(test::read_text(errors));
  for (std::string line; std::getline(error_lines, line);)
    EXPECT_EQ(line, "error: ignoring const execution_exception& while preparing to exit");
  const std::vector<PrintedCase> printed = parse_demo(out);
  ASSERT_EQ(printed.size(), 2 * s.cases.size()) << out;
  for (std::size_t k = 0; k < s.cases.size(); ++k) {
    expect_same(printed[k], s.cases[k].system, s.cases[k].numbers, "at the file's state (Octave)");
    const CaseSystem c = derive_case(other_system, s.cases[k].system.id);
    expect_same(printed[s.cases.size() + k], c, solve_numbers(c, other_values), "elsewhere (Octave)");
  }
}

class CodeExportOf : public testing::TestWithParam<built::Named> {};

TEST_P(CodeExportOf, PythonAgreesWithSolve) { expect_python_agrees(GetParam().make()); }
TEST_P(CodeExportOf, MatlabRunsInOctaveAndAgreesWithSolve) { expect_matlab_agrees(GetParam().make()); }

// ---------------------------------------------------------------- MATLAB structure

const std::set<std::string> kMatlabKeywords{"function", "if",     "else", "elseif", "end",   "for",
                                            "while",    "switch", "case", "try",    "catch", "return"};
const std::set<std::string> kMatlabOpeners{"function", "if", "for", "while", "switch", "try"};
const std::set<std::string> kMatlabBuiltins{"zeros", "sqrt", "sin",   "cos",     "tan",    "exp",    "log",
                                            "abs",   "pi",   "numel", "fprintf", "nargin", "nargout"};

// A line without its comment and with every string literal emptied.
std::string code_of(const std::string& line) {
  std::string out;
  bool in_string = false;
  for (char c : line) {
    if (c == '\'') {
      in_string = !in_string;
      out += c;
    } else if (!in_string && c == '%') {
      break;
    } else if (!in_string) {
      out += c;
    }
  }
  return out;
}

struct Token {
  std::string name;
  bool field = false;  // after a '.', a struct field
};

std::vector<Token> identifiers(const std::string& code) {
  std::vector<Token> out;
  const std::regex word(R"([A-Za-z_]\w*)");
  for (auto it = std::sregex_iterator(code.begin(), code.end(), word); it != std::sregex_iterator(); ++it) {
    const auto at = static_cast<std::size_t>(it->position());
    // A number's exponent (1e-05) is not a name.
    if (at > 0 && std::isdigit(static_cast<unsigned char>(code[at - 1])) != 0) continue;
    out.push_back({it->str(), at > 0 && code[at - 1] == '.'});
  }
  return out;
}

// Checks the file's block structure and that every name a function reads is a
// parameter of it, assigned on an earlier line, a local function or a builtin. Returns
// the local functions by name.
std::set<std::string> check_matlab(const std::string& text) {
  std::set<std::string> functions;
  const std::regex header(R"(function\s+(?:(?:\[[^\]]*\]|\w+)\s*=\s*)?(\w+)\s*\(([^)]*)\))");
  std::istringstream lines(text);
  std::vector<std::string> codes;
  for (std::string line; std::getline(lines, line);) codes.push_back(code_of(line));
  for (const std::string& code : codes) {
    std::smatch m;
    if (std::regex_search(code, m, header)) {
      EXPECT_TRUE(functions.insert(m[1]).second) << "twice: " << m[1];
    }
  }

  int depth = 0;
  std::set<std::string> defined;
  std::size_t number = 0;
  for (const std::string& code : codes) {
    ++number;
    SCOPED_TRACE("line " + std::to_string(number) + ": " + code);
    const std::vector<Token> tokens = identifiers(code);
    std::smatch m;
    if (std::regex_search(code, m, header)) {
      EXPECT_EQ(depth, 0) << "a function inside another";
      defined.clear();
      const std::regex name(R"(\w+)");
      const std::string params = m[2];
      for (auto it = std::sregex_iterator(params.begin(), params.end(), name); it != std::sregex_iterator(); ++it)
        defined.insert(it->str());
      const std::string outputs = code.substr(0, code.find('='));
      for (const Token& t : identifiers(outputs))
        if (t.name != "function") defined.insert(t.name);  // assigned in the body; read after
      ++depth;
      continue;
    }
    for (const Token& t : tokens) {
      if (t.field) continue;
      if (kMatlabOpeners.count(t.name) != 0) ++depth;
      if (t.name == "end") {
        --depth;
        EXPECT_GE(depth, 0) << "an end without a block";
      }
    }
    // Left side: names assigned (NAME = or [A, B] = or NAME(i) = or for NAME =).
    std::set<std::string> assigned;
    const std::regex assignment(R"(^\s*(?:for\s+)?(\[[^\]]*\]|\w+)(?:\.\w+)*\s*(\([^=]*\))?\s*=[^=])");
    std::string right = code;
    if (std::regex_search(code, m, assignment)) {
      for (const Token& t : identifiers(m[1])) assigned.insert(t.name);
      right = m[2].str() + " " + code.substr(static_cast<std::size_t>(m.length(0)) - 1);
      if (m[2].matched) {
        for (const std::string& name : assigned) {
          EXPECT_EQ(defined.count(name), 1u) << name << " indexed before it is made";
        }
      }
    }
    for (const Token& t : identifiers(right)) {
      if (t.field || kMatlabKeywords.count(t.name) != 0 || kMatlabBuiltins.count(t.name) != 0) continue;
      EXPECT_TRUE(defined.count(t.name) != 0 || functions.count(t.name) != 0) << t.name << " used before it is defined";
    }
    defined.insert(assigned.begin(), assigned.end());
  }
  EXPECT_EQ(depth, 0) << "unbalanced blocks";
  return functions;
}

void expect_matlab_structure(const Mechanism& mechanism) {
  const MechanismSolution s = work_out_mechanism(mechanism, kCases);
  const std::string text = matlab_export(s);
  SCOPED_TRACE(mechanism.name);
  EXPECT_EQ(text.substr(0, text.find('\n')), "function varargout = " + export_stem(s) + "()");
  const std::set<std::string> functions = check_matlab(text);
  for (CaseId id : kAllCases) {
    const std::string name = "case" + std::to_string(case_number(id));
    EXPECT_EQ(functions.count(name), 1u) << name;
    // Every case has its A and B filled row by row, labelled.
    const CaseSystem& c = s.cases[static_cast<std::size_t>(case_number(id) - 1)].system;
    for (const std::string& label : c.labels) EXPECT_NE(text.find("% (" + label + ")\n"), std::string::npos) << label;
  }
  EXPECT_EQ(functions, (std::set<std::string>{export_stem(s), "parameters", "state", "case1", "case2", "case3", "demo",
                                              "print_case"}));
  // What the case functions read from p is what parameters() sets.
  std::set<std::string> set, read;
  const std::regex set_field(R"(\np\.(\w+) = )"), read_field(R"(= p\.(\w+);)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), set_field); it != std::sregex_iterator(); ++it)
    set.insert((*it)[1]);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), read_field); it != std::sregex_iterator(); ++it)
    read.insert((*it)[1]);
  EXPECT_EQ(read, set);
  EXPECT_EQ(set.size(), mechanism.parameters.size());
}

TEST_P(CodeExportOf, MatlabIsWellFormed) { expect_matlab_structure(GetParam().make()); }

INSTANTIATE_TEST_SUITE_P(Mechanisms, CodeExportOf, testing::ValuesIn(kMechanisms), test_name);

// The structure check itself catches a name read before it is assigned and a missing end.
TEST(CodeExport, MatlabCheckCatchesFaults) {
  EXPECT_NONFATAL_FAILURE(check_matlab("function y = f(x)\ny = x + z;\nend\n"), "z used before it is defined");
  EXPECT_NONFATAL_FAILURE(check_matlab("function y = f(x)\nif x\ny = 1;\nend\n"), "unbalanced blocks");
}

// ---------------------------------------------------------------- the printer and names

TEST(CodeExport, PrinterSpellsEachLanguage) {
  sym::SymbolTable table;
  const GiNaC::symbol L = table.add({GiNaC::symbol("L"), sym::Role::parameter, "L", "L", "L", "L", "", ""}).symbol;
  const GiNaC::symbol m = table.add({GiNaC::symbol("m"), sym::Role::parameter, "m", "m", "m", "m", "", ""}).symbol;
  const GiNaC::symbol th =
      table.add({GiNaC::symbol("1.theta"), sym::Role::coordinate, "1.theta", "", "", "", "rad", ""}).symbol;
  const std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> names{{L, "L"}, {m, "m"}, {th, "theta_1"}};
  const CodePrinter python(CodeLanguage::python, table, names);
  const CodePrinter matlab(CodeLanguage::matlab, table, names);
  const GiNaC::ex inertia = m * (GiNaC::pow(L, 2) + GiNaC::numeric(1, 100)) / 12;
  // GiNaC keeps a sum factor with integer coefficients: (1/100 + L^2)/12 is (1 + 100 L^2)/1200.
  EXPECT_EQ(python(inertia), "m*(1 + 100*L**2)/1200");
  EXPECT_EQ(matlab(inertia), "m*(1 + 100*L.^2)/1200");
  const GiNaC::ex moment = -GiNaC::numeric(3, 2) * m * L * GiNaC::cos(th) + GiNaC::sqrt(L) / m;
  EXPECT_EQ(python(moment), "np.sqrt(L)/m - 3*L*m*np.cos(theta_1)/2");
  EXPECT_EQ(matlab(moment), "sqrt(L)/m - 3*L*m*cos(theta_1)/2");
  const GiNaC::ex mixed = GiNaC::pow(L, -GiNaC::numeric(1, 2)) * GiNaC::Pi * GiNaC::pow(th, GiNaC::numeric(3, 2));
  EXPECT_EQ(python(mixed), "np.pi*theta_1**(3/2)/np.sqrt(L)");
  EXPECT_EQ(matlab(mixed), "pi*theta_1.^(3/2)/sqrt(L)");
  EXPECT_EQ(python(GiNaC::numeric("0.08") * m - 2), "0.08*m - 2");
  // The file's decimals are read as fractions and print as decimals; other fractions stay.
  EXPECT_EQ(python(GiNaC::numeric(2, 25) * m - GiNaC::numeric(3, 10)), "0.08*m - 0.3");
  EXPECT_EQ(matlab(GiNaC::numeric(89, 120000) * m + GiNaC::numeric(1, 2) * L), "89*m/120000 + L/2");
  EXPECT_EQ(matlab(GiNaC::numeric("1e-5") * L + GiNaC::numeric("-2.5e3") * m), "1e-05*L - 2500*m");
  // A sum factor prints with the sign its text prefers, whichever GiNaC chose.
  EXPECT_EQ(python(GiNaC::pow(m - L, 2) * GiNaC::pow(L + m, -2)), "(L - m)**2/(L + m)**2");
  EXPECT_EQ(python(GiNaC::pow(L - m, 2) * GiNaC::pow(L + m, -2)), "(L - m)**2/(L + m)**2");
  EXPECT_EQ(python(GiNaC::pow(m - L, 3) * L), "-L*(L - m)**3");
  EXPECT_EQ(python(-GiNaC::pow(L - m, 3) * L), "-L*(L - m)**3");
  EXPECT_EQ(matlab(GiNaC::pow(m - L, -3)), "-1/(L - m).^3");
  EXPECT_EQ(python(m * (m - L) * GiNaC::cos(th)), "-m*np.cos(theta_1)*(L - m)");
  EXPECT_THROW((void)python(GiNaC::symbol("stray")), std::logic_error);
}

TEST(CodeExport, KeysBecomeIdentifiers) {
  EXPECT_EQ(code_identifier("L"), "L");
  EXPECT_EQ(code_identifier("1.theta"), "theta_1");
  EXPECT_EQ(code_identifier("1.theta_dot"), "theta_1_dot");
  EXPECT_EQ(code_identifier("crank.x_ddot"), "x_crank_ddot");
  EXPECT_EQ(code_identifier("P.force_x"), "force_P_x");
  EXPECT_EQ(code_identifier("s.s"), "s_s");
  EXPECT_EQ(code_identifier("1.inertia"), "inertia_1");
  EXPECT_EQ(code_identifier("left-arm.theta"), "theta_left_arm");
}

// A parameter named like a keyword or a name the file uses itself gets a trailing _.
TEST(CodeExport, ClashingNamesAreRenamed) {
  Mechanism m = built::double_pendulum();
  m.parameters.push_back({"lambda", 0.5, {}});
  m.parameters.push_back({"end", 0.5, {}});
  const MechanismSolution s = work_out_mechanism(m, {CaseId::reduced});
  const std::string python = python_export(s);
  EXPECT_NE(python.find("    lambda_ = p[\"lambda_\"]\n"), std::string::npos);
  EXPECT_NE(python.find("    end = p[\"end\"]\n"), std::string::npos);
  const std::string matlab = matlab_export(s);
  EXPECT_NE(matlab.find("\nend_ = p.end_;\n"), std::string::npos);
  EXPECT_NE(matlab.find("\nlambda = p.lambda;\n"), std::string::npos);
  check_matlab(matlab);
}

// The same mechanism exports the same bytes from a second, independent derivation (its
// GiNaC symbols are new, so GiNaC's own term order may differ).
TEST(CodeExport, OutputIsDeterministic) {
  for (const built::Named& named : kMechanisms) {
    const Mechanism m = named.make();
    const MechanismSolution first = work_out_mechanism(m, kCases);
    const MechanismSolution second = work_out_mechanism(m, kCases);
    EXPECT_TRUE(python_export(first) == python_export(second)) << named.name << ": the Python files differ";
    EXPECT_TRUE(matlab_export(first) == matlab_export(second)) << named.name << ": the MATLAB files differ";
  }
}

// Only the selected cases are exported.
TEST(CodeExport, OneCaseExportsOneFunction) {
  const MechanismSolution s = work_out_mechanism(built::homework(), {CaseId::generalized});
  const std::string python = python_export(s);
  EXPECT_NE(python.find("\ndef case2("), std::string::npos);
  EXPECT_EQ(python.find("\ndef case1("), std::string::npos);
  EXPECT_EQ(python.find("\ndef case3("), std::string::npos);
  EXPECT_EQ(check_matlab(matlab_export(s)),
            (std::set<std::string>{"two_blocks", "parameters", "state", "case2", "demo", "print_case"}));
}

}  // namespace
}  // namespace linkage
