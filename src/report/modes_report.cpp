#include "report/modes_report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <utility>

#include "core/number_format.hpp"
#include "report/expression_print.hpp"
#include "report/json_layout.hpp"
#include "report/latex_math.hpp"
#include "report/math_document.hpp"
#include "report/notation.hpp"
#include "report/text_layout.hpp"

namespace linkage {
namespace {

// A piece of the report's words, of a heading or of a table's cell: plain text (the text
// format's; escaped for LaTeX and Markdown), or with its LaTeX spelling when that differs
// (math in $...$, read by both LaTeX and Markdown), or a number to `digits` (0: the
// report's) in each format's notation.
struct Piece {
  std::string plain;
  std::string tex;
  std::optional<double> number;
  int digits = 0;
};
using Pieces = std::vector<Piece>;

Piece words(std::string plain) { return {std::move(plain), "", std::nullopt, 0}; }
Piece formula(std::string plain, std::string_view tex) { return {std::move(plain), concat({"$", tex, "$"}), {}, 0}; }
// Words and math in one piece: `tex` as written (text-mode LaTeX, math in $...$).
Piece spelled(std::string plain, std::string tex) { return {std::move(plain), std::move(tex), std::nullopt, 0}; }
Piece value(double v, int digits = 0) { return {"", "", v, digits}; }

// A table: headed columns, labelled rows (the text's layout_table; LaTeX's tabular and
// Markdown's pipe table with the labels as their first column).
struct Grid {
  Pieces headers;
  Pieces row_labels;
  std::vector<Pieces> cells;
  std::size_t separator_before = 0;  // the text's " | " before this column (0: none)
};

// How a format writes the blocks of the modes report; modes_sections says what they hold.
class ModesOut {
 public:
  virtual ~ModesOut() = default;
  virtual void title(const Pieces& text) = 0;
  virtual void section(const Pieces& heading) = 0;
  virtual void paragraph(const Pieces& text) = 0;
  virtual void table(const Grid& grid) = 0;
  /// The nonzero entries of a symbolic matrix over the tree coordinates, "M[q_i, q_j] = ...".
  virtual void entries(const std::string& name, const std::string& tex_name,
                       const std::vector<std::vector<GiNaC::ex>>& A, bool symmetric) = 0;
  /// A matrix in numbers, M = [...], its rows and columns labelled by coordinates.
  virtual void matrix(const Piece& name, const Eigen::MatrixXd& A, const Pieces& rows, const Pieces& columns) = 0;
  /// R of dq = R dz: the tree coordinates' rows, the independent ones' columns.
  virtual void reduction(const Eigen::MatrixXd& R, const Pieces& rows, const Pieces& columns) = 0;
  [[nodiscard]] virtual std::string take() = 0;
};

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += concat({out.empty() ? "" : ", ", n});
  return out;
}

// The sections of `linkage modes` in every format: the equilibrium, the expansion in
// symbols with the reduction R, M, C, K in numbers, the modes (and each body's motion
// when a loop ties the bodies' coordinates), and with --verify the check.
void modes_sections(ModesOut& out, const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                    const std::vector<ModeCheck>* checks, Style style) {
  const Mechanism& m = system.mechanism();
  // The tree coordinates by name with their symbols (text: θ₂ in `style`), and the independent ones.
  Pieces tree, symbols, independent;
  for (std::size_t i = 0; i < linear.tree_coordinates.size(); ++i) {
    const GiNaC::symbol& q = system.coordinates()[i].symbols.q;
    const std::string tex = print(q, system.table(), Style::latex);
    tree.push_back(formula(linear.tree_coordinates[i], tex));
    symbols.push_back(formula(print(q, system.table(), style), tex));
  }
  for (std::size_t k : linear.independent) independent.push_back(tree[k]);
  out.title({words(concat({"Small vibrations of ", m.name, ": ", m.title}))});

  out.section({words("1. The equilibrium")});
  if (linear.at_initial) {
    const bool balanced = linear.residual <= 1e-10 * linear.force_scale || linear.residual == 0;
    Pieces text{words("At the file's [initial] coordinates, rates zero (--at-initial). ")};
    if (balanced)
      text.insert(text.end(), {words("It is an equilibrium: the largest generalized force there is "),
                               value(linear.residual, 3), words(".")});
    else
      text.insert(text.end(),
                  {words("It is not an equilibrium: the generalized forces there reach "), value(linear.residual, 3),
                   words(" (N or N m), so the motion drifts away from it while it vibrates.")});
    out.paragraph(text);
  } else {
    out.paragraph({words("Found by Newton's method from the file's [initial] coordinates with the rates zero and the "
                         "loads at "),
                   formula("t = 0", "t = 0"),
                   words(": " + std::to_string(linear.newton_steps) + " steps; the largest generalized force left is "),
                   value(linear.residual, 3), words(" (N or N m).")});
  }
  {
    Grid grid;
    grid.headers = {words("coordinate"), words("value"), words("unit")};
    for (std::size_t i = 0; i < linear.tree_coordinates.size(); ++i) {
      grid.row_labels.push_back(symbols[i]);
      grid.cells.push_back({words(linear.tree_coordinates[i]), value(linear.equilibrium[static_cast<Eigen::Index>(i)]),
                            words(linear.tree_units[i])});
    }
    out.table(grid);
  }

  out.section({words("2. The expansion")});
  const Piece lambda = formula("lambda", "\\lambda");
  Pieces expansion{
      words("Lagrange's rows "),
      formula("F(q, q', q'', lambda) = M(q) q'' - Q(q, q', t, lambda) = 0",
              "F(q, \\dot q, \\ddot q, \\lambda) = M(q)\\, \\ddot q - Q(q, \\dot q, t, \\lambda) = 0"),
      words(" (the loop forces and drivers' torques "),
      lambda,
      words(" among the loads "),
      formula("Q", "Q"),
      words(") to first order about the equilibrium, rates and accelerations zero: "),
      formula("M0 dq'' + C0 dq' + K0 dq + (dF/dlambda) dlambda = 0",
              "M_0\\, \\delta\\ddot q + C_0\\, \\delta\\dot q + K_0\\, \\delta q + (\\partial F/\\partial\\lambda)\\, "
              "\\delta\\lambda = 0"),
      words(", with "),
      formula("C0 = dF/dq'", "C_0 = \\partial F/\\partial\\dot q"),
      words(" and "),
      formula("K0 = dF/dq", "K_0 = \\partial F/\\partial q"),
      words(" there")};
  if (linear.multipliers.size() > 0)
    expansion.insert(expansion.end(), {words(" ("), lambda,
                                       words(" held at its equilibrium value: the constraints' "
                                             "curvature).")});
  else
    expansion.push_back(words("."));
  out.paragraph(expansion);
  out.entries("M", "M_0", linear.M_symbolic, true);
  out.entries("C", "C_0", linear.C_symbolic, false);
  out.entries("K", "K_0", linear.K_symbolic, false);
  if (linear.multipliers.size() > 0) {
    out.paragraph(
        {words(concat({"The ", system.drivers().empty() ? "loop" : "loop and driver", " rows "})),
         formula("J0 dq = 0", "J_0\\, \\delta q = 0"), words(" leave the independent coordinates "),
         formula(concat({"z = (", joined(linear.coordinates), ")"}),
                 concat({"z = (\\text{", joined(linear.coordinates), "})"})),
         words(": "), formula("dq = R dz", "\\delta q = R\\, \\delta z"), words(", and "),
         formula("M = R^T M0 R, C = R^T C0 R, K = R^T K0 R", "M = R^T M_0 R,\\ C = R^T C_0 R,\\ K = R^T K_0 R"),
         words(" ("), formula("R^T (dF/dlambda) = 0", "R^T (\\partial F/\\partial\\lambda) = 0"), words(" removes "),
         formula("dlambda", "\\delta\\lambda"), words(").")});
    out.reduction(linear.R, tree, independent);
  }

  out.section(
      {words("3. The linearized equations "), formula("M z'' + C z' + K z = 0", "M \\ddot z + C \\dot z + K z = 0")});
  out.matrix(formula("M", "M"), linear.M, independent, independent);
  if (modes.damped) out.matrix(formula("C", "C"), linear.C, independent, independent);
  out.matrix(formula("K", "K"), linear.K, independent, independent);

  out.section({words("4. The modes: "), formula("K v = w^2 M v", "K v = \\omega^2 M v")});
  const bool neutral = std::any_of(modes.modes.begin(), modes.modes.end(),
                                   [](const Mode& mode) { return mode.kind == Mode::Kind::neutral; });
  if (modes.stable)
    out.paragraph(
        {words("The equilibrium is stable: every mode oscillates" + std::string(modes.damped ? " and decays" : "") +
               (neutral ? ", but for a neutral mode, which moves freely (no stiffness)." : "."))});
  else
    out.paragraph({words("The equilibrium is unstable: a mode grows as "), formula("exp(sigma t)", "e^{\\sigma t}"),
                   words(", "), formula("sigma", "\\sigma"), words(" its growth rate.")});
  Grid grid;
  grid.headers = {words("kind"), spelled("w (rad/s)", "$\\omega$ (rad/s)"), spelled("f (Hz)", "$f$ (Hz)"),
                  spelled("period (s)", "$T$ (s)")};
  if (modes.damped) grid.headers.push_back(formula("zeta", "\\zeta"));
  if (!modes.stable) grid.headers.push_back(spelled("sigma (1/s)", "$\\sigma$ (1/s)"));
  grid.separator_before = grid.headers.size();
  grid.headers.insert(grid.headers.end(), independent.begin(), independent.end());
  const Piece none = words("-");
  for (std::size_t k = 0; k < modes.modes.size(); ++k) {
    const Mode& mode = modes.modes[k];
    const bool oscillates = mode.kind == Mode::Kind::oscillation;
    grid.row_labels.push_back(words("mode " + std::to_string(k + 1)));
    Pieces row{words(kind_word(mode.kind)), oscillates ? value(mode.omega) : none,
               oscillates ? value(mode.omega / (2 * std::numbers::pi)) : none,
               oscillates ? value(2 * std::numbers::pi / mode.omega) : none};
    if (modes.damped) row.push_back(oscillates ? value(mode.damping_ratio) : none);
    if (!modes.stable) row.push_back(mode.kind == Mode::Kind::unstable ? value(mode.growth_rate) : none);
    for (Eigen::Index i = 0; i < mode.shape.size(); ++i) row.push_back(value(mode.shape[i]));
    grid.cells.push_back(std::move(row));
  }
  out.table(grid);
  out.paragraph({words("Shapes in the independent coordinates, each scaled so its largest component is 1.")});
  if (linear.tree_coordinates.size() > linear.coordinates.size()) {
    // A loop ties the bodies' coordinates: each body's share of the motion.
    out.paragraph({words("Each body's motion: the mode in every coordinate of the spanning tree, "),
                   formula("dq = R v", "\\delta q = R v"), words(", scaled so its largest component is 1.")});
    Grid bodies;
    bodies.headers = tree;
    for (std::size_t k = 0; k < modes.modes.size(); ++k) {
      const Eigen::VectorXd& shape = modes.modes[k].tree_shape;
      const double largest = shape.cwiseAbs().maxCoeff();
      bodies.row_labels.push_back(words("mode " + std::to_string(k + 1)));
      Pieces row;
      for (Eigen::Index i = 0; i < shape.size(); ++i) row.push_back(value(shape[i] / largest));
      bodies.cells.push_back(std::move(row));
    }
    out.table(bodies);
  }
  if (checks == nullptr) return;

  out.section({words("5. The check: the full equations")});
  if (checks->empty()) {
    out.paragraph({words("No mode oscillates, so there is no frequency to check.")});
    return;
  }
  Pieces how{words("Each oscillating mode's shape, its largest coordinate moved by "),
             value(checks->front().amplitude, 3),
             words(" (rad or m), starts the nonlinear equations at rest (DOP853, tolerances 1e-13, loops closed); the "
                   "upward zero crossings of the mode's coordinate over ten periods give the frequency the motion "
                   "has")};
  if (modes.damped)
    how.insert(how.end(),
               {words(" (with damping, "), formula("w sqrt(1 - zeta^2)", "\\omega\\sqrt{1 - \\zeta^2}"), words(").")});
  else
    how.push_back(words("."));
  out.paragraph(how);
  Grid checked;
  checked.headers = {words("predicted (rad/s)"), words("measured (rad/s)"), words("relative difference"),
                     words("crossings")};
  bool agree = true;
  for (const ModeCheck& check : *checks) {
    checked.row_labels.push_back(words("mode " + std::to_string(check.mode + 1)));
    checked.cells.push_back({value(check.predicted), value(check.measured), value(check.relative_error(), 2),
                             words(std::to_string(check.crossings))});
    agree = agree && check.relative_error() <= kModeCheckTolerance;
  }
  out.table(checked);
  if (agree)
    out.paragraph({words("Every mode agrees with the motion to "), value(kModeCheckTolerance, 1), words(".")});
  else
    out.paragraph({words("A mode DISAGREES with the motion by more than "), value(kModeCheckTolerance, 1),
                   words(": the linearization does not describe this equilibrium.")});
}

// ---- the formats ----

class TextOut final : public ModesOut {
 public:
  TextOut(const sym::System& system, const ReportOptions& o) : system_(system), o_(o) {}

