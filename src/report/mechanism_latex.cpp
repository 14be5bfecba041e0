// The worked derivation of any mechanism as LaTeX or Markdown: one writer, the two formats
// differing only in how a heading, a paragraph, a display, a list and a table are written.
#include "report/mechanism_latex.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "report/expression_print.hpp"
#include "report/latex_math.hpp"
#include "report/markdown.hpp"
#include "report/math_document.hpp"
#include "report/mechanism_parts.hpp"
#include "report/notation.hpp"
#include "symbolic/energy.hpp"

namespace linkage {

namespace {

// Equation rows wrap beyond this many visible characters (latex_math's visible_length,
// which counts no spaces): the homework's longest row, (6.2), takes 50 and stays whole
// as in its golden files; 56 leaves room for a tag in a 12 cm text block.
constexpr std::size_t kEquationLimit = 56;
// A q = B prints in one display, as the homework's, when A has at most 8 columns and
// they take at most kMatrixWidth characters (the homework's widest A, Case 1's numbers,
// takes 60); otherwise in blocks of at most 8 columns and kBlockWidth characters, which
// leaves room for "A_1 =" and the column of unknowns beside each block.
constexpr std::size_t kMaxColumns = 8;
constexpr std::size_t kMatrixWidth = 64;
constexpr std::size_t kBlockWidth = 52;

using Matrix = std::vector<std::vector<std::string>>;

struct ColumnBlock {
  std::size_t begin = 0, end = 0;
};

// A_1 ... A_9, then A_{10}.
std::string subscript(std::string_view base, std::size_t index) {
  const std::string digits = std::to_string(index);
  return digits.size() == 1 ? concat({base, "_", digits}) : concat({base, "_{", digits, "}"});
}

std::string joined(const std::vector<std::string>& rows, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < rows.size(); ++i) out += concat({rows[i], i + 1 < rows.size() ? separator : "\n"});
  return out;
}

// Columns [begin, end) of every row.
Matrix columns(const Matrix& m, const ColumnBlock& block) {
  Matrix out;
  for (const auto& row : m)
    out.emplace_back(row.begin() + static_cast<std::ptrdiff_t>(block.begin),
                     row.begin() + static_cast<std::ptrdiff_t>(block.end));
  return out;
}

// One block when A fits as the homework's does, else greedy blocks; widths are each
// column's widest entry, symbolic or numeric, so both split at the same columns.
std::vector<ColumnBlock> column_blocks(const Matrix& symbolic, const Matrix& numeric) {
  const std::size_t n = symbolic.empty() ? 0 : symbolic.front().size();
  std::vector<std::size_t> width(n, 0);
  for (const Matrix* m : {&symbolic, &numeric})
    for (const auto& row : *m)
      for (std::size_t c = 0; c < n; ++c) width[c] = std::max(width[c], visible_length(row[c]) + 1);
  std::size_t total = 0;
  for (std::size_t w : width) total += w;
  if (n <= kMaxColumns && total <= kMatrixWidth) return {{0, n}};
  std::vector<ColumnBlock> blocks;
  std::size_t used = 0;
  for (std::size_t c = 0; c < n; ++c) {
    if (blocks.empty() || c - blocks.back().begin == kMaxColumns || used + width[c] > kBlockWidth) {
      blocks.push_back({c, c});
      used = 0;
    }
    blocks.back().end = c + 1;
    used += width[c];
  }
  return blocks;
}

class DerivationWriter : private MathDocument {
 public:
  DerivationWriter(const MechanismSolution& s, const ReportOptions& options, Format format)
      : MathDocument(format), s_(s), system_(*s.system), o_(options) {}

  std::string run() {
    write_mechanism_sections(*this, s_, o_);
    return out_;
  }

 private:
  template <class Writer>
  friend void linkage::write_mechanism_sections(Writer& w, const MechanismSolution& s, const ReportOptions& o);

  // ---- the mechanism's expressions ----

  [[nodiscard]] std::string tex(const GiNaC::ex& e) const { return print(e, system_.table(), Style::latex); }
  [[nodiscard]] const sym::SymbolInfo& info(const GiNaC::symbol& s) const { return *system_.table().find(s); }
  [[nodiscard]] double value(const GiNaC::ex& e) const { return value_at(e, s_.values); }
  [[nodiscard]] std::string number(double v) const { return format_number(v, Style::latex, o_.digits); }

