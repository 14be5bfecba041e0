// `linkage solve --mechanism` as text: the worked derivation of any mechanism, step by step
// as the homework's solution goes, then each case and the agreement table.
#include "report/mechanism_text.hpp"

#include "report/expression_print.hpp"
#include "report/mechanism_parts.hpp"
#include "report/notation.hpp"
#include "report/text_layout.hpp"
#include "symbolic/energy.hpp"
#include "symbolic/joints.hpp"

namespace linkage {

namespace {

class MechanismWriter {
 public:
  MechanismWriter(const MechanismSolution& s, const ReportOptions& options)
      : s_(s), system_(*s.system), o_(options), style_(options.text_style) {}

  std::string run() {
    write_mechanism_sections(*this, s_, o_);
    return out_;
  }

 private:
  template <class Writer>
  friend void linkage::write_mechanism_sections(Writer& w, const MechanismSolution& s, const ReportOptions& o);

  void title() {
    const Mechanism& m = system_.mechanism();
    heading(concat({"Worked solution: ", m.title.empty() ? m.name : m.title}), '=');
    if (!m.description.empty()) {
      blank();
      prose(m.description, "");
    }
  }

  void line(const std::string& text) { out_ += text + "\n"; }
  void lines(const std::vector<std::string>& text) {
    for (const auto& l : text) line(l);
  }
  void blank() { out_ += "\n"; }
  void prose(std::string_view text, std::string_view indent = "  ") { lines(wrap_words(text, indent, o_.width)); }
  void heading(std::string_view title, char underline) {
    if (!out_.empty()) blank();
    line(std::string(title));
    line(std::string(display_width(title), underline));
  }

  [[nodiscard]] std::string math(const GiNaC::ex& e) const { return strip_marks(print(e, system_.table(), style_)); }
  [[nodiscard]] std::string marked(const GiNaC::ex& e) const { return print(e, system_.table(), style_); }
  [[nodiscard]] std::string spelling(const GiNaC::symbol& s) const {
    const sym::SymbolInfo* info = system_.table().find(s);
    return style_ == Style::unicode ? info->unicode : info->ascii;
  }
  [[nodiscard]] std::string number(double value) const { return format_number(value, style_, o_.digits); }
  [[nodiscard]] std::string unit(std::string_view ascii) const { return unit_text(ascii, style_); }
  [[nodiscard]] std::string place(std::size_t body, const sym::Load& load) const {
    const std::string where = load_place(system_, body, load);
    return where.empty() ? where : concat({" at ", where});
  }
  [[nodiscard]] double value(const GiNaC::ex& e) const { return value_at(e, s_.values); }
  [[nodiscard]] std::string substituted(const GiNaC::ex& e) const { return strip_marks(substituted_marked(e)); }
  [[nodiscard]] std::string substituted_marked(const GiNaC::ex& e) const {
    return (print_substituted(e, system_.table(), style_, [&](const sym::SymbolInfo& info) {
      const double v = value(info.symbol);
      return format_number(v, style_, info.role == sym::Role::parameter ? 0 : o_.digits);
    }));
  }

  // "lhs = formula = substituted = value unit", wrapped when long.
  void step(const std::string& lhs, const GiNaC::ex& formula, const std::string& unit_ascii) {
    std::string result = number(value(formula));
    if (!unit_ascii.empty()) result += concat({" ", unit(unit_ascii)});
    const std::string symbolic = math(formula);
    const std::string numbers = substituted(formula);
    std::string text = concat({"  ", lhs, " = ", symbolic});
    if (numbers != symbolic && numbers != number(value(formula))) text += concat({" = ", numbers});
    text += concat({" = ", result});
    if (display_width(text) <= o_.width) {
      line(text);
      return;
    }
    const std::string equals = std::string(display_width(lhs) + 2, ' ') + " = ";
    lines(wrap(concat({"  ", lhs, " = "}), marked(formula), std::string(display_width(equals) + 2, ' '), o_.width));
    if (numbers != symbolic)
      lines(wrap(equals, substituted_marked(formula), std::string(display_width(equals) + 2, ' '), o_.width));
    line(equals + result);
  }