  void title(const Pieces& text) override { out_ += plain(text) + "\n\n"; }
  void section(const Pieces& heading) override {
    if (sections_++ > 0) out_ += "\n";
    out_ += plain(heading) + "\n";
  }
  void paragraph(const Pieces& text) override { lines(wrap_words(plain(text), "", o_.width)); }
  void table(const Grid& grid) override {
    Table table;
    for (const Piece& h : grid.headers) table.headers.push_back(plain(h));
    for (const Piece& l : grid.row_labels) table.row_labels.push_back(plain(l));
    for (const Pieces& row : grid.cells) {
      table.cells.emplace_back();
      for (const Piece& cell : row) table.cells.back().push_back(plain(cell));
    }
    table.separator_before = grid.separator_before;
    lines(layout_table(table, "  ", o_.width));
  }
  void entries(const std::string& name, const std::string&, const std::vector<std::vector<GiNaC::ex>>& A,
               bool symmetric) override {
    bool any = false;
    for (std::size_t i = 0; i < A.size(); ++i)
      for (std::size_t j = symmetric ? i : 0; j < A[i].size(); ++j) {
        if (A[i][j].is_zero()) continue;
        any = true;
        const std::string first = concat({"  ", name, "[", symbol(i), ", ", symbol(j), "] = "});
        lines(wrap(first, print(A[i][j], system_.table(), o_.text_style), "      ", o_.width));
      }
    if (!any) out_ += concat({"  ", name, " = 0\n"});
  }
  void matrix(const Piece& name, const Eigen::MatrixXd& A, const Pieces& rows, const Pieces& columns) override {
    out_ += concat({"  ", name.plain, ":\n"});
    reduction(A, rows, columns);
  }
  void reduction(const Eigen::MatrixXd& R, const Pieces& rows, const Pieces& columns) override {
    Grid grid;
    grid.headers = columns;
    grid.row_labels = rows;
    for (Eigen::Index i = 0; i < R.rows(); ++i) {
      grid.cells.emplace_back();
      for (Eigen::Index j = 0; j < R.cols(); ++j) grid.cells.back().push_back(value(R(i, j)));
    }
    table(grid);
  }
  [[nodiscard]] std::string take() override { return std::exchange(out_, {}); }

