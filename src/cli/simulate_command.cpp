// `linkage simulate`: a mechanism's motion over time as a CSV or JSON table, with a summary
// of the run's cost and accuracy on stderr. The homework's flags are settings of
// two-blocks.toml, its table's names that file's [aliases].
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli/angle_option.hpp"
#include "cli/commands.hpp"
#include "cli/input_options.hpp"
#include "cli/mechanism_options.hpp"
#include "cli/simulation_flags.hpp"
#include "columns/mechanism_columns.hpp"
#include "columns/trajectory_rows.hpp"
#include "core/angle_unit.hpp"
#include "core/atomic_file.hpp"
#include "core/deriving.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "core/progress.hpp"
#include "integrate/mechanism_simulation.hpp"
#include "pipeline/simulate_rows.hpp"
#include "report/mechanism_solution.hpp"
#include "symbolic/joints.hpp"

namespace linkage::cli {
namespace {

constexpr double kMaxRows = 1e7;
struct SimulateOptions {
  InputOptions inputs;
  SimulationFlags simulation;
  std::string duration, every = "0.01";
  std::string out;
  std::string format;
  std::string columns = "all";
  std::string angles = "rad";
  CLI::Option* columns_option = nullptr;
  bool quiet = false;
  MechanismOptions mechanism;
};

enum class Format { csv, json };

Format choose_format(const SimulateOptions& o) {
  if (o.format == "csv") return Format::csv;
  if (o.format == "json") return Format::json;
  if (!o.format.empty()) throw Error::input("--format: '" + o.format + "' is not a format; valid: csv, json");
  // From the extension, whatever its case; an unknown one is a mistake, not CSV.
  std::string ext = std::filesystem::path(o.out).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".json") return Format::json;
  if (ext == ".csv" || o.out.empty() || o.out == "-") return Format::csv;
  throw Error::input("--out: '" + o.out + "' has " +
                     (ext.empty() ? std::string("no extension") : "extension '" + ext + "'") +
                     "; valid: .csv or .json, or give --format csv|json");
}

/// The output times k * every strictly before the end, then the duration itself.
/// The table's row times; more than kMaxRows rows is an input error.
TrajectoryRows checked_rows(double duration, double every) {
  const double ratio = duration / every;
  if (ratio > kMaxRows)
    throw Error::input("--every: " + format_roundtrip(every) + " s gives " + format_significant(ratio, 3) +
                       " rows for --duration " + format_roundtrip(duration) + " s; the limit is 1e7 rows");
  return {duration, every};
}

/// Writes rows as they are computed: CSV lines go out whole, so a run that fails
/// part way leaves only complete lines on stdout (and no file at all with --out).
class TableWriter {
 public:
  TableWriter(Format format, std::FILE* stdout_file, AtomicFile* file)
      : format_(format), stdout_(stdout_file), file_(file) {}

  void begin(const std::vector<std::string>& names, const std::string& json_header) {
    if (format_ == Format::csv) {
      emit(joined_names(names) + "\n");
    } else {
      json_ = json_header + "  \"rows\": [";
    }
  }

  void row(const std::vector<double>& values) {
    line_.clear();
    if (format_ == Format::json) line_ += rows_ ? ",\n    [" : "\n    [";
    line_ += joined_values(values, format_ == Format::csv ? "," : ", ");
    line_ += format_ == Format::csv ? "\n" : "]";
    ++rows_;
    if (format_ == Format::csv)
      emit(line_);
    else
      json_ += line_;
  }

  /// JSON is only written once complete, so a failed run prints none of it.
  void end(const std::string& json_summary) {
    if (format_ == Format::json) emit(json_ + "\n  ],\n" + json_summary);
  }

 private:
  void emit(const std::string& text) {
    if (file_ != nullptr) {
      file_->stream() << text;
      if (!file_->stream()) throw Error::failure(write_failure(file_->target(), errno));
    } else if (std::fwrite(text.data(), 1, text.size(), stdout_) != text.size()) {
      throw Error::failure("cannot write standard output: " + std::string(std::strerror(errno)));
    }
  }