  // "lhs &= formula \\ &= substituted = value unit", as the homework's derivation.
  [[nodiscard]] MathStep step(const std::string& lhs, const GiNaC::ex& formula, const std::string& unit_ascii) const {
    std::string result = number(value(formula));
    if (!unit_ascii.empty()) result += "\\ " + unit_text(unit_ascii, Style::latex);
    const std::string symbolic = tex(formula);
    const std::string numbers =
        print_substituted(formula, system_.table(), Style::latex, [&](const sym::SymbolInfo& symbol) {
          return format_number(value(symbol.symbol), Style::latex, symbol.role == sym::Role::parameter ? 0 : o_.digits);
        });
    if (symbolic == number(value(formula))) return {lhs, "", "", result};
    if (numbers == symbolic || numbers == number(value(formula))) return {lhs, mark_sums(symbolic), "", result};
    return {lhs, mark_sums(symbolic), mark_sums(numbers), result};
  }

  [[nodiscard]] std::string body_label(int body) const { return linkage::body_label(system_.mechanism(), body); }

  // ---- the sections ----

  void title() {
    const Mechanism& m = system_.mechanism();
    const std::string name = m.title.empty() ? m.name : m.title;
    if (latex()) {
      out_ += "% Worked solution of a mechanism, from `linkage solve`.\n";
      out_ += "% Paste into a document or a slide; needs \\usepackage{amsmath}.\n";
      if (!name.empty() || !m.description.empty())
        heading(concat({"Worked solution", name.empty() ? "" : ": ", name}), latex_escape(m.description));
      return;
    }
    out_ += concat({"# Worked solution", name.empty() ? "" : ": ", markdown_escape(name), "\n"});
    if (!m.description.empty()) paragraph(markdown_escape(m.description));
  }

  void inputs() {
    const Mechanism& m = system_.mechanism();
    heading("Inputs and definitions", "The parameters, in SI units, and the definitions in them.");
    Matrix rows;
    for (const Parameter& p : m.parameters)
      rows.push_back({inline_math(system_.table().find(p.name)->latex), number_cell(p.value, 0), unit_cell(p.unit),
                      text(p.meaning.empty() ? "parameter" : p.meaning)});
    table({"symbol", "value", "unit", "meaning"}, "lrll", rows);
    if (!m.definitions.empty()) {
      std::vector<MathStep> steps;
      for (const Definition& d : m.definitions) {
        const sym::SymbolInfo* symbol = system_.table().find(d.name);
        steps.push_back(step(symbol->latex, system_.constants().at(symbol->symbol), symbol->unit));
      }
      aligned(step_rows(steps, pad()));
    }
    new_paragraph("The initial state, in the generalized coordinates of the spanning tree:");
    Matrix state;
    for (const sym::GeneralizedCoordinate& g : system_.coordinates())
      for (const GiNaC::symbol* q : {&g.symbols.q, &g.symbols.q_dot}) {
        const sym::SymbolInfo& symbol = info(*q);
        state.push_back({inline_math(symbol.latex), number_cell(sym::to_double(s_.state.at(*q)), 0),
                         unit_cell(symbol.unit), text(symbol.meaning)});
      }
    table({"symbol", "value", "unit", "meaning"}, "lrll", state);
    new_paragraph(text(given_note(m)));
    if (!s_.closure_note.empty()) new_paragraph(text(s_.closure_note));
  }

  void inertia() {
    const std::vector<PinInertia> pins = pin_inertias(system_);
    heading("Moments of inertia",
            std::string("Each body's moment of inertia about its centre of mass, from its shape: the area integral for "
                        "a rectangle, $m L^2/12$ for a rod, $m r^2/2$ for a disc, none for a point mass.") +
                (pins.empty() ? ""
                              : " The parallel-axis theorem moves it to each pin $P$: $I^P = I + m \\lvert r "
                                "\\rvert^2$, $r$ from the centre of mass to $P$."));
    std::vector<MathStep> steps;
    std::vector<std::string> done;
    for (const sym::BodySystem& b : system_.bodies()) {
      if (!b.rotates) continue;
      const std::string name = info(GiNaC::ex_to<GiNaC::symbol>(b.inertia)).latex;
      if (std::find(done.begin(), done.end(), name) != done.end()) continue;
      done.push_back(name);
      steps.push_back(step(name, b.inertia_formula, "kg m^2"));
    }
    for (const PinInertia& p : pins) steps.push_back(step(p.latex, p.formula, "kg m^2"));
    if (!steps.empty()) aligned(step_rows(steps, pad()));
  }