 private:
  [[nodiscard]] std::string plain(const Piece& p) const {
    return p.number ? format_significant(*p.number, p.digits > 0 ? p.digits : o_.digits) : p.plain;
  }
  [[nodiscard]] std::string plain(const Pieces& pieces) const {
    std::string out;
    for (const Piece& p : pieces) out += plain(p);
    return out;
  }
  [[nodiscard]] std::string symbol(std::size_t i) const {
    return print(system_.coordinates()[i].symbols.q, system_.table(), o_.text_style);
  }
  void lines(const std::vector<std::string>& text) {
    for (const std::string& line : text) out_ += line + "\n";
  }

  const sym::System& system_;
  const ReportOptions& o_;
  std::string out_;
  int sections_ = 0;
};

// LaTeX (a fragment needing amsmath) and Markdown (math in $ and $$), as solve's
// mechanism_latex writes them: run-in headings, tabulars or pipe tables, the symbolic
// entries in align rows, the matrices as bmatrix.
class MathOut final : public ModesOut, private MathDocument {
 public:
  MathOut(const sym::System& system, const ReportOptions& o, Format format)
      : MathDocument(format), system_(system), o_(o) {}

  void title(const Pieces& text) override {
    if (latex()) {
      out_ += "% Small vibrations of a mechanism, from `linkage modes`.\n";
      out_ += "% Paste into a document or a slide; needs \\usepackage{amsmath}.\n";
      heading(plain(text), "");
      return;
    }
    out_ += concat({"# ", formatted(text), "\n"});
  }
  void section(const Pieces& heading) override {
    if (latex())
      out_ +=
          concat({"\n% ---- ", plain(heading), " ----\n\\par\\medskip\\noindent\\textbf{", formatted(heading), ".}\n"});
    else
      out_ += concat({"\n## ", formatted(heading), "\n"});
    run_in_ = latex();
  }
  void paragraph(const Pieces& text) override {
    if (std::exchange(run_in_, false))
      MathDocument::paragraph(formatted(text));
    else
      new_paragraph(formatted(text));
  }
  void table(const Grid& grid) override {
    std::vector<std::string> headers{""};
    std::string align = "l";
    for (std::size_t c = 0; c < grid.headers.size(); ++c) {
      headers.push_back(formatted(grid.headers[c]));
      const bool numbers = std::all_of(grid.cells.begin(), grid.cells.end(), [&](const Pieces& row) {
        return row[c].number.has_value() || row[c].plain == "-" ||
               (!row[c].plain.empty() && std::isdigit(static_cast<unsigned char>(row[c].plain.front())) != 0);
      });
      align += numbers ? 'r' : 'l';
    }
    std::vector<std::vector<std::string>> rows;
    for (std::size_t r = 0; r < grid.cells.size(); ++r) {
      rows.push_back({formatted(grid.row_labels[r])});
      for (const Piece& cell : grid.cells[r]) rows.back().push_back(formatted(cell));
    }
    // Narrower gaps than LaTeX's 6pt: the modes' tables are wide (a column per coordinate).
    if (latex()) out_ += "{\\setlength{\\tabcolsep}{4pt}%\n";
    MathDocument::table(headers, align, rows);
    if (latex()) out_ += "}\n";
    run_in_ = false;
  }
  void entries(const std::string&, const std::string& tex_name, const std::vector<std::vector<GiNaC::ex>>& A,
               bool symmetric) override {
    std::vector<std::string> rows;
    for (std::size_t i = 0; i < A.size(); ++i)
      for (std::size_t j = symmetric ? i : 0; j < A[i].size(); ++j)
        if (!A[i][j].is_zero())
          rows.push_back(equation_row(concat({tex_name, "[", symbol(i), ", ", symbol(j), "]"}), tex(A[i][j]), "",
                                      kEquationLimit, pad()));
    if (rows.empty()) {
      display(concat({pad(), tex_name, " = 0\n"}));
      return;
    }
    std::string joined_rows;
    for (std::size_t r = 0; r < rows.size(); ++r)
      joined_rows += concat({rows[r], r + 1 < rows.size() ? " \\\\\n" : "\n"});
    aligned(joined_rows);
  }
  void matrix(const Piece& name, const Eigen::MatrixXd& A, const Pieces&, const Pieces&) override {
    display(concat({pad(), name.tex.substr(1, name.tex.size() - 2), " =\n", bmatrix(numbers(A), {}, pad())}));
  }
  void reduction(const Eigen::MatrixXd& R, const Pieces& rows, const Pieces& columns) override {
    display(concat({deltas(rows), pad(), "=\n", bmatrix(numbers(R), {}, pad()), deltas(columns)}));
  }
  [[nodiscard]] std::string take() override { return std::exchange(out_, {}); }