  Format format_;
  std::FILE* stdout_;
  AtomicFile* file_;
  std::string json_, line_;
  long rows_ = 0;
};

/// "key": value for the lines around the rows: one object per line, keys in order.
std::string json_line(const std::string& key, const nlohmann::ordered_json& value) {
  return "  " + nlohmann::json(key).dump() + ": " + value.dump();
}

nlohmann::ordered_json options_json(const SimulationOptions& s, double every) {
  return {{"case", s.case_id},
          {"integrator", info(s.integrator).name},
          {"dt", s.dt},
          {"rtol", s.rtol},
          {"atol", s.atol},
          {"duration", s.duration},
          {"every", every},
          {"stabilize", name(s.stabilization)},
          {"baumgarte_alpha", s.baumgarte_alpha},
          {"baumgarte_beta", s.baumgarte_beta}};
}

/// "dop853 (rtol 1e-10, atol 1e-10)" or "rk4 (dt 0.001 s)", for the summaries.
std::string method_text(const SimulationOptions& s) {
  const IntegratorInfo& integrator = info(s.integrator);
  return integrator.adaptive ? std::string(integrator.name) + " (rtol " + format_roundtrip(s.rtol) + ", atol " +
                                   format_roundtrip(s.atol) + ")"
                             : std::string(integrator.name) + " (dt " + format_roundtrip(s.dt) + " s)";
}

std::string mechanism_json_header(const sym::System& system, const GiNaC::exmap& initial, const SimulationOptions& s,
                                  double every, const std::vector<MechanismColumn>& columns,
                                  const WrittenColumns& written) {
  const Mechanism& m = system.mechanism();
  nlohmann::ordered_json params = nlohmann::ordered_json::object(), state = nlohmann::ordered_json::object();
  for (const Parameter& p : m.parameters) params[m.named(p.name)] = p.value;
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    state[m.named(g.coordinate.key)] = sym::to_double(initial.at(g.symbols.q));
    state[m.named(g.coordinate.key + "_dot")] = sym::to_double(initial.at(g.symbols.q_dot));
  }
  nlohmann::ordered_json names = nlohmann::ordered_json::array(), units = nlohmann::ordered_json::object();
  for (std::size_t j = 0; j < columns.size(); ++j) {
    names.push_back(columns[j].name);
    units[columns[j].name] = written.units[j];
  }
  return "{\n" + json_line("mechanism", system.mechanism().name) + ",\n" + json_line("parameters", params) + ",\n" +
         json_line("initial_state", state) + ",\n" + json_line("options", options_json(s, every)) + ",\n" +
         json_line("columns", names) + ",\n" + json_line("units", units) + ",\n";
}

std::string mechanism_json_summary(const MechanismStats& st, double wall) {
  const nlohmann::ordered_json summary = {{"steps_accepted", st.steps_accepted},
                                          {"steps_rejected", st.steps_rejected},
                                          {"rhs_evaluations", st.rhs_evaluations},
                                          {"max_energy_error", st.max_energy_error},
                                          {"energy_scale", st.energy_scale},
                                          {"max_constraint_error", st.max_constraint_error},
                                          {"wall_seconds", wall}};
  return json_line("summary", summary) + "\n}\n";
}

/// The file's [table] (every column when it has none), comma-separated, by the names the
/// run prints.
std::string table_columns(const Mechanism& m) {
  if (m.table.empty()) return "all";
  std::string list;
  for (const TableColumn& c : m.table) list += (list.empty() ? "" : ",") + m.named(c.name);
  return list;
}