  void constraints() {
    heading("The joints: constraints at position, velocity and acceleration level",
            "Each joint's constraint in the maximal coordinates of its bodies; the velocity and acceleration forms "
            "are its first and second time derivatives.");
    const Mechanism& m = system_.mechanism();
    for (std::size_t j = 0; j < m.joints.size(); ++j) {
      const Joint& joint = m.joints[j];
      const sym::JointSystem& js = system_.joints()[j];
      new_paragraph(text(concat({"Joint ", joint.name, ": ", kJointTypeNames[static_cast<std::size_t>(joint.type)],
                                 " between ", joint.bodies[0], ".", joint.points[0], " and ", joint.bodies[1], ".",
                                 joint.points[1], js.in_tree ? " (spanning tree)." : " (closes a loop)."})));
      std::vector<std::string> groups;
      for (const GiNaC::ex& phi : js.constraints) groups.push_back(levels(phi));
      aligned(joined(groups, " \\\\[1ex]\n"));
      // A row's constant (a gear's c_G): the rest of the row at the initial state.
      if (const GiNaC::ex& c = system_.joint_constant(static_cast<int>(j)); !c.is_zero()) {
        new_paragraph(text("Its constant, the rest of the row at the initial state:"));
        const MathStep at_start = step(tex(c), system_.constants().at(c), info(GiNaC::ex_to<GiNaC::symbol>(c)).unit);
        // c_G = (the rest of the row)|_{t=0} = its parameters' form = value.
        aligned(step_rows({{at_start.quantity, tex(GiNaC::expand(js.constraints.at(0) + c)) + " \\Big|_{t = 0}",
                            at_start.formula, at_start.result}},
                          pad()));
      }
    }
    for (const sym::DriverSystem& d : system_.drivers()) {
      const Driver& driver = m.drivers[static_cast<std::size_t>(d.index)];
      const Joint& joint = m.joints[static_cast<std::size_t>(d.joint)];
      new_paragraph(concat({text(concat({"Driver ", driver.name, ": ", joint_type_name(joint.type), " ", joint.name,
                                         " on its motion ", driver.motion.text, ", a row of every case; its ",
                                         joint_type_info(joint.type).driver_column, " "})),
                            inline_math(tex(d.unknown)),
                            text(concat({" on ", joint.bodies[1], " is an unknown of every case."}))}));
      aligned(levels(d.constraint));
    }
  }

  // A constraint row at position, velocity and acceleration level, as aligned rows.
  std::string levels(const GiNaC::ex& phi) {
    static constexpr std::array<const char*, 3> kLevels{"position", "velocity", "acceleration"};
    std::vector<std::string> rows;
    GiNaC::ex form = phi;
    for (const char* level : {kLevels[0], kLevels[1]}) {
      rows.push_back(
          equation_row(tex(GiNaC::expand(form)), "0", concat({" && \\text{", level, "}"}), kEquationLimit, pad()));
      form = system_.time_derivative(form);
    }
    // The acceleration level as Case 1 writes it: the accelerations on the left.
    const EquationSides eq = acceleration_form(system_, phi, Style::latex);
    rows.push_back(equation_row(eq.lhs, eq.rhs, concat({" && \\text{", kLevels[2], "}"}), kEquationLimit, pad()));
    std::string out = joined(rows, " \\\\\n");
    out.pop_back();
    return out;
  }