 private:
  // Equation rows wrap beyond this many visible characters, as solve's do.
  static constexpr std::size_t kEquationLimit = 56;

  [[nodiscard]] std::string formatted(const Piece& p) const {
    if (p.number) return number_cell(*p.number, p.digits > 0 ? p.digits : o_.digits);
    return p.tex.empty() ? text(p.plain) : p.tex;
  }
  [[nodiscard]] std::string formatted(const Pieces& pieces) const {
    std::string out;
    for (const Piece& p : pieces) out += formatted(p);
    return out;
  }
  [[nodiscard]] static std::string plain(const Pieces& pieces) {
    std::string out;
    for (const Piece& p : pieces) out += p.plain;
    return out;
  }
  [[nodiscard]] std::string tex(const GiNaC::ex& e) const { return print(e, system_.table(), Style::latex); }
  [[nodiscard]] std::string symbol(std::size_t i) const { return tex(system_.coordinates()[i].symbols.q); }
  [[nodiscard]] std::vector<std::vector<std::string>> numbers(const Eigen::MatrixXd& A) const {
    std::vector<std::vector<std::string>> rows(static_cast<std::size_t>(A.rows()));
    for (Eigen::Index i = 0; i < A.rows(); ++i)
      for (Eigen::Index j = 0; j < A.cols(); ++j)
        rows[static_cast<std::size_t>(i)].push_back(format_number(A(i, j), Style::latex, o_.digits));
    return rows;
  }
  // The column of coordinate changes, \delta\theta_2 ...: `coordinates`' symbols.
  [[nodiscard]] std::string deltas(const Pieces& coordinates) const {
    std::vector<std::string> entries;
    for (const Piece& c : coordinates) {
      const std::string symbol = c.tex.substr(1, c.tex.size() - 2);
      // A space before a letter: \delta s_S, not the unknown command \deltas.
      const bool letter = !symbol.empty() && std::isalpha(static_cast<unsigned char>(symbol.front())) != 0;
      entries.push_back(concat({"\\delta", letter ? " " : "", symbol}));
    }
    return inline_column(entries, pad());
  }

