#include "report/code_export.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/number_format.hpp"
#include "report/code_printer.hpp"

namespace linkage {

namespace {

using Names = std::map<GiNaC::ex, std::string, GiNaC::ex_is_less>;

// Keywords, and the names the generated code uses itself: a symbol never takes them.
const std::set<std::string>& reserved(CodeLanguage language) {
  static const std::set<std::string> python{
      "False",    "None",   "True",  "and",        "as",     "assert",   "async",   "await",      "break", "class",
      "continue", "def",    "del",   "elif",       "else",   "except",   "finally", "for",        "from",  "global",
      "if",       "import", "in",    "is",         "lambda", "nonlocal", "not",     "or",         "pass",  "raise",
      "return",   "try",    "while", "with",       "yield",  "np",       "p",       "q",          "qd",    "t",
      "A",        "B",      "u",     "PARAMETERS", "Q0",     "QD0",      "CASES",   "parameters", "demo",  "changes",
      "unknown",  "case",   "case1", "case2",      "case3",  "print",    "float",   "dict",       "title", "labels",
      "unknowns", "label",  "value", "name",       "i",      "number"};
  static const std::set<std::string> matlab{
      "break",      "case",     "catch",  "classdef", "continue",  "else",       "elseif",     "end",
      "for",        "function", "global", "if",       "otherwise", "parfor",     "persistent", "return",
      "spmd",       "switch",   "try",    "while",    "p",         "q",          "qd",         "t",
      "A",          "B",        "u",      "model",    "varargout", "parameters", "state",      "demo",
      "print_case", "case1",    "case2",  "case3",    "pi",        "sin",        "cos",        "tan",
      "sqrt",       "exp",      "log",    "abs",      "zeros",     "numel",      "fprintf",    "nargin",
      "nargout",    "i",        "j",      "title",    "labels",    "unknowns",   "k",          "ans"};
  return language == CodeLanguage::python ? python : matlab;
}

std::string valid_characters(std::string name) {
  for (char& c : name)
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 || static_cast<unsigned char>(c) >= 0x80) c = '_';
  if (name.empty() || std::isalpha(static_cast<unsigned char>(name[0])) == 0) name = "v" + name;
  return name;
}

struct Assignment {
  std::string name;
  GiNaC::ex value;
};

struct GlossaryLine {
  std::string identifier, key, meaning;
};

// Everything both languages write, named once.
struct Plan {
  const MechanismSolution* solution = nullptr;
  std::vector<CaseSystem> cases;  // the solved ones
  std::string stem;
  Names names;
  std::vector<std::pair<std::string, double>> parameters;
  std::vector<Assignment> constants;  // definitions as the file writes them, then inertias
  std::vector<std::string> q, qd;     // generalized coordinates and rates
  std::vector<double> q0, qd0;
  std::vector<Assignment> maximal;  // Case 1: the other maximal coordinates, then their rates
  // The springs' lengths: in maximal coordinates for Case 1, in generalized ones otherwise.
  std::vector<Assignment> lengths_maximal, lengths_generalized;
  std::vector<GlossaryLine> glossary;
};

std::string parameter_value(const sym::System& system, const std::string& name) {
  for (const Parameter& p : system.mechanism().parameters)
    if (p.name == name) return format_roundtrip(p.value);
  return "?";
}

double finite(double value, const std::string& what) {
  if (!std::isfinite(value)) throw std::logic_error("code export: " + what + " is not finite");
  return value;
}

Plan make_plan(const MechanismSolution& s, CodeLanguage language) {
  const sym::System& system = *s.system;
  const sym::SymbolTable& table = system.table();
  Plan plan;
  plan.solution = &s;
  for (const SolvedCase& c : s.cases) plan.cases.push_back(c.system);
  plan.stem = export_stem(s);
  std::set<std::string> taken = reserved(language);
  taken.insert(plan.stem);
  plan.names[system.time()] = "t";
  for (const sym::SymbolInfo& info : table.all()) {
    if (info.role == sym::Role::time) continue;  // named "t" above, in the glossary below
    std::string id = code_identifier(info.key);
    while (taken.count(id) != 0) id += "_";
    taken.insert(id);
    plan.names[info.symbol] = id;
    std::string meaning = info.meaning + (info.unit.empty() ? "" : " [" + info.unit + "]");
    if (info.role == sym::Role::parameter) meaning = "parameter, " + parameter_value(system, info.key) + " in the file";
    if (info.role == sym::Role::definition) meaning = "definition";
    plan.glossary.push_back({id, info.key, meaning});
  }
  auto name_of = [&](const std::string& key) { return plan.names.at(table.find(key)->symbol); };

  const Mechanism& mechanism = system.mechanism();
  for (const Parameter& p : mechanism.parameters)
    plan.parameters.emplace_back(name_of(p.name), finite(p.value, "parameter " + p.name));
  for (const Definition& d : mechanism.definitions)
    plan.constants.push_back({name_of(d.name), system.quantity(d.value, false)});
  std::set<std::string> inertias;
  for (const sym::BodySystem& b : system.bodies()) {
    if (!b.rotates || !GiNaC::is_a<GiNaC::symbol>(b.inertia)) continue;
    const std::string& id = plan.names.at(b.inertia);
    if (inertias.insert(id).second) plan.constants.push_back({id, b.inertia_formula});
  }
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    plan.q.push_back(plan.names.at(g.symbols.q));
    plan.qd.push_back(plan.names.at(g.symbols.q_dot));
    plan.q0.push_back(finite(sym::to_double(s.state.at(g.symbols.q)), g.coordinate.key));
    plan.qd0.push_back(finite(sym::to_double(s.state.at(g.symbols.q_dot)), g.coordinate.key + "_dot"));
  }
  for (const sym::Role role : {sym::Role::coordinate, sym::Role::rate})
    for (const sym::SymbolInfo& info : table.all()) {
      if (info.role != role) continue;
      const auto it = system.to_generalized().find(info.symbol);
      if (it != system.to_generalized().end()) plan.maximal.push_back({plan.names.at(info.symbol), it->second});
    }
  for (const sym::SymbolInfo& info : table.all()) {
    if (info.role != sym::Role::length) continue;
    const GiNaC::ex& length = system.lengths().at(info.symbol);
    plan.lengths_maximal.push_back({plan.names.at(info.symbol), length});
    plan.lengths_generalized.push_back({plan.names.at(info.symbol), length.subs(system.to_generalized())});
  }
  return plan;
}