void run_simulate_mechanism(const SimulateOptions& o, SimulationOptions s, double every, Format format) {
  const auto start = std::chrono::steady_clock::now();
  const TrajectoryRows samples = checked_rows(s.duration, every);
  // The initial state worked out as solve does, so a value that breaks it is named the same way.
  Deriving deriving(o.quiet);
  // The default mechanism speaks its interface (the homework's): its [table] by default,
  // each quantity named by its [aliases] in the table and in messages.
  const bool default_interface = !o.mechanism.chosen();
  Mechanism mechanism = chosen_mechanism(o.mechanism, o.inputs);
  mechanism.speaks_aliases = default_interface;
  const MechanismSolution checked = work_out_mechanism(mechanism, {static_cast<CaseId>(s.case_id)});
  const sym::System& system = *checked.system;
  std::vector<MechanismColumn> all = mechanism_columns(system);
  for (MechanismColumn& c : all) c.name = system.mechanism().named(c.name);
  const bool asked = o.columns_option != nullptr && o.columns_option->count() > 0;
  const std::vector<MechanismColumn> columns =
      default_interface
          ? named_columns(all, o.columns == "all" ? table_columns(system.mechanism()) : o.columns, "--columns", &system)
          : select_mechanism_columns(all, asked ? o.columns : "default", "--columns", &system);
  s.kinematics = needs_kinematics(columns);
  MechanismSimulation simulation(system, checked.state, s, checked.cases.front().system);
  deriving.done();
  if (!o.quiet) {
    note_ignored_simulation_flags(o.simulation, s, simulation.dynamics().constraint_rows(),
                                  simulation.stats().kinematic);
    if (!checked.closure_note.empty()) std::fprintf(stderr, "linkage: note: %s\n", checked.closure_note.c_str());
  }
  std::optional<AtomicFile> file;
  if (!o.out.empty()) file.emplace(o.out, "out");
  TableWriter writer(format, stdout, file ? &*file : nullptr);
  const AngleUnit angles = parse_angle_unit(o.angles, "--angles");
  const WrittenColumns written = written_columns(columns, angles);
  writer.begin(written.names,
               format == Format::json ? mechanism_json_header(system, checked.state, s, every, columns, written) : "");
  Progress progress("simulate", s.duration, "s simulated", o.quiet);
  simulation.on_progress([&progress](double t) { progress.update(t); });
  (void)mechanism_trajectory(simulation, s.case_id, samples, columns, angles,
                             [&](double t, const std::vector<double>& values) {
                               writer.row(values);
                               progress.update(t);
                             });
  progress.finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writer.end(mechanism_json_summary(simulation.stats(), wall));
  if (file) file->commit();
  std::fflush(stdout);
  const MechanismStats& st = simulation.stats();
  // Kinematic analysis: no integrator, no stabilization; its steps are the continuation's.
  const std::string method = st.kinematic ? "kinematic analysis (0 degrees of freedom)"
                                          : method_text(s) + ", stabilize " + std::string(name(s.stabilization));
  // The largest constraint error in its joint's unit, naming the joint.
  std::string constraint = format_significant(st.max_constraint_error, 3);
  if (const Joint* joint = system.mechanism().find_joint(st.drifted_joint))
    constraint += std::string(" ") + sym::joint_stages(joint->type).constraint_unit + " (joint " + joint->name + ")";
  std::fprintf(stderr,
               "linkage simulate: %s, Case %d, %s, 0 to %s s, %ld rows\n"
               "  %s: %lld accepted, %lld rejected; %s: %lld\n"
               "  largest energy balance error: %s of the energy scale %s J; largest constraint error: %s\n"
               "  wall time: %s s (%s %s s); evaluator: %s\n",
               system.mechanism().name.c_str(), s.case_id, method.c_str(), format_roundtrip(s.duration).c_str(),
               samples.count, st.kinematic ? "continuation steps" : "steps", static_cast<long long>(st.steps_accepted),
               static_cast<long long>(st.steps_rejected),
               st.kinematic ? "position solves" : "right-hand side evaluations",
               static_cast<long long>(st.rhs_evaluations), format_significant(st.max_energy_error, 3).c_str(),
               format_significant(st.energy_scale, 4).c_str(), constraint.c_str(), format_significant(wall, 3).c_str(),
               st.kinematic ? "kinematic analysis" : "integration", format_significant(st.wall_seconds, 3).c_str(),
               st.evaluator.c_str());
  const std::string warning = mechanism_result_warning(s, st);
  if (!warning.empty()) std::fprintf(stderr, "linkage: warning: %s\n", warning.c_str());
}