  const sym::System& system_;
  const ReportOptions& o_;
  bool run_in_ = false;  // LaTeX: a paragraph now runs on after the section's heading
};

std::string modes_document(ModesOut& out, const sym::System& system, const Linearization& linear,
                           const ModalAnalysis& modes, const ReportOptions& o, const std::vector<ModeCheck>* checks) {
  modes_sections(out, system, linear, modes, checks, o.text_style);
  return out.take();
}

}  // namespace

ModesAnalysis analyse_modes(const sym::System& system, bool at_initial, bool verify) {
  LinearizeOptions options;
  options.at_initial = at_initial;
  ModesAnalysis out{linearize(system, options), {}, {}};
  out.modes = modal_analysis(out.linear);
  if (verify) out.checks = verify_modes(system, out.linear, out.modes);
  return out;
}

std::string modes_text(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                       const ReportOptions& o, const std::vector<ModeCheck>* checks) {
  TextOut out(system, o);
  return modes_document(out, system, linear, modes, o, checks);
}

std::string modes_latex(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                        const ReportOptions& o, const std::vector<ModeCheck>* checks) {
  MathOut out(system, o, MathDocument::Format::latex);
  return modes_document(out, system, linear, modes, o, checks);
}

std::string modes_markdown(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                           const ReportOptions& o, const std::vector<ModeCheck>* checks) {
  MathOut out(system, o, MathDocument::Format::markdown);
  return modes_document(out, system, linear, modes, o, checks);
}