// Every symbol of the case's entries must be one the function assigns before A and B.
void require_defined(const Plan& plan, const CaseSystem& c) {
  std::set<std::string> defined{"t"};
  for (const auto& [name, value] : plan.parameters) defined.insert(name);
  for (const Assignment& a : plan.constants) defined.insert(a.name);
  defined.insert(plan.q.begin(), plan.q.end());
  defined.insert(plan.qd.begin(), plan.qd.end());
  if (c.maximal)
    for (const Assignment& a : plan.maximal) defined.insert(a.name);
  for (const Assignment& a : plan.lengths_maximal) defined.insert(a.name);
  auto check = [&](const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
      if (!GiNaC::is_a<GiNaC::symbol>(*it)) continue;
      const auto name = plan.names.find(*it);
      if (name == plan.names.end() || defined.count(name->second) == 0)
        throw std::logic_error("code export: a Case " + std::to_string(case_number(c.id)) +
                               " entry uses a symbol the function does not define");
    }
  };
  for (const auto& row : c.A)
    for (const GiNaC::ex& e : row) check(e);
  for (const GiNaC::ex& e : c.B) check(e);
}

std::string case_title(const CaseSystem& c) { return "Case " + std::to_string(case_number(c.id)) + ": " + c.title; }

std::vector<std::string> unknown_names(const Plan& plan, const CaseSystem& c) {
  std::vector<std::string> out;
  for (const GiNaC::symbol& u : c.unknowns) out.push_back(plan.names.at(u));
  return out;
}

std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : separator) + p;
  return out;
}