  void energy() {
    const GiNaC::ex power = sym::nonconservative_power(system_);
    std::string note = power.is_zero()
                           ? "Only conservative forces work on the mechanism: its energy $E = T + V$ stays constant."
                           : "The dampers and applied loads work at the rate $P$; $E = T + V$ changes at that rate.";
    if (!system_.drivers().empty())
      note = concat({power.is_zero() ? "$E = T + V$ changes at the drivers' power"
                                     : "The dampers and applied loads work at the rate $P$; $E = T + V$ changes at "
                                       "$P$ and at the drivers' power",
                     ", each driver's torque or force times its joint's relative rate."});
    if (!touches_ground(system_.mechanism()))
      note +=
          " Nothing touches the ground: the horizontal momentum and the angular momentum $H_c$ about the centre of "
          "mass stay constant, and the vertical momentum changes at "
          "the rate of gravity.";
    heading("Energy and momentum", note);
    std::vector<MathStep> steps;
    for (const sym::SymbolInfo& symbol : system_.table().all())  // the springs' lengths, used from here on
      if (symbol.role == sym::Role::length)
        steps.push_back(step(symbol.latex, system_.lengths().at(symbol.symbol), "m"));
    const GiNaC::ex T = sym::kinetic_energy(system_);
    const GiNaC::ex V = with_lengths(system_, sym::potential_energy(system_));
    const sym::Vec2 p = sym::linear_momentum(system_);
    const double v = value(V);
    steps.push_back(step("T", T, "J"));
    steps.push_back(step("V", V, "J"));
    steps.push_back({"E", "T + V", concat({number(value(T)), v < 0 ? " - " : " + ", number(std::abs(v))}),
                     concat({number(value(T) + v), "\\ ", unit_text("J", Style::latex)})});
    if (!power.is_zero()) steps.push_back(step("P", with_lengths(system_, power), "W"));
    steps.push_back(step("p_x", p.x, "kg m/s"));
    steps.push_back(step("p_y", p.y, "kg m/s"));
    steps.push_back(step("H_O", sym::angular_momentum(system_), "kg m^2/s"));
    if (!touches_ground(system_.mechanism()))
      steps.push_back(step("H_c", sym::angular_momentum_about_centre(system_), "kg m^2/s"));
    aligned(step_rows(steps, pad()));
  }

  void forces() {
    heading("Forces and moments on each body",
            "Each body's free-body diagram as a list: a joint's force is the force its second body exerts on its "
            "first, so the first body feels $+F$ and the second $-F$.");
    if (!system_.lengths().empty())
      new_paragraph(
          "A spring of length $l$ (above) between points $A$ and $B$ pulls each towards the other with "
          "$k (l - l_0) + c \\dot{l}$, $\\dot{l} = (B - A) \\cdot (\\dot{B} - \\dot{A}) / l$.");
    const WrittenValues written = written_state_values(system_);
    if (!written.values.empty()) {
      new_paragraph(text("Values that read the state, as the file writes them:"));
      std::vector<std::string> items;
      for (const WrittenValue& v : written.values)
        items.push_back(concat(
            {text(v.what), ": ", latex() ? concat({"\\texttt{", text(v.text), "}"}) : concat({"`", v.text, "`"})}));
      list(items);
      std::string rewritten;
      for (const auto& [name, expression] : written.rewritten)
        rewritten +=
            concat({rewritten.empty() ? "" : ", ", text(name), " ", inline_math(concat({"= ", tex(expression)}))});
      if (!rewritten.empty())
        new_paragraph(concat({text("Case 1 writes them in maximal coordinates: "), rewritten,
                              text("; Cases 2 and 3 keep a slider's travel and rate as their own coordinate.")}));
    }
    const Mechanism& m = system_.mechanism();
    for (std::size_t b = 0; b < system_.bodies().size(); ++b) {
      new_paragraph(text(concat({"On ", body_label(static_cast<int>(b)), ":"})));
      std::vector<std::string> items;
      for (std::size_t j = 0; j < m.joints.size(); ++j) {
        const Joint& joint = m.joints[j];
        const sym::JointSystem& js = system_.joints()[j];
        const bool first = m.bodies[b].name == joint.bodies[0];
        if (!first && m.bodies[b].name != joint.bodies[1]) continue;
        const GiNaC::ex sign = first ? 1 : -1;
        std::string item =
            concat({inline_math(concat({"\\left(", tex(sign * js.force.x), ", ", tex(sign * js.force.y), "\\right)"})),
                    " at ", text(joint.points[first ? 0 : 1])});
        if (!js.moment.is_zero()) item += concat({", moment ", inline_math(tex(sign * js.moment))});
        const std::string from = linkage::body_label(m, first ? joint.bodies[1] : joint.bodies[0]);
        items.push_back(concat(
            {item, ": ",
             text(concat({kJointTypeNames[static_cast<std::size_t>(joint.type)], " ", joint.name, ", from ", from}))}));
      }
      std::vector<sym::Load> loads = system_.loads();
      for (const sym::DriverSystem& d : system_.drivers()) loads.insert(loads.end(), d.loads.begin(), d.loads.end());
      for (const sym::Load& load : loads) {
        if (load.body != static_cast<int>(b)) continue;
        std::string item;
        if (!(load.force.x.is_zero() && load.force.y.is_zero())) {
          item = inline_math(concat({"\\left(", tex(load.force.x), ", ", tex(load.force.y), "\\right)"}));
          const std::string place = load_place(system_, b, load);
          if (!place.empty()) item += concat({" at ", text(place)});
        }
        if (!load.moment.is_zero())
          item += concat({item.empty() ? "moment " : ", moment ", inline_math(tex(load.moment))});
        items.push_back(concat({item, ": ", text(load.source)}));
      }
      if (items.empty()) items.emplace_back("none");
      list(items);
    }
  }