std::string modes_json(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                       const std::vector<ModeCheck>* checks) {
  using json = nlohmann::ordered_json;
  const auto matrix = [](const Eigen::MatrixXd& A) {
    json rows = json::array();
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
      json row = json::array();
      for (Eigen::Index j = 0; j < A.cols(); ++j) row.push_back(A(i, j));
      rows.push_back(std::move(row));
    }
    return rows;
  };
  json out;
  out["mechanism"] = system.mechanism().name;
  out["at_initial"] = linear.at_initial;
  json equilibrium = json::object();
  for (std::size_t i = 0; i < linear.tree_coordinates.size(); ++i)
    equilibrium[linear.tree_coordinates[i]] = linear.equilibrium[static_cast<Eigen::Index>(i)];
  out["equilibrium"] = std::move(equilibrium);
  out["residual"] = linear.residual;
  out["coordinates"] = linear.coordinates;
  out["M"] = matrix(linear.M);
  out["C"] = matrix(linear.C);
  out["K"] = matrix(linear.K);
  json list = json::array();
  for (const Mode& mode : modes.modes) {
    json one;
    one["kind"] = kind_word(mode.kind);
    if (mode.kind == Mode::Kind::unstable) {
      one["growth_rate"] = mode.growth_rate;
    } else {
      one["omega"] = mode.omega;
      one["frequency_hz"] = mode.omega / (2 * std::numbers::pi);
      one["damping_ratio"] = mode.damping_ratio;
    }
    json shape = json::object();
    for (std::size_t i = 0; i < linear.coordinates.size(); ++i)
      shape[linear.coordinates[i]] = mode.shape[static_cast<Eigen::Index>(i)];
    one["shape"] = std::move(shape);
    json tree = json::object();
    for (std::size_t i = 0; i < linear.tree_coordinates.size(); ++i)
      tree[linear.tree_coordinates[i]] = mode.tree_shape[static_cast<Eigen::Index>(i)];
    one["tree_shape"] = std::move(tree);
    list.push_back(std::move(one));
  }
  out["modes"] = std::move(list);
  out["stable"] = modes.stable;
  if (checks != nullptr) {
    json verify = json::array();
    for (const ModeCheck& check : *checks)
      verify.push_back({{"mode", check.mode + 1},
                        {"predicted", check.predicted},
                        {"measured", check.measured},
                        {"relative_error", check.relative_error()},
                        {"crossings", check.crossings}});
    out["verify"] = std::move(verify);
  }
  return json_layout(out);
}

}  // namespace linkage
