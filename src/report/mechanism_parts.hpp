#pragma once
// Pieces every writer of a mechanism's derivation uses alike (mechanism_text,
// mechanism_latex): how a body is called, where a load acts, whether anything ties the
// mechanism to the world, and a constraint's acceleration form.
#include <string>

#include "core/style.hpp"
#include "model/mechanism.hpp"
#include "report/mechanism_solution.hpp"
#include "report/notation.hpp"
#include "report/report_options.hpp"
#include "symbolic/system.hpp"

namespace linkage {

/// "block 1", "rod 2", "disc 3", "mass 4" for a body named by digits, else its name;
/// "the ground" for -1.
[[nodiscard]] std::string body_label(const Mechanism& mechanism, int body);

/// The label of the body named `name` (kGround: "the ground").
[[nodiscard]] std::string body_label(const Mechanism& mechanism, const std::string& name);

/// Where `load` acts on body `body`: "the centre of mass", a named point of the body, or ""
/// when it is neither.
[[nodiscard]] std::string load_place(const sym::System& system, std::size_t body, const sym::Load& load);

/// A body's moment of inertia about one of its pins, by the parallel-axis theorem:
/// I^P = I + m |r|², r from the centre of mass to the pin point (the homework's I_zz^P).
struct PinInertia {
  std::string unicode, ascii, latex;  // "I^P", "I^P", "I_{zz}^{P}"
  GiNaC::ex formula;
};
/// One per rotating body and pin point away from its centre of mass, in body and joint
/// order; equal ones (the same symbol, point name and formula) once.
[[nodiscard]] std::vector<PinInertia> pin_inertias(const sym::System& system);

/// Where the values came from: "Given: m = 2 (run.toml:1:5), 2.theta = 0.7 (--theta2);
/// the rest as in the shipped two-blocks.toml." or "All values as in pendulum.toml."
[[nodiscard]] std::string given_note(const Mechanism& mechanism);

/// `e` with each spring's length written out, |r_b - r_a| in maximal coordinates, and its
/// square replaced by its symbol (l_k1), so energies print with the symbol the loads use.
[[nodiscard]] GiNaC::ex with_lengths(const sym::System& system, const GiNaC::ex& e);

/// A value of the file that reads the state, as the file writes it ("stiffness of spring
/// k1", "k*(1 + (S.s/a)^2)"), and the names in it that are no maximal coordinate (a slider's
/// travel and rate) with their expressions in maximal coordinates, as Case 1 writes them.
struct WrittenValue {
  std::string what, text;
};
struct WrittenValues {
  std::vector<WrittenValue> values;
  std::vector<std::pair<std::string, GiNaC::ex>> rewritten;  // "S.s" -> x_cart
};
[[nodiscard]] WrittenValues written_state_values(const sym::System& system);

/// Whether a joint or spring holds the mechanism to the ground, or an applied force or
/// torque acts: otherwise its horizontal momentum stays constant.
[[nodiscard]] bool touches_ground(const Mechanism& mechanism);

/// The second time derivative of the constraint row `phi` as Case 1 writes it: the
/// accelerations on the left (in the order of the symbol table), the rest on the right.
[[nodiscard]] EquationSides acceleration_form(const sym::System& system, const GiNaC::ex& phi, Style style);

/// The order of a mechanism's worked derivation, shared by every format: the title, the
/// parts `options` shows, each case, the agreement table. `Writer` has title(), inputs(),
/// inertia(), constraints(), energy(), forces(), newton_euler(), one_case(const
/// SolvedCase&) and agreement() (a friend of the writer may call them private).
template <class Writer>
void write_mechanism_sections(Writer& w, const MechanismSolution& s, const ReportOptions& o) {
  w.title();
  if (o.shows(ReportPart::inputs)) w.inputs();
  if (o.shows(ReportPart::inertia)) w.inertia();
  if (o.shows(ReportPart::constraints)) w.constraints();
  if (o.shows(ReportPart::energy)) w.energy();
  if (o.shows(ReportPart::constraints)) {
    w.forces();
    w.newton_euler();
  }
  if (o.shows(ReportPart::symbolic) || o.shows(ReportPart::numeric) || o.shows(ReportPart::solution) ||
      o.shows(ReportPart::residual))
    for (const SolvedCase& c : s.cases) w.one_case(c);
  if (!s.agreement.empty() && o.shows(ReportPart::comparison)) w.agreement();
}

}  // namespace linkage
