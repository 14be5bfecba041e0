#include "report/modes_report.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/number_format.hpp"
#include "report/expression_print.hpp"
#include "report/json_layout.hpp"
#include "report/text_layout.hpp"

namespace linkage {
namespace {

std::string number(double v, const ReportOptions& o) { return format_significant(v, o.digits); }

void add_lines(std::string& out, const std::vector<std::string>& lines) {
  for (const std::string& line : lines) out += line + "\n";
}

void paragraph(std::string& out, const std::string& text, const ReportOptions& o) {
  add_lines(out, wrap_words(text, "", o.width));
}

// A matrix in numbers, its rows and columns labelled by the coordinates.
void matrix_table(std::string& out, const std::string& name, const Eigen::MatrixXd& A,
                  const std::vector<std::string>& labels, const ReportOptions& o) {
  out += "  " + name + ":\n";
  Table table;
  table.headers = labels;
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    table.row_labels.push_back(labels[static_cast<std::size_t>(i)]);
    std::vector<std::string> row;
    for (Eigen::Index j = 0; j < A.cols(); ++j) row.push_back(number(A(i, j), o));
    table.cells.push_back(std::move(row));
  }
  add_lines(out, layout_table(table, "  ", o.width));
}

// The nonzero entries of a symbolic matrix, each "NAME[q_i, q_j] = expression" wrapped.
void symbolic_entries(std::string& out, const std::string& name, const std::vector<std::vector<GiNaC::ex>>& A,
                      const std::vector<std::string>& symbols, bool symmetric, const sym::System& system,
                      const ReportOptions& o) {
  bool any = false;
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = symmetric ? i : 0; j < A[i].size(); ++j) {
      if (A[i][j].is_zero()) continue;
      any = true;
      const std::string first = "  " + name + "[" + symbols[i] + ", " + symbols[j] + "] = ";
      add_lines(out, wrap(first, print(A[i][j], system.table(), o.text_style), "      ", o.width));
    }
  if (!any) out += "  " + name + " = 0\n";
}

}  // namespace