  void inputs() {
    const Mechanism& m = system_.mechanism();
    heading("Inputs and definitions", '-');
    Table table;
    table.headers = {"value", "unit", "meaning"};
    for (const Parameter& p : m.parameters) {
      const sym::SymbolInfo* info = system_.table().find(p.name);
      table.row_labels.push_back(style_ == Style::unicode ? info->unicode : info->ascii);
      table.cells.push_back(
          {format_number(p.value, style_, 0), unit(p.unit), p.meaning.empty() ? "parameter" : p.meaning});
    }
    lines(layout_table(table, "  ", o_.width));
    if (!m.definitions.empty()) {
      blank();
      for (const Definition& d : m.definitions) {
        const sym::SymbolInfo* info = system_.table().find(d.name);
        step(style_ == Style::unicode ? info->unicode : info->ascii, system_.constants().at(info->symbol), info->unit);
      }
    }
    blank();
    line("  Initial state (generalized coordinates of the spanning tree):");
    Table state;
    state.headers = {"value", "unit", "meaning"};
    for (const sym::GeneralizedCoordinate& g : system_.coordinates()) {
      for (const GiNaC::symbol* s : {&g.symbols.q, &g.symbols.q_dot}) {
        const sym::SymbolInfo* info = system_.table().find(*s);
        state.row_labels.push_back(style_ == Style::unicode ? info->unicode : info->ascii);
        state.cells.push_back(
            {format_number(sym::to_double(s_.state.at(*s)) * angle_factor(info->unit, o_.angles), style_, 0),
             unit(angle_unit_text(info->unit, o_.angles)), info->meaning});
      }
    }
    lines(layout_table(state, "    ", o_.width));
    blank();
    prose(given_note(m));
    if (!s_.closure_note.empty()) {
      blank();
      prose(s_.closure_note);
    }
  }

  void inertia() {
    heading("Moments of inertia", '-');
    const bool uni = style_ == Style::unicode;
    const std::vector<PinInertia> pins = pin_inertias(system_);
    std::string note =
        concat({"Each body's moment of inertia about its centre of mass, from its shape: the area "
                "integral for a rectangle, m L",
                uni ? "²" : "^2", "/12 for a rod, m r", uni ? "²" : "^2", "/2 for a disc, none for a point mass."});
    if (const sym::SymbolInfo* shared = system_.table().find("I");
        shared != nullptr && shared->role == sym::Role::inertia)
      note += " I stands for I_zz^C.";
    if (!pins.empty())
      note += concat({" The parallel-axis theorem moves it to each pin P: I^P = I + m |r|", uni ? "²" : "^2",
                      ", r from the centre of mass to P."});
    prose(note);
    blank();
    std::vector<std::string> done;
    for (const sym::BodySystem& b : system_.bodies()) {
      if (!b.rotates) continue;
      const std::string name = spelling(GiNaC::ex_to<GiNaC::symbol>(b.inertia));
      if (std::find(done.begin(), done.end(), name) != done.end()) continue;
      done.push_back(name);
      step(name, b.inertia_formula, "kg m^2");
    }
    for (const PinInertia& p : pins) step(uni ? p.unicode : p.ascii, p.formula, "kg m^2");
  }

  void constraints() {
    heading("The joints: constraints at position, velocity and acceleration level", '-');
    prose(
        "Each joint's constraint in the maximal coordinates of its bodies; the velocity and acceleration forms "
        "are its first and second time derivatives.");
    const Mechanism& m = system_.mechanism();
    for (std::size_t j = 0; j < m.joints.size(); ++j) {
      const Joint& joint = m.joints[j];
      const sym::JointSystem& js = system_.joints()[j];
      blank();
      line(concat({"  Joint ", joint.name, ": ", kJointTypeNames[static_cast<std::size_t>(joint.type)], " between ",
                   joint.bodies[0], ".", joint.points[0], " and ", joint.bodies[1], ".", joint.points[1],
                   js.in_tree ? " (spanning tree)" : " (closes a loop)"}));
      for (const GiNaC::ex& phi : js.constraints) levels(phi);
      // A row's constant (a gear's c_G): the rest of the row at the initial state.
      if (const GiNaC::ex& c = system_.joint_constant(static_cast<int>(j)); !c.is_zero()) {
        const GiNaC::ex rest = GiNaC::expand(js.constraints.at(0) + c);
        const GiNaC::ex& at_start = system_.constants().at(c);
        const std::string& unit_ascii = system_.table().find(GiNaC::ex_to<GiNaC::symbol>(c))->unit;
        line("    its constant, the rest of the row at the initial state:");
        const std::string lhs =
            concat({"  ", spelling(GiNaC::ex_to<GiNaC::symbol>(c)), " = ", math(rest), " at t = 0"});
        if (GiNaC::is_a<GiNaC::numeric>(at_start))  // nothing to substitute: its value
          line(concat({"  ", lhs, " = ", number(value(at_start)), unit_ascii.empty() ? "" : " ", unit(unit_ascii)}));
        else
          step(lhs, at_start, unit_ascii);
      }
    }
    for (const sym::DriverSystem& d : system_.drivers()) {
      const Driver& driver = m.drivers[static_cast<std::size_t>(d.index)];
      const Joint& joint = m.joints[static_cast<std::size_t>(d.joint)];
      blank();
      lines(wrap_words(
          concat({"Driver ", driver.name, ": ", joint_type_name(joint.type), " ", joint.name, " on its motion ",
                  driver.motion.text, ", a row of every case; its ", joint_type_info(joint.type).driver_column, " ",
                  spelling(d.unknown), " on ", joint.bodies[1], " is an unknown of every case"}),
          "  ", o_.width));
      levels(d.constraint);
    }
  }

