#pragma once
// Everything `linkage solve --mechanism` shows for any mechanism, computed once from the
// one symbolic system and printed by each format: the state (loops closed), each
// selected case's symbolic system, its numbers and solution, each body's acceleration
// and each joint's force per case, and how closely the cases agree.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "formulations/case_numbers.hpp"
#include "formulations/case_system.hpp"
#include "model/mechanism.hpp"
#include "symbolic/system.hpp"

namespace linkage {

struct SolvedCase {
  CaseSystem system;
  CaseNumbers numbers;
};

/// One Case 1 unknown (every body acceleration and joint force) across the solved cases.
struct MechanismAgreement {
  GiNaC::symbol unknown;
  std::vector<std::optional<double>> values;  // per solved case
  std::vector<bool> recovered;                // the case yields it from eliminated rows
  double max_abs_difference = 0;
};

struct MechanismSolution {
  std::shared_ptr<const sym::System> system;
  GiNaC::exmap state;   // generalized coordinates and rates, loops closed
  GiNaC::exmap values;  // every symbol's value at that state
  std::string closure_note;
  std::vector<SolvedCase> cases;
  std::vector<MechanismAgreement> agreement;  // empty unless two or more cases
};

/// Derives and solves the selected cases. Errors name the file position of a bad value,
/// an alias of a key the JSON does not have or one that names another key, and the case
/// and condition number of a singular matrix.
/// How Case 3 is written: by eliminating the tree's joint forces from Newton-Euler (the
/// homework's (1.3) to (4.3)), or in Lagrange's form M(q) q'' = Q (`solve --form lagrange`).
enum class CaseForm { newton_euler, lagrange };
[[nodiscard]] MechanismSolution work_out_mechanism(const Mechanism& mechanism, const std::vector<CaseId>& cases,
                                                   CaseForm form = CaseForm::newton_euler);
/// The same for a system derived already.
[[nodiscard]] MechanismSolution work_out_mechanism(std::shared_ptr<const sym::System> system,
                                                   const std::vector<CaseId>& cases,
                                                   CaseForm form = CaseForm::newton_euler);

/// A body's centre-of-mass acceleration and angular acceleration in a solved case.
struct BodyMotion {
  double ax = 0, ay = 0, alpha = 0;
};
[[nodiscard]] BodyMotion body_motion(const MechanismSolution& s, const SolvedCase& c, std::size_t body);

/// A joint's force (bodies[1] on bodies[0], world) and, for a slider, its moment.
struct JointForce {
  double fx = 0, fy = 0;
  std::optional<double> moment;
};
[[nodiscard]] JointForce joint_force(const MechanismSolution& s, const SolvedCase& c, std::size_t joint);

/// The names of the JSON's quantity keys: the mechanism's own ("1.x_ddot", "P.force_x"), or
/// its file's [aliases] where it has them ("x1_ddot", "F_x").
enum class JsonKeys { mechanism, aliases };

/// `linkage solve --format json`.
[[nodiscard]] std::string mechanism_json(const MechanismSolution& s, JsonKeys keys = JsonKeys::mechanism);

}  // namespace linkage