std::string modes_text(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes,
                       const ReportOptions& o, const std::vector<ModeCheck>* checks) {
  const Mechanism& m = system.mechanism();
  std::vector<std::string> symbols;  // θ₁, s: as the derivation spells the tree coordinates
  for (const sym::GeneralizedCoordinate& g : system.coordinates())
    symbols.push_back(print(g.symbols.q, system.table(), o.text_style));
  std::string out = "Small vibrations of " + m.name + ": " + m.title + "\n\n";

  out += "1. The equilibrium\n";
  if (linear.at_initial) {
    const bool balanced = linear.residual <= 1e-10 * linear.force_scale || linear.residual == 0;
    paragraph(out,
              "At the file's [initial] coordinates, rates zero (--at-initial). " +
                  (balanced ? std::string("It is an equilibrium: the largest generalized force there is ") +
                                  format_significant(linear.residual, 3) + "."
                            : "It is not an equilibrium: the generalized forces there reach " +
                                  format_significant(linear.residual, 3) +
                                  " (N or N m), so the motion drifts away from it while it vibrates."),
              o);
  } else {
    paragraph(out,
              "Found by Newton's method from the file's [initial] coordinates with the rates zero and the loads "
              "at t = 0: " +
                  std::to_string(linear.newton_steps) + " steps; the largest generalized force left is " +
                  format_significant(linear.residual, 3) + " (N or N m).",
              o);
  }
  {
    Table table;
    table.headers = {"coordinate", "value", "unit"};
    for (std::size_t i = 0; i < symbols.size(); ++i) {
      table.row_labels.push_back(symbols[i]);
      table.cells.push_back({linear.tree_coordinates[i], number(linear.equilibrium[static_cast<Eigen::Index>(i)], o),
                             linear.tree_units[i]});
    }
    add_lines(out, layout_table(table, "  ", o.width));
  }

  out += "\n2. The expansion\n";
  paragraph(out,
            "Lagrange's rows F(q, q', q'', lambda) = M(q) q'' - Q(q, q', t, lambda) = 0 (the loop forces and "
            "drivers' torques lambda among the loads Q) to first order about the equilibrium, rates and "
            "accelerations zero: M0 dq'' + C0 dq' + K0 dq + (dF/dlambda) dlambda = 0, with C0 = dF/dq' and "
            "K0 = dF/dq there" +
                std::string(linear.multipliers.size() > 0 ? " (lambda held at its equilibrium value: the "
                                                            "constraints' curvature)."
                                                          : "."),
            o);
  symbolic_entries(out, "M", linear.M_symbolic, symbols, true, system, o);
  symbolic_entries(out, "C", linear.C_symbolic, symbols, false, system, o);
  symbolic_entries(out, "K", linear.K_symbolic, symbols, false, system, o);
  if (linear.multipliers.size() > 0) {
    std::string z;
    for (const std::string& c : linear.coordinates) z += (z.empty() ? "" : ", ") + c;
    paragraph(out,
              "The " + std::string(system.drivers().empty() ? "loop" : "loop and driver") +
                  " rows J0 dq = 0 leave the independent coordinates z = (" + z +
                  "): dq = R dz, and M = R^T M0 R, C = R^T C0 R, K = R^T K0 R (R^T (dF/dlambda) = 0 removes "
                  "dlambda).",
              o);
    Table table;
    table.headers = linear.coordinates;
    for (std::size_t i = 0; i < linear.tree_coordinates.size(); ++i) {
      table.row_labels.push_back(linear.tree_coordinates[i]);
      std::vector<std::string> row;
      for (Eigen::Index k = 0; k < linear.R.cols(); ++k)
        row.push_back(number(linear.R(static_cast<Eigen::Index>(i), k), o));
      table.cells.push_back(std::move(row));
    }
    add_lines(out, layout_table(table, "  ", o.width));
  }

  out += "\n3. The linearized equations M z'' + C z' + K z = 0\n";
  matrix_table(out, "M", linear.M, linear.coordinates, o);
  if (modes.damped) matrix_table(out, "C", linear.C, linear.coordinates, o);
  matrix_table(out, "K", linear.K, linear.coordinates, o);

  out += "\n4. The modes: K v = w^2 M v\n";
  const bool neutral = std::any_of(modes.modes.begin(), modes.modes.end(),
                                   [](const Mode& mode) { return mode.kind == Mode::Kind::neutral; });
  paragraph(out,
            modes.stable
                ? "The equilibrium is stable: every mode oscillates" + std::string(modes.damped ? " and decays" : "") +
                      (neutral ? ", but for a neutral mode, which moves freely (no stiffness)." : ".")
                : "The equilibrium is unstable: a mode grows as exp(sigma t), sigma its growth rate.",
            o);
  Table table;
  table.headers = {"kind", "w (rad/s)", "f (Hz)", "period (s)"};
  if (modes.damped) table.headers.push_back("zeta");
  if (!modes.stable) table.headers.push_back("sigma (1/s)");
  table.separator_before = table.headers.size();
  for (const std::string& c : linear.coordinates) table.headers.push_back(c);
  for (std::size_t k = 0; k < modes.modes.size(); ++k) {
    const Mode& mode = modes.modes[k];
    const bool oscillates = mode.kind == Mode::Kind::oscillation;
    table.row_labels.push_back("mode " + std::to_string(k + 1));
    std::vector<std::string> row{kind_word(mode.kind), oscillates ? number(mode.omega, o) : "-",
                                 oscillates ? number(mode.omega / (2 * std::numbers::pi), o) : "-",
                                 oscillates ? number(2 * std::numbers::pi / mode.omega, o) : "-"};
    if (modes.damped) row.push_back(oscillates ? number(mode.damping_ratio, o) : "-");
    if (!modes.stable) row.push_back(mode.kind == Mode::Kind::unstable ? number(mode.growth_rate, o) : "-");
    for (Eigen::Index i = 0; i < mode.shape.size(); ++i) row.push_back(number(mode.shape[i], o));
    table.cells.push_back(std::move(row));
  }
  add_lines(out, layout_table(table, "  ", o.width));
  paragraph(out, "Shapes in the independent coordinates, each scaled so its largest component is 1.", o);
  if (checks == nullptr) return out;
  out += "\n5. The check: the full equations\n";
  if (checks->empty()) {
    paragraph(out, "No mode oscillates, so there is no frequency to check.", o);
    return out;
  }
  paragraph(out,
            "Each oscillating mode's shape, its largest coordinate moved by " +
                format_significant(checks->front().amplitude, 3) +
                " (rad or m), starts the nonlinear equations at rest (DOP853, tolerances 1e-13, loops closed); the "
                "upward zero crossings of the mode's coordinate over ten periods give the frequency the motion has" +
                std::string(modes.damped ? " (with damping, w sqrt(1 - zeta^2))." : "."),
            o);
  Table checked;
  checked.headers = {"predicted (rad/s)", "measured (rad/s)", "relative difference", "crossings"};
  bool agree = true;
  for (const ModeCheck& check : *checks) {
    checked.row_labels.push_back("mode " + std::to_string(check.mode + 1));
    checked.cells.push_back({number(check.predicted, o), number(check.measured, o),
                             format_significant(check.relative_error(), 2), std::to_string(check.crossings)});
    agree = agree && check.relative_error() <= kModeCheckTolerance;
  }
  add_lines(out, layout_table(checked, "  ", o.width));
  paragraph(out,
            agree ? "Every mode agrees with the motion to " + format_significant(kModeCheckTolerance, 1) + "."
                  : "A mode DISAGREES with the motion by more than " + format_significant(kModeCheckTolerance, 1) +
                        ": the linearization does not describe this equilibrium.",
            o);
  return out;
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