  // A constraint row at position, velocity and acceleration level.
  void levels(const GiNaC::ex& phi) {
    lines(wrap("    position      ", concat({marked(GiNaC::expand(phi)), std::string(1, kBreakMark), " = 0"}),
               std::string(20, ' '), o_.width));
    const GiNaC::ex rate = system_.time_derivative(phi);
    lines(wrap("    velocity      ", concat({marked(GiNaC::expand(rate)), std::string(1, kBreakMark), " = 0"}),
               std::string(20, ' '), o_.width));
    const EquationSides eq = acceleration_form(system_, phi, style_);
    lines(wrap("    acceleration  ", concat({eq.lhs, std::string(1, kBreakMark), " = ", eq.rhs}), std::string(20, ' '),
               o_.width));
  }

  void energy() {
    heading("Energy and momentum", '-');
    const GiNaC::ex power = sym::nonconservative_power(system_);
    std::string note = power.is_zero()
                           ? "Only conservative forces work on the mechanism: its energy E = T + V stays constant."
                           : "The dampers and applied loads work at the rate P; E = T + V changes at that rate.";
    if (!system_.drivers().empty())
      note = concat({power.is_zero() ? "E = T + V"
                                     : "The dampers and applied loads work at the rate P; E = T + V changes at P and",
                     power.is_zero() ? " changes at the drivers' power" : " at the drivers' power",
                     ", each driver's torque or force times its joint's relative rate."});
    if (!touches_ground(system_.mechanism()))
      note +=
          " Nothing touches the ground: the horizontal momentum and the angular momentum H_c about the centre of mass "
          "stay constant, and the vertical momentum changes at "
          "the rate of gravity.";
    prose(note);
    blank();
    for (const sym::SymbolInfo& info : system_.table().all())  // the springs' lengths, used from here on
      if (info.role == sym::Role::length) step(spelling(info.symbol), system_.lengths().at(info.symbol), "m");
    const GiNaC::ex T = sym::kinetic_energy(system_);
    const GiNaC::ex V = with_lengths(system_, sym::potential_energy(system_));
    const sym::Vec2 p = sym::linear_momentum(system_);
    const bool uni = style_ == Style::unicode;
    step("T", T, "J");
    step("V", V, "J");
    line(concat({"  E = T + V = ", number(value(T) + value(V)), " J"}));
    if (!power.is_zero()) step("P", with_lengths(system_, power), "W");
    step(uni ? "p_x" : "p_x", p.x, "kg m/s");
    step(uni ? "p_y" : "p_y", p.y, "kg m/s");
    step("H_O", sym::angular_momentum(system_), "kg m^2/s");
    if (!touches_ground(system_.mechanism())) step("H_c", sym::angular_momentum_about_centre(system_), "kg m^2/s");
  }

