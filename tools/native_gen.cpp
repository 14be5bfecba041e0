// linkage_native_gen OUTPUT.cpp: the build step that compiles the shipped mechanisms into
// the program (issue 24). Every Program that `simulate` and `render` run for every shipped
// mechanism and case, the kinematics included, as one C++ file with a table by
// fingerprint (evaluate/native_builtin.hpp). A build tool, not a module of the program:
// here rather than in src/, which holds only the program's modules.
#include <cstdio>
#include <exception>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "evaluate/mechanism_dynamics.hpp"
#include "evaluate/native_builtin.hpp"
#include "formulations/case_system.hpp"
#include "linkage/embedded_mechanisms.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/system.hpp"

int main(int argc, char** argv) {
  using namespace linkage;
  if (argc != 2) {
    std::fprintf(stderr, "usage: linkage_native_gen OUTPUT.cpp\n");
    return 2;
  }
  try {
    std::vector<std::unique_ptr<sym::System>> systems;
    std::vector<std::unique_ptr<eval::MechanismDynamics>> dynamics;  // the Programs stay put
    std::vector<const eval::Program*> programs;
    for (const EmbeddedMechanism& shipped : kEmbeddedMechanisms) {
      systems.push_back(std::make_unique<sym::System>(load_mechanism(std::string(shipped.name))));
      for (const CaseId id : kAllCases) {
        dynamics.push_back(std::make_unique<eval::MechanismDynamics>(*systems.back(), id));
        for (const eval::Program* p : dynamics.back()->programs(true)) programs.push_back(p);
      }
    }
    const std::string text = eval::builtin_native_source(programs);
    // Rewritten only when changed, so an unchanged table is not compiled again.
    std::ifstream old(argv[1], std::ios::binary);
    std::ostringstream before;
    before << old.rdbuf();
    if (old && before.str() == text) return 0;
    std::ofstream out(argv[1], std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) {
      std::fprintf(stderr, "linkage_native_gen: cannot write %s\n", argv[1]);
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "linkage_native_gen: %s\n", e.what());
    return 1;
  }
  return 0;
}
