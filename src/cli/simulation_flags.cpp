#include "cli/simulation_flags.hpp"

#include <cstdio>

#include "cli/input_options.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"

namespace linkage::cli {

void add_simulation_flags(CLI::App* sub, SimulationFlags& o) {
  const SimulationOptions d;
  const auto fmt = [](double v) { return format_roundtrip(v); };
  const std::string group = "Simulation";
  sub->add_option("--case", o.which_case,
                  "Formulation: 1 (maximal coordinates, can drift off the pin), 2 or 3 (generalized coordinates) "
                  "(default " +
                      o.which_case + ")")
      ->type_name("1|2|3")
      ->group(group);
  std::string names;
  for (const IntegratorInfo& i : integrators())
    names += "\n  " + std::string(i.name) + ": " + std::string(i.description);
  o.integrator_option =
      sub->add_option("--integrator", o.integrator, "Integrator (default " + o.integrator + "):" + names)
          ->type_name("NAME")
          ->group(group);
  o.dt_option =
      sub->add_option("--dt", o.numbers["dt"],
                      "Step of fixed-step integrators, first step of adaptive ones, s (default " + fmt(d.dt) + ")")
          ->type_name("S")
          ->group(group);
  o.rtol_option =
      sub->add_option("--rtol", o.numbers["rtol"],
                      "Relative tolerance of adaptive integrators, in [1e-14, 1] (default " + fmt(d.rtol) + ")")
          ->type_name("NUM")
          ->group(group);
  o.atol_option = sub->add_option("--atol", o.numbers["atol"],
                                  "Absolute tolerance of adaptive integrators, in [1e-20, 1], in the state's units "
                                  "(m, rad, m/s, rad/s) (default " +
                                      fmt(d.atol) + ")")
                      ->type_name("NUM")
                      ->group(group);
  o.stabilize_option =
      sub->add_option("--stabilize", o.stabilize,
                      "Constraint stabilization of Case 1: none, baumgarte (C'' + 2 alpha C' + beta^2 C = 0) or "
                      "projection (back onto the joints' constraints after every step) (default " +
                          o.stabilize + ")")
          ->type_name("KIND")
          ->group(group);
  sub->add_option("--evaluator", o.evaluator,
                  "What computes the equations: compiled (native code: built in for the shipped mechanisms, "
                  "else compiled with the system's c++ and cached in $XDG_CACHE_HOME/linkage/native), "
                  "interpreted (never compiles), or auto: built in, else a cached entry, else compiled when c++ "
                  "is on PATH and the run is expected to take 40 million right-hand sides or more (duration / dt "
                  "x the method's stages: a compile of 0.3 s (four-bar) to a few s (long chains) against a saving of "
                  "at most 60 ns each), else "
                  "interpreted (default " +
                      o.evaluator + ")")
      ->type_name("KIND")
      ->group(group);
  o.alpha_option = sub->add_option("--baumgarte-alpha", o.numbers["baumgarte_alpha"],
                                   "Baumgarte damping gain alpha, 1/s (default " + fmt(d.baumgarte_alpha) + ")")
                       ->type_name("NUM")
                       ->group(group);
  o.beta_option = sub->add_option("--baumgarte-beta", o.numbers["baumgarte_beta"],
                                  "Baumgarte stiffness gain beta, 1/s (default " + fmt(d.baumgarte_beta) +
                                      "; alpha = beta is critically damped)")
                      ->type_name("NUM")
                      ->group(group);
}

SimulationOptions resolve_simulation_flags(const SimulationFlags& o, double duration) {
  SimulationOptions s;
  if (o.which_case == "1" || o.which_case == "2" || o.which_case == "3")
    s.case_id = o.which_case[0] - '0';
  else
    throw Error::input("--case: '" + o.which_case + "' is not a case; valid: 1, 2, 3");
  s.integrator = parse_integrator(o.integrator, "--integrator");
  s.stabilization = parse_stabilization(o.stabilize, "--stabilize");
  s.evaluator = parse_evaluator(o.evaluator, "--evaluator");
  s.duration = duration;
  for (const NumberOption& n : kNumberOptions)
    if (const auto it = o.numbers.find(n.name); it != o.numbers.end() && !it->second.empty())
      s.*n.field = parse_number(it->second, flag_name(n.name), std::string(n.unit));
  s.validate();
  return s;
}

void note_ignored_simulation_flags(const SimulationFlags& o, const SimulationOptions& s, int kept_constraints,
                                   bool kinematic) {
  const auto note = [](const std::string& text) { std::fprintf(stderr, "linkage: note: %s\n", text.c_str()); };
  if (kinematic) {
    std::string given;
    for (const auto& [option, flag] :
         {std::pair{o.integrator_option, "--integrator"}, std::pair{o.dt_option, "--dt"},
          std::pair{o.rtol_option, "--rtol"}, std::pair{o.atol_option, "--atol"},
          std::pair{o.stabilize_option, "--stabilize"}, std::pair{o.alpha_option, "--baumgarte-alpha"},
          std::pair{o.beta_option, "--baumgarte-beta"}})
      if (option != nullptr && option->count() > 0) given += (given.empty() ? "" : ", ") + std::string(flag);
    if (!given.empty())
      note("kinematic analysis (0 degrees of freedom): the drivers fix the motion and nothing is integrated, so " +
           given + " not used");
    return;
  }
  if (kept_constraints == 0 && s.stabilization != Stabilization::none)
    note("Case " + std::to_string(s.case_id) +
         " keeps no constraint here (its coordinates meet every joint by construction); --stabilize " +
         std::string(name(s.stabilization)) + " has nothing to do");
  if (kept_constraints < 0 && s.case_id != 1 && s.stabilization != Stabilization::none)
    note("Case " + std::to_string(s.case_id) +
         " integrates (x1, y1, theta1, theta2), so the pin constraint holds by construction; --stabilize " +
         std::string(name(s.stabilization)) + " has nothing to do");
  if (s.stabilization != Stabilization::baumgarte && (o.alpha_option->count() > 0 || o.beta_option->count() > 0))
    note("--baumgarte-alpha/--baumgarte-beta apply only with --stabilize baumgarte");
  if (!info(s.integrator).adaptive && (o.rtol_option->count() > 0 || o.atol_option->count() > 0))
    note("--rtol/--atol apply only to adaptive integrators (dopri5, dop853, vern7); " +
         std::string(info(s.integrator).name) + " takes fixed steps of --dt");
}

}  // namespace linkage::cli