void run_simulate(const SimulateOptions& o) {
  const SimulationOptions defaults;
  const double duration = o.duration.empty() ? defaults.duration : parse_number(o.duration, "--duration", "s");
  const SimulationOptions s = resolve_simulation_flags(o.simulation, duration);
  (void)parse_angle_unit(o.angles, "--angles");  // checked before any work
  const double every = parse_number(o.every, "--every", "s");
  if (!(every > 0 && every <= s.duration))
    throw Error::input("--every: " + format_roundtrip(every) + " s is out of range; valid: 0 < every <= duration (" +
                       format_roundtrip(s.duration) + " s)");
  run_simulate_mechanism(o, s, every, choose_format(o));
}

}  // namespace

void register_simulate(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  const SimulationOptions d;
  auto fmt = [](double v) { return format_roundtrip(v); };
  CLI::App* sub = app.add_subcommand("simulate",
                                     "Integrate a mechanism's motion over time (default: the homework's two blocks) "
                                     "and write it as a CSV or JSON table");
  add_simulation_flags(sub, o->simulation);
  sub->add_option("--duration", o->duration, "Simulated time, s, at most 1e6 (default " + fmt(d.duration) + ")")
      ->type_name("S");
  sub->add_option("--every", o->every,
                  "Output interval, s (default " + o->every +
                      "); adaptive integrators sample by dense output and never shorten a step to hit a sample")
      ->type_name("S");
  sub->add_option("--out", o->out, "Output file, written atomically (default: stdout)")->type_name("FILE");
  sub->add_option("--format", o->format, "Output format: csv or json (default: from the --out extension, else csv)")
      ->type_name("csv|json");
  o->columns_option =
      sub->add_option("--columns", o->columns,
                      "Comma-separated columns to compute and write. A mechanism's: t; every body's x, y, theta "
                      "and their _dot and _ddot (1.x, 2.theta_dot, 2.theta_ddot); every slider's s and s_ddot; "
                      "every named point's 3.P.x, .y, .vx, .vy, .ax, .ay (world frame; m, m/s, m/s^2); every "
                      "joint's force_x, force_y (on its first body; moment for a slider), constraint_error (m) and "
                      "constraint_velocity_error (m/s); every [[driver]]'s NAME.torque (N m) or NAME.force (N), on "
                      "its joint's second body; energy (J, kinetic + potential), work (of dampers, loads and "
                      "drivers) and energy_error; "
                      "momentum_x, momentum_y and angular_momentum when nothing holds it to the ground. With "
                      "--mechanism: default (t, every body's x, y, theta, every slider's s), all, or names. The "
                      "homework (no --mechanism) names them as its table always has, e.g. x1, theta2_dot, "
                      "x1_ddot, F_x (the pin force on block 1, N), constraint_position_error (m), "
                      "constraint_velocity_error (m/s), x2, y2; all of them by default. NAME=EXPRESSION defines a "
                      "column over the others, the parameters and the functions of mechanism files: "
                      "gamma=4.theta-3.theta (an angle: in --angles' unit), P=M.torque*2.theta_dot (W)")
          ->type_name("LIST");
  add_angle_option(sub, o->angles, "angle columns (theta, rates, accelerations) in the table");
  sub->add_flag("--quiet", o->quiet, "No progress or notes on stderr (the summary and warnings stay)");
  add_mechanism_options(sub, o->mechanism);
  add_input_options(sub, o->inputs);
  add_runner(sub, [o] { run_simulate(*o); });
}

}  // namespace linkage::cli