// The header both languages share, each line after `comment`.
void write_header(std::ostream& out, const Plan& plan, const std::string& comment, const std::string& usage) {
  const Mechanism& m = plan.solution->system->mechanism();
  auto line = [&](const std::string& text) { out << comment << (text.empty() ? "" : " " + text) << '\n'; };
  line("The equations of motion of the mechanism " + (m.name.empty() ? std::string("built in code") : m.name) +
       ", each solved case as A u = B,");
  line("written by linkage from the same symbolic expressions its worked solution prints and");
  line("solves. The state is the generalized coordinates q and their rates qd; Case 1 computes");
  line("every body's maximal coordinates from them.");
  if (!plan.solution->closure_note.empty()) line("Its state: " + plan.solution->closure_note);
  line("");
  out << usage;
  line("");
  line("Names: a key of linkage made an identifier. BODY.NAME (of a body or a joint) becomes");
  line("NAME_BODY, a suffix after NAME's first underscore staying last: 1.theta -> theta_1,");
  line("1.theta_dot -> theta_1_dot, P.force_x -> force_P_x; characters other than letters,");
  line("digits and _ become _, a name not starting with a letter gets a v in front, and one");
  line("that would clash with another or with a word of the language gets a trailing _.");
  std::size_t wide_id = 10, wide_key = 3;
  for (const GlossaryLine& g : plan.glossary) {
    wide_id = std::max(wide_id, g.identifier.size());
    wide_key = std::max(wide_key, g.key.size());
  }
  auto row = [&](const std::string& id, const std::string& key, const std::string& meaning) {
    line("  " + id + std::string(wide_id - id.size() + 2, ' ') + key + std::string(wide_key - key.size() + 2, ' ') +
         meaning);
  };
  row("identifier", "key", "meaning");
  row("t", "t", "time [s]");
  for (const GlossaryLine& g : plan.glossary) row(g.identifier, g.key, g.meaning);
  line("");
  line("q  = (" + joined(plan.q, ", ") + ")");
  line("qd = (" + joined(plan.qd, ", ") + ")");
}

// ---------------------------------------------------------------- MATLAB / Octave

std::string matlab_string(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string matlab_cell(const std::vector<std::string>& items) {
  std::vector<std::string> quoted;
  for (const std::string& item : items) quoted.push_back(matlab_string(item));
  return "{" + joined(quoted, ", ") + "}";
}

std::string matlab_vector(const std::vector<double>& values) {
  std::vector<std::string> parts;
  for (double v : values) parts.push_back(format_roundtrip(v));
  return "[" + joined(parts, "; ") + "]";
}

void matlab_case(std::ostream& out, const Plan& plan, const CaseSystem& c, const CodePrinter& print) {
  require_defined(plan, c);
  const int n = case_number(c.id);
  const std::vector<std::string> unknowns = unknown_names(plan, c);
  out << "\nfunction [A, B, u] = case" << n << "(p, q, qd, t)\n";
  out << "% " << case_title(c) << ".\n";
  out << "% Unknowns u = [" << joined(unknowns, "; ") << "].\n";
  out << "% Parameters\n";
  for (const auto& [name, value] : plan.parameters) out << name << " = p." << name << ";\n";
  if (!plan.constants.empty()) out << "% Definitions and inertias\n";
  for (const Assignment& a : plan.constants) out << a.name << " = " << print(a.value) << ";\n";
  out << "% Generalized coordinates and rates\n";
  for (std::size_t k = 0; k < plan.q.size(); ++k) out << plan.q[k] << " = q(" << k + 1 << ");\n";
  for (std::size_t k = 0; k < plan.qd.size(); ++k) out << plan.qd[k] << " = qd(" << k + 1 << ");\n";
  if (c.maximal && !plan.maximal.empty()) {
    out << "% Maximal coordinates and rates from them\n";
    for (const Assignment& a : plan.maximal) out << a.name << " = " << print(a.value) << ";\n";
  }
  if (!plan.lengths_maximal.empty()) out << "% Spring lengths\n";
  for (const Assignment& a : c.maximal ? plan.lengths_maximal : plan.lengths_generalized)
    out << a.name << " = " << print(a.value) << ";\n";
  out << "A = zeros(" << c.A.size() << ", " << c.unknowns.size() << ");\n";
  out << "B = zeros(" << c.B.size() << ", 1);\n";
  for (std::size_t i = 0; i < c.A.size(); ++i) {
    out << "% (" << c.labels[i] << ")\n";
    for (std::size_t j = 0; j < c.A[i].size(); ++j)
      if (!c.A[i][j].is_zero())
        out << "A(" << i + 1 << ", " << j + 1 << ") = " << print(c.A[i][j]) << ";  % " << unknowns[j] << '\n';
    if (!c.B[i].is_zero()) out << "B(" << i + 1 << ") = " << print(c.B[i]) << ";\n";
  }
  out << "u = A \\ B;\nend\n";
}

// ---------------------------------------------------------------- Python (NumPy)

std::string python_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (static_cast<unsigned char>(c) < 0x20)
      out += ' ';
    else
      out += c;
  }
  return out + "\"";
}