  void forces() {
    heading("Forces and moments on each body", '-');
    prose(
        "Each body's free-body diagram as a list: a joint's force is the force its second body exerts on its "
        "first, so the first body feels +F and the second -F.");
    if (!system_.lengths().empty()) {
      blank();
      prose(
          "A spring of length l (above) between points A and B pulls each towards the other with k (l - l0) + "
          "c l', l' = (B - A) . (B' - A') / l.");
    }
    const WrittenValues written = written_state_values(system_);
    if (!written.values.empty()) {
      blank();
      prose("Values that read the state, as the file writes them:");
      for (const WrittenValue& v : written.values)
        lines(wrap("    ", concat({v.what, ": ", v.text}), "      ", o_.width));
      std::string rewritten;
      for (const auto& [name, expression] : written.rewritten)
        rewritten += concat({rewritten.empty() ? "" : ", ", name, " = ", math(expression)});
      if (!rewritten.empty())
        prose(concat({"Case 1 writes them in maximal coordinates: ", rewritten,
                      "; Cases 2 and 3 keep a slider's travel and rate as their own coordinate."}));
    }
    const Mechanism& m = system_.mechanism();
    for (std::size_t b = 0; b < system_.bodies().size(); ++b) {
      blank();
      line(concat({"  ", body_label(system_.mechanism(), static_cast<int>(b)), ":"}));
      for (std::size_t j = 0; j < m.joints.size(); ++j) {
        const Joint& joint = m.joints[j];
        const sym::JointSystem& js = system_.joints()[j];
        const bool first = m.bodies[b].name == joint.bodies[0];
        const bool second = m.bodies[b].name == joint.bodies[1];
        if (!first && !second) continue;
        const GiNaC::ex sign = first ? 1 : -1;
        std::string text = concat(
            {"    (", math(sign * js.force.x), ", ", math(sign * js.force.y), ") at ", joint.points[first ? 0 : 1]});
        if (!js.moment.is_zero()) text += concat({", moment ", math(sign * js.moment)});
        line(concat({text, ": ", kJointTypeNames[static_cast<std::size_t>(joint.type)], " ", joint.name, ", from ",
                     body_label(system_.mechanism(), first ? joint.bodies[1] : joint.bodies[0])}));
      }
      std::vector<sym::Load> loads = system_.loads();
      for (const sym::DriverSystem& d : system_.drivers()) loads.insert(loads.end(), d.loads.begin(), d.loads.end());
      for (const sym::Load& load : loads) {
        if (load.body != static_cast<int>(b)) continue;
        // A long load (a spring's, a damper's) wraps at its sums and between its components.
        const std::string mark(1, kBreakMark);
        std::string text;
        if (!(load.force.x.is_zero() && load.force.y.is_zero()))
          text += concat({"(", marked(load.force.x), ",", mark, " ", marked(load.force.y), ")", place(b, load)});
        if (!load.moment.is_zero())
          text += concat({text.empty() ? "moment " : concat({",", mark, " moment "}), marked(load.moment)});
        lines(wrap("    ", concat({text, ": ", load.source}), "      ", o_.width));
      }
    }
  }

  void newton_euler() {
    heading("Newton-Euler equations of each body", '-');
    prose(
        "m a = sum of the forces, and I alpha = sum of the moments about the centre of mass, in maximal "
        "coordinates; Case 1 takes them as they are, Cases 2 and 3 write them in the generalized coordinates.");
    const CaseSystem case1 = maximal_case(system_);
    std::vector<const sym::SymbolInfo*> unknowns;
    for (const GiNaC::symbol& u : case1.unknowns) unknowns.push_back(system_.table().find(u));
    std::size_t row = 0;
    for (std::size_t b = 0; b < system_.bodies().size(); ++b) {
      blank();
      line(concat({"  ", body_label(system_.mechanism(), static_cast<int>(b)), ":"}));
      for (std::size_t k = 0; k < system_.newton_euler()[b].rows.size(); ++k, ++row) {
        const EquationSides eq = equation_sides(case1.A[row], case1.B[row], unknowns, system_.table(), style_);
        lines(wrap("    ", eq.lhs + kBreakMark + " = " + eq.rhs, "        ", o_.width));
      }
    }
  }

