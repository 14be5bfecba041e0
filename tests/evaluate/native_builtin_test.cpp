// The built-in native code (issue 24): the table the build step generates
// (tools/native_gen.cpp) holds every program the shipped mechanisms run. This fails when
// the generation step is stale, so it keeps the build honest.
#include "evaluate/native_builtin.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cli/native_shipped.hpp"
#include "evaluate/mechanism_dynamics.hpp"
#include "formulations/case_system.hpp"
#include "linkage/embedded_mechanisms.hpp"
#include "model/mechanism_toml.hpp"
#include "symbolic/system.hpp"

namespace linkage::eval {
namespace {

TEST(NativeBuiltin, EveryProgramOfEveryShippedMechanismIsBuiltIn) {
  use_builtin_native({kShippedNative, kShippedNativeCount});
  std::size_t programs = 0;
  for (const EmbeddedMechanism& shipped : kEmbeddedMechanisms) {
    const sym::System system(load_mechanism(std::string(shipped.name)));
    for (const CaseId id : kAllCases) {
      MechanismDynamics dynamics(system, id);
      for (const Program* p : dynamics.programs(true)) {
        ++programs;
        EXPECT_NE(builtin_native(p->fingerprint()), nullptr)
            << shipped.name << " Case " << case_number(id) << ": a program missing from the built-in table";
      }
      MechanismDynamics attached(system, id);
      EXPECT_TRUE(attached.attach_builtin(true)) << shipped.name << " Case " << case_number(id);
      for (const Program* p : attached.programs(true)) EXPECT_TRUE(p->native());
    }
  }
  EXPECT_GT(programs, 3 * kEmbeddedMechanisms.size());
  use_builtin_native({});
}

TEST(NativeBuiltin, AnUnknownProgramIsNotAttached) {
  use_builtin_native({kShippedNative, kShippedNativeCount});
  Program changed = compile({GiNaC::ex(GiNaC::numeric(12345, 7))}, {});
  std::vector<Program*> programs{&changed};
  EXPECT_EQ(builtin_native(changed.fingerprint()), nullptr);
  EXPECT_FALSE(attach_builtin(programs));
  EXPECT_FALSE(changed.native());
  use_builtin_native({});
}

}  // namespace
}  // namespace linkage::eval
