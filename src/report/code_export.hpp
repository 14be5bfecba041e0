#pragma once
// `linkage solve --format matlab|python`: the solved cases of a mechanism as one
// self-contained source file a student runs and changes in MATLAB/GNU Octave or in
// Python 3 with NumPy. Per case a function of the parameters, the generalized state and
// the time returning A, B and u = A \ B, every entry printed from the case's own GiNaC
// expression (code_printer.hpp); the file's parameters and state as defaults; a demo
// that prints every case there. Identifiers are the symbol table's keys made valid
// (code_identifier); the file's header lists them all.
#include <string>

#include "report/mechanism_solution.hpp"

namespace linkage {

/// A MATLAB/Octave function file; its main function is export_stem(s), so save it as
/// export_stem(s) + ".m". Run without outputs it prints every case at the file's state;
/// `model = NAME()` gives the functions (model.parameters, model.state, model.case1, ...).
[[nodiscard]] std::string matlab_export(const MechanismSolution& s);

/// A Python 3 module (NumPy): PARAMETERS, Q0, QD0, parameters(**changes), caseN(p, q, qd,
/// t), demo(p, q, qd, t); run as a script it prints every case at the file's state.
[[nodiscard]] std::string python_export(const MechanismSolution& s);

/// The mechanism's name as a file and function name: "two-blocks" -> "two_blocks"
/// ("mechanism" when it has none).
[[nodiscard]] std::string export_stem(const MechanismSolution& s);

/// A symbol key as an identifier, before clashes are resolved: "L" -> "L", "BODY.NAME"
/// -> "NAME_BODY" with NAME's first underscore suffix last ("1.theta_dot" ->
/// "theta_1_dot", "P.force_x" -> "force_P_x"); other characters than ASCII letters,
/// digits and _ become _, and a name that does not start with a letter gets a "v".
[[nodiscard]] std::string code_identifier(const std::string& key);

}  // namespace linkage