  void one_case(const SolvedCase& solved) {
    const CaseSystem& c = solved.system;
    heading(case_heading(c), '-');
    std::vector<const sym::SymbolInfo*> unknowns;
    std::string u_list;
    for (const GiNaC::symbol& u : c.unknowns) {
      unknowns.push_back(system_.table().find(u));
      u_list += (u_list.empty() ? "" : ", ") + spelling(u);
    }
    prose(concat({"Unknowns: q = (", u_list, ")"}));
    std::vector<std::string> labels;
    for (const std::string& label : c.labels) labels.push_back(parenthesized(label));
    if (o_.shows(ReportPart::symbolic)) {
      blank();
      line("  Equations, one per row of A q = B:");
      lines(case_equation_lines(system_, c, o_));
    }
    Table table;
    for (const GiNaC::symbol& u : c.unknowns) table.headers.push_back(spelling(u));
    table.headers.emplace_back("B");
    table.row_labels = labels;
    table.separator_before = c.unknowns.size();
    for (std::size_t r = 0; r < c.A.size(); ++r) {
      std::vector<std::string> row;
      for (const GiNaC::ex& e : c.A[r]) row.push_back(marked(e));
      row.push_back(marked(c.B[r]));
      table.cells.push_back(std::move(row));
    }
    if (o_.shows(ReportPart::symbolic)) {
      blank();
      line("  Symbolic A | B:");
      lines(layout_table(table, "    ", o_.width));
    }
    const CaseNumbers& n = solved.numbers;
    for (Eigen::Index r = 0; r < n.A.rows(); ++r) {
      auto& row = table.cells[static_cast<std::size_t>(r)];
      for (Eigen::Index col = 0; col < n.A.cols(); ++col) row[static_cast<std::size_t>(col)] = number(n.A(r, col));
      row.back() = number(n.B[r]);
    }
    if (o_.shows(ReportPart::numeric)) {
      blank();
      line("  Numeric A | B:");
      lines(layout_table(table, "    ", o_.width));
    }
    if (o_.shows(ReportPart::solution)) {
      Table solution;
      solution.headers = {"value", "unit", "meaning"};
      for (std::size_t i = 0; i < c.unknowns.size(); ++i) {
        solution.row_labels.push_back(spelling(c.unknowns[i]));
        solution.cells.push_back(
            {number(n.solution[static_cast<Eigen::Index>(i)] * angle_factor(unknowns[i]->unit, o_.angles)),
             unit(angle_unit_text(unknowns[i]->unit, o_.angles)), unknowns[i]->meaning});
      }
      blank();
      line("  Solution:");
      lines(layout_table(solution, "    ", o_.width));
    }
    if (!o_.shows(ReportPart::residual)) return;
    blank();
    const bool uni = style_ == Style::unicode;
    line(std::string(uni ? "  Residual ‖A q - B‖₂ = " : "  Residual ||A q - B||_2 = ") +
         format_number(n.residual, style_, 2));
    line(std::string(uni ? "  Condition number κ₂(A) = " : "  Condition number cond_2(A) = ") +
         format_number(n.condition, style_, 3) + " (largest / smallest singular value)");
  }

  void agreement() {
    heading("The cases agree", '-');
    prose(
        "Every body's acceleration and every joint force from every case, and the largest difference between "
        "cases. A * marks a value the case does not solve for but recovers: a body's acceleration through the "
        "kinematics of the spanning tree, a tree joint's force through the equation it was eliminated with.");
    Table table;
    for (const SolvedCase& c : s_.cases) table.headers.push_back("Case " + std::to_string(case_number(c.system.id)));
    table.headers.emplace_back(style_ == Style::unicode ? "max |Δ|" : "max |diff|");
    table.separator_before = s_.cases.size();
    for (const MechanismAgreement& a : s_.agreement) {
      table.row_labels.push_back(spelling(a.unknown));
      std::vector<std::string> row;
      for (std::size_t i = 0; i < a.values.size(); ++i)
        row.push_back(a.values[i] ? number(*a.values[i]) + (a.recovered[i] ? "*" : "") : "-");
      row.push_back(format_number(a.max_abs_difference, style_, 2));
      table.cells.push_back(std::move(row));
    }
    blank();
    lines(layout_table(table, "    ", o_.width));
  }

  const MechanismSolution& s_;
  const sym::System& system_;
  const ReportOptions& o_;
  Style style_;
  std::string out_;
};

}  // namespace

std::string case_heading(const CaseSystem& c) {
  return concat({"Case ", std::to_string(case_number(c.id)), ": ", c.title});
}

std::vector<std::string> case_equation_lines(const sym::System& system, const CaseSystem& c,
                                             const ReportOptions& options) {
  std::vector<const sym::SymbolInfo*> unknowns;
  for (const GiNaC::symbol& u : c.unknowns) unknowns.push_back(system.table().find(u));
  std::vector<std::string> out;
  for (std::size_t r = 0; r < c.A.size(); ++r) {
    const EquationSides eq = equation_sides(c.A[r], c.B[r], unknowns, system.table(), options.text_style);
    const std::string first = concat({"    ", parenthesized(c.labels[r]), "  "});
    for (std::string& l :
         wrap(first, eq.lhs + kBreakMark + " = " + eq.rhs, std::string(display_width(first) + 4, ' '), options.width))
      out.push_back(std::move(l));
  }
  return out;
}

CaseEquations case_equations(const sym::System& system, CaseId id) {
  const CaseSystem c = derive_case(system, id);
  return {case_heading(c), case_equation_lines(system, c, ReportOptions{})};
}

std::string mechanism_text(const MechanismSolution& solution, const ReportOptions& options) {
  return MechanismWriter(solution, options).run();
}

}  // namespace linkage