std::string python_float(double value) {
  std::string text = format_roundtrip(value);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string python_list(const std::vector<double>& values) {
  std::vector<std::string> parts;
  for (double v : values) parts.push_back(python_float(v));
  return "[" + joined(parts, ", ") + "]";
}

std::string python_strings(const std::vector<std::string>& items) {
  std::vector<std::string> quoted;
  for (const std::string& item : items) quoted.push_back(python_string(item));
  return "[" + joined(quoted, ", ") + "]";
}

void python_case(std::ostream& out, const Plan& plan, const CaseSystem& c, const CodePrinter& print) {
  require_defined(plan, c);
  const int n = case_number(c.id);
  const std::vector<std::string> unknowns = unknown_names(plan, c);
  const std::string in = "    ";
  out << "\n\ndef case" << n << "(p, q, qd, t=0.0):\n";
  out << in << "# " << case_title(c) << ".\n";
  out << in << "# Unknowns u = (" << joined(unknowns, ", ") << ").\n";
  out << in << "# Parameters\n";
  for (const auto& [name, value] : plan.parameters) out << in << name << " = p[\"" << name << "\"]\n";
  if (!plan.constants.empty()) out << in << "# Definitions and inertias\n";
  for (const Assignment& a : plan.constants) out << in << a.name << " = " << print(a.value) << '\n';
  out << in << "# Generalized coordinates and rates\n";
  for (std::size_t k = 0; k < plan.q.size(); ++k) out << in << plan.q[k] << " = q[" << k << "]\n";
  for (std::size_t k = 0; k < plan.qd.size(); ++k) out << in << plan.qd[k] << " = qd[" << k << "]\n";
  if (c.maximal && !plan.maximal.empty()) {
    out << in << "# Maximal coordinates and rates from them\n";
    for (const Assignment& a : plan.maximal) out << in << a.name << " = " << print(a.value) << '\n';
  }
  if (!plan.lengths_maximal.empty()) out << in << "# Spring lengths\n";
  for (const Assignment& a : c.maximal ? plan.lengths_maximal : plan.lengths_generalized)
    out << in << a.name << " = " << print(a.value) << '\n';
  out << in << "A = np.zeros((" << c.A.size() << ", " << c.unknowns.size() << "))\n";
  out << in << "B = np.zeros(" << c.B.size() << ")\n";
  for (std::size_t i = 0; i < c.A.size(); ++i) {
    out << in << "# (" << c.labels[i] << ")\n";
    for (std::size_t j = 0; j < c.A[i].size(); ++j)
      if (!c.A[i][j].is_zero())
        out << in << "A[" << i << ", " << j << "] = " << print(c.A[i][j]) << "  # " << unknowns[j] << '\n';
    if (!c.B[i].is_zero()) out << in << "B[" << i << "] = " << print(c.B[i]) << '\n';
  }
  out << in << "u = np.linalg.solve(A, B)\n";
  out << in << "return A, B, u\n";
}

}  // namespace

std::string code_identifier(const std::string& key) {
  const auto dot = key.find('.');
  if (dot == std::string::npos) return valid_characters(key);
  const std::string owner = key.substr(0, dot);
  const std::string field = key.substr(dot + 1);
  const auto underscore = field.find('_');
  if (underscore == std::string::npos || underscore == 0) return valid_characters(field + "_" + owner);
  return valid_characters(field.substr(0, underscore) + "_" + owner + field.substr(underscore));
}