  void newton_euler() {
    heading("Newton-Euler equations of each body",
            "$m a$ = the sum of the forces, and $I \\alpha$ = the sum of the moments about the centre of mass, in "
            "maximal coordinates; Case 1 takes them as they are, Cases 2 and 3 write them in the generalized "
            "coordinates.");
    const CaseSystem case1 = maximal_case(system_);
    std::vector<const sym::SymbolInfo*> unknowns;
    for (const GiNaC::symbol& u : case1.unknowns) unknowns.push_back(&info(u));
    std::size_t row = 0;
    for (std::size_t b = 0; b < system_.bodies().size(); ++b) {
      new_paragraph(text(concat({"For ", body_label(static_cast<int>(b)), ":"})));
      std::vector<std::string> rows;
      for (std::size_t k = 0; k < system_.newton_euler()[b].rows.size(); ++k, ++row) {
        const EquationSides eq = equation_sides(case1.A[row], case1.B[row], unknowns, system_.table(), Style::latex);
        rows.push_back(equation_row(eq.lhs, eq.rhs, "", kEquationLimit, pad()));
      }
      aligned(joined(rows, " \\\\\n"));
    }
  }

  // A q = B in one display as the homework's, or A in column blocks beside their unknowns.
  void matrix_display(const Matrix& A, const std::vector<std::string>& B, const CaseSystem& c,
                      const std::vector<ColumnBlock>& blocks) {
    std::vector<std::string> names;
    for (const GiNaC::symbol& u : c.unknowns) names.push_back(info(u).latex);
    const std::string gaps = latex() ? "  \\setlength{\\arraycolsep}{3pt}\n" : "";
    if (blocks.size() == 1) {
      const std::string equation = matrix_equation(A, names, B, c.labels, {false, latex(), latex()}, pad());
      if (latex())
        out_ += concat({"\\begin{multline*}\n", gaps, equation, "\\end{multline*}\n"});
      else
        math(equation);
      return;
    }
    std::vector<std::string> comments;
    if (latex())
      for (const std::string& label : c.labels) comments.push_back(parenthesized(label));
    for (std::size_t k = 0; k < blocks.size(); ++k) {
      const std::vector<std::string> block_names(names.begin() + static_cast<std::ptrdiff_t>(blocks[k].begin),
                                                 names.begin() + static_cast<std::ptrdiff_t>(blocks[k].end));
      display(concat({gaps, pad(), subscript("A", k + 1), " =\n", bmatrix(columns(A, blocks[k]), comments, pad()),
                      pad(), ", \\qquad ", subscript("q", k + 1), " =\n", inline_column(block_names, pad())}));
    }
    display(concat({pad(), "B =\n", column_vector(B, comments, pad())}));
  }

  [[nodiscard]] static std::string block_sum(std::size_t blocks) {
    std::string sum;
    for (std::size_t k = 1; k <= blocks; ++k)
      sum += concat({k == 1 ? "" : " + ", subscript("A", k), " ", subscript("q", k)});
    return sum + " = B";
  }