std::string export_stem(const MechanismSolution& s) {
  const std::string& name = s.system->mechanism().name;
  if (name.empty()) return "mechanism";
  std::string stem = valid_characters(name);
  // A MATLAB function name has at most 63 characters and must differ from the file's own functions.
  if (stem.size() > 50) stem.resize(50);
  static const std::set<std::string> helpers{"parameters", "state", "demo", "print_case", "case1", "case2", "case3"};
  if (helpers.count(stem) != 0 || reserved(CodeLanguage::matlab).count(stem) != 0 ||
      reserved(CodeLanguage::python).count(stem) != 0)
    stem += "_mechanism";
  return stem;
}

std::string matlab_export(const MechanismSolution& s) {
  const Plan plan = make_plan(s, CodeLanguage::matlab);
  const CodePrinter print(CodeLanguage::matlab, s.system->table(), plan.names);
  std::string upper = plan.stem;
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));

  std::ostringstream out;
  out << "function varargout = " << plan.stem << "()\n";
  out << "% " << upper << "  "
      << (s.system->mechanism().title.empty() ? "a planar mechanism" : s.system->mechanism().title) << "\n%\n";
  std::ostringstream usage;
  usage << "% Save as " << plan.stem << ".m; runs in MATLAB and GNU Octave.\n"
        << "%   " << plan.stem << "\n"
        << "%       prints every case at the file's state;\n"
        << "%   model = " << plan.stem << "();\n"
        << "%       gives its functions, for any parameters and state:\n"
        << "%   p = model.parameters();                the file's parameters (a struct; change any field)\n"
        << "%   [q, qd] = model.state();               the file's generalized coordinates and rates\n";
  for (const CaseSystem& c : plan.cases)
    usage << "%   [A, B, u] = model.case" << case_number(c.id) << "(p, q, qd, t);  Case " << case_number(c.id)
          << " at time t, u = A \\ B\n";
  usage << "%   model.demo(p, q, qd, t);               prints every case there\n";
  write_header(out, plan, "%", usage.str());
  out << "model.parameters = @parameters;\nmodel.state = @state;\n";
  for (const CaseSystem& c : plan.cases)
    out << "model.case" << case_number(c.id) << " = @case" << case_number(c.id) << ";\n";
  out << "model.demo = @demo;\n";
  out << "if nargout > 0\n  varargout{1} = model;\nelse\n  demo();\nend\nend\n";

  out << "\nfunction p = parameters()\n% The file's parameters, SI units.\n";
  for (const auto& [name, value] : plan.parameters) out << "p." << name << " = " << format_roundtrip(value) << ";\n";
  if (plan.parameters.empty()) out << "p = struct();\n";
  out << "end\n";
  out << "\nfunction [q, qd] = state()\n% The file's generalized coordinates and rates.\n";
  out << "q = " << matlab_vector(plan.q0) << ";\n";
  out << "qd = " << matlab_vector(plan.qd0) << ";\nend\n";
  for (const CaseSystem& c : plan.cases) matlab_case(out, plan, c, print);

  out << "\nfunction demo(p, q, qd, t)\n"
      << "% Prints every case at a state: by default the file's, at t = 0.\n"
      << "if nargin < 1\n  p = parameters();\nend\n"
      << "if nargin < 3\n  [q, qd] = state();\nend\n"
      << "if nargin < 4\n  t = 0;\nend\n";
  for (const CaseSystem& c : plan.cases) {
    const int n = case_number(c.id);
    out << "[A, B, u] = case" << n << "(p, q, qd, t);\n";
    out << "print_case(" << matlab_string(case_title(c)) << ", " << matlab_cell(c.labels) << ", "
        << matlab_cell(unknown_names(plan, c)) << ", A, B, u);\n";
  }
  out << "end\n";
  out << "\nfunction print_case(title, labels, unknowns, A, B, u)\n"
      << "fprintf('%s\\n', title);\n"
      << "for k = 1:numel(labels)\n"
      << "  fprintf('  (%s)  A =', labels{k});\n"
      << "  fprintf(' %.17g', A(k, :));\n"
      << "  fprintf(' | B = %.17g\\n', B(k));\n"
      << "end\n"
      << "for k = 1:numel(unknowns)\n"
      << "  fprintf('  %s = %.17g\\n', unknowns{k}, u(k));\n"
      << "end\n"
      << "end\n";
  return out.str();
}

std::string python_export(const MechanismSolution& s) {
  const Plan plan = make_plan(s, CodeLanguage::python);
  const CodePrinter print(CodeLanguage::python, s.system->table(), plan.names);
  std::ostringstream out;
  out << "#!/usr/bin/env python3\n";
  out << "# " << (s.system->mechanism().title.empty() ? "A planar mechanism" : s.system->mechanism().title) << '\n';
  out << "#\n";
  std::ostringstream usage;
  usage << "# Needs Python 3 and NumPy. Run it to print every case at the file's state:\n"
        << "#   python3 " << plan.stem << ".py\n"
        << "# or use it at any parameters and state:\n"
        << "#   import " << plan.stem << " as mech\n"
        << "#   p = mech.parameters()                           # the file's; parameters(NAME=VALUE) changes some\n";
  for (const CaseSystem& c : plan.cases)
    usage << "#   A, B, u = mech.case" << case_number(c.id) << "(p, mech.Q0, mech.QD0, t=0.0)  # Case "
          << case_number(c.id) << ", u solves A u = B\n";
  usage << "#   mech.demo(p, q, qd, t)                          # prints every case there\n";
  write_header(out, plan, "#", usage.str());
  out << "\nimport numpy as np\n\n";
  out << "# The file's parameters, SI units.\nPARAMETERS = {\n";
  for (const auto& [name, value] : plan.parameters) out << "    \"" << name << "\": " << python_float(value) << ",\n";
  out << "}\n";
  out << "# The file's generalized coordinates (" << joined(plan.q, ", ") << ") and rates.\n";
  out << "Q0 = " << python_list(plan.q0) << "\n";
  out << "QD0 = " << python_list(plan.qd0) << "\n";
  out << "\n\ndef parameters(**changes):\n"
      << "    # The file's parameters with some changed: parameters(L=0.4).\n"
      << "    unknown = sorted(set(changes) - set(PARAMETERS))\n"
      << "    if unknown:\n"
      << "        raise KeyError(\"unknown parameter %s; valid: %s\" % (\", \".join(unknown), \", "
         "\".join(PARAMETERS)))\n"
      << "    p = dict(PARAMETERS)\n"
      << "    p.update({name: float(value) for name, value in changes.items()})\n"
      << "    return p\n";
  for (const CaseSystem& c : plan.cases) python_case(out, plan, c, print);

  out << "\n\n# Each case: its number, title, function, row labels and unknowns.\nCASES = [\n";
  for (const CaseSystem& c : plan.cases) {
    const int n = case_number(c.id);
    out << "    (" << n << ", " << python_string(case_title(c)) << ", case" << n << ", " << python_strings(c.labels)
        << ", " << python_strings(unknown_names(plan, c)) << "),\n";
  }
  out << "]\n";
  out << "\n\ndef demo(p=None, q=None, qd=None, t=0.0):\n"
      << "    # Prints every case at a state: by default the file's, at t = 0.\n"
      << "    p = parameters() if p is None else p\n"
      << "    q = Q0 if q is None else q\n"
      << "    qd = QD0 if qd is None else qd\n"
      << "    for number, title, case, labels, unknowns in CASES:\n"
      << "        A, B, u = case(p, q, qd, t)\n"
      << "        print(title)\n"
      << "        for i, label in enumerate(labels):\n"
      << "            row = \" \".join(repr(float(value)) for value in A[i])\n"
      << "            print(\"  (%s)  A = %s | B = %s\" % (label, row, repr(float(B[i]))))\n"
      << "        for name, value in zip(unknowns, u):\n"
      << "            print(\"  %s = %s\" % (name, repr(float(value))))\n";
  out << "\n\nif __name__ == \"__main__\":\n    demo()\n";
  return out.str();
}

}  // namespace linkage