  void one_case(const SolvedCase& solved) {
    const CaseSystem& c = solved.system;
    const CaseNumbers& n = solved.numbers;
    const bool symbolic = o_.shows(ReportPart::symbolic);
    heading(concat({"Case ", std::to_string(case_number(c.id)), ": ", c.title}),
            symbolic ? "The equations, one per row of $A q = B$:" : "");
    std::vector<const sym::SymbolInfo*> unknowns;
    for (const GiNaC::symbol& u : c.unknowns) unknowns.push_back(&info(u));
    Matrix A_symbolic, A_numeric;
    std::vector<std::string> B_symbolic, B_numeric;
    for (std::size_t r = 0; r < c.A.size(); ++r) {
      A_symbolic.emplace_back();
      A_numeric.emplace_back();
      for (std::size_t col = 0; col < c.unknowns.size(); ++col) {
        A_symbolic.back().push_back(tex(c.A[r][col]));
        A_numeric.back().push_back(number(n.A(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(col))));
      }
      B_symbolic.push_back(tex(c.B[r]));
      B_numeric.push_back(number(n.B[static_cast<Eigen::Index>(r)]));
    }
    const std::vector<ColumnBlock> blocks = column_blocks(A_symbolic, A_numeric);
    const std::string in_blocks = blocks.size() == 1
                                      ? ""
                                      : concat({", with $A$ in blocks of columns, $", block_sum(blocks.size()),
                                                "$, each $A_k$ beside the unknowns $q_k$ its columns multiply"});
    if (symbolic) {
      std::vector<std::string> rows;
      for (std::size_t r = 0; r < c.A.size(); ++r) {
        const EquationSides eq = equation_sides(c.A[r], c.B[r], unknowns, system_.table(), Style::latex);
        rows.push_back(equation_row(eq.lhs, eq.rhs, tag(c.labels[r]), kEquationLimit, pad()));
      }
      aligned(joined(rows, " \\\\\n"));
      paragraph(concat({"In matrix form, rows in the order of the equations", in_blocks, ":"}));
      matrix_display(A_symbolic, B_symbolic, c, blocks);
    }
    if (o_.shows(ReportPart::numeric)) {
      paragraph(symbolic || blocks.size() == 1 ? "Numerically:" : concat({"Numerically", in_blocks, ":"}));
      matrix_display(A_numeric, B_numeric, c, blocks);
    }
    if (o_.shows(ReportPart::solution)) {
      paragraph("Solution:");
      std::vector<std::string> names, values, units;
      std::vector<SolutionRow> rows;
      for (std::size_t i = 0; i < c.unknowns.size(); ++i) {
        const double v = n.solution[static_cast<Eigen::Index>(i)];
        names.push_back(unknowns[i]->latex);
        values.push_back(number(v));
        units.push_back(unit_text(unknowns[i]->unit, Style::latex));
        rows.push_back({unknowns[i]->latex, v, unknowns[i]->unit, markdown_escape(unknowns[i]->meaning)});
      }
      if (latex())
        display(solution_equation(names, values, units, pad()));
      else
        out_ += solution_markdown(rows, o_.digits);
    }
    if (o_.shows(ReportPart::residual)) display(concat({pad(), residual_line(n.residual, n.condition), "\n"}));
  }

  void agreement() {
    const std::string star = latex() ? "$^{*}$" : "\\*";
    heading("The cases agree",
            concat({"Every body's acceleration and every joint force from every case, and the largest difference "
                    "between cases. A ",
                    star,
                    " marks a value the case does not solve for but recovers: a body's acceleration through the "
                    "kinematics of the spanning tree, a tree joint's force through the equation it was eliminated "
                    "with."}));
    std::vector<int> cases;
    for (const SolvedCase& c : s_.cases) cases.push_back(case_number(c.system.id));
    std::vector<AgreementRow> rows;
    for (const MechanismAgreement& a : s_.agreement)
      rows.push_back({info(a.unknown).latex, a.values, a.recovered, a.max_abs_difference});
    out_ += latex() ? agreement_tabular(cases, rows, o_.digits) : agreement_markdown(cases, rows, o_.digits);
  }

  const MechanismSolution& s_;
  const sym::System& system_;
  const ReportOptions& o_;
};

}  // namespace

std::string mechanism_latex(const MechanismSolution& solution, const ReportOptions& options) {
  return DerivationWriter(solution, options, MathDocument::Format::latex).run();
}

std::string mechanism_markdown(const MechanismSolution& solution, const ReportOptions& options) {
  return DerivationWriter(solution, options, MathDocument::Format::markdown).run();
}

std::string mechanism_html(const MechanismSolution& solution, const ReportOptions& options, std::size_t limit) {
  // The HTML is longer than its Markdown: a Markdown over the limit is not converted at all.
  const std::string markdown = mechanism_markdown(solution, options);
  std::string html = markdown.size() <= limit ? markdown_to_html(markdown) : std::string();
  if (!html.empty() && html.size() <= limit) return html;
  std::string cases;
  for (const SolvedCase& c : solution.cases) {
    if (!cases.empty()) cases += ',';
    cases += std::to_string(case_number(c.system.id));
  }
  return concat({"<p>The worked solution is longer than a page holds (more than ",
                 format_number(static_cast<double>(limit) / 1e6, Style::unicode, 3),
                 " MB of HTML): <code>linkage solve --case ", solution.cases.size() == 1 ? cases : "all",
                 " --format markdown</code> prints it, with this clip&#39;s mechanism and settings.</p>\n"});
}

}  // namespace linkage
