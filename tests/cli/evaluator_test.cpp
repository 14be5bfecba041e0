// --evaluator (issue 24): built-in native code gives the interpreter's numbers on every
// shipped mechanism; a user's file compiles once into the cache, then loads from it; with
// no compiler on PATH auto falls back and compiled is refused. XDG_CACHE_HOME (and PATH)
// are set here for the runs, so the user's cache is never touched.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "linkage/embedded_mechanisms.hpp"
#include "support/scoped_env.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

using test::test_mechanism;

using test::run_linkage;
using test::RunResult;
using test::ScopedEnv;
using test::TempDir;

RunResult simulate(const std::string& mechanism, const std::string& evaluator) {
  return run_linkage(
      {"simulate", "--mechanism", mechanism, "--duration", "1", "--columns", "all", "--evaluator", evaluator});
}

TEST(Evaluator, CompiledAndInterpretedGiveTheSameCsvOnEveryShippedMechanism) {
  TempDir cache;
  const ScopedEnv xdg("XDG_CACHE_HOME", cache.path().string());
  for (const EmbeddedMechanism& shipped : kEmbeddedMechanisms) {
    const std::string name(shipped.name);
    const RunResult compiled = simulate(name, "compiled");
    const RunResult interpreted = simulate(name, "interpreted");
    ASSERT_EQ(compiled.exit_code, 0) << name << ": " << compiled.err;
    ASSERT_EQ(interpreted.exit_code, 0) << name << ": " << interpreted.err;
    EXPECT_NE(compiled.err.find("evaluator: compiled (built in)"), std::string::npos) << name << ": " << compiled.err;
    EXPECT_NE(interpreted.err.find("evaluator: interpreted"), std::string::npos) << name;
    EXPECT_EQ(compiled.out, interpreted.out) << name;
    EXPECT_GT(compiled.out.size(), 100U) << name;
  }
  EXPECT_TRUE(cache.entries().empty()) << "built-in code needs no cache";
}

TEST(Evaluator, AUsersFileCompilesOnceThenLoadsFromTheCache) {
  TempDir cache;
  const ScopedEnv xdg("XDG_CACHE_HOME", cache.path().string());
  const std::string file = test_mechanism("cart-pendulum.toml");
  const RunResult first = simulate(file, "compiled");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.err.find("evaluator: compiled (compiled into " + cache.path().string() + "/linkage/native/"),
            std::string::npos)
      << first.err;
  const RunResult second = simulate(file, "auto");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.err.find("evaluator: compiled (cache " + cache.path().string() + "/linkage/native/"),
            std::string::npos)
      << second.err;
  const RunResult interpreted = simulate(file, "interpreted");
  ASSERT_EQ(interpreted.exit_code, 0) << interpreted.err;
  EXPECT_EQ(first.out, interpreted.out);
  EXPECT_EQ(second.out, interpreted.out);
}

// Loads in the state's rates and coordinates (issue 25): the generated programs take q and
// q' as inputs, so the compiled code gives the interpreter's CSV, shaking columns included.
TEST(Evaluator, LoadsThatDependOnTheStateCompileToTheInterpretersNumbers) {
  TempDir cache;
  const ScopedEnv xdg("XDG_CACHE_HOME", cache.path().string());
  const std::string file = test_mechanism("state-loads-cart.toml");
  const RunResult compiled = simulate(file, "compiled");
  const RunResult interpreted = simulate(file, "interpreted");
  ASSERT_EQ(compiled.exit_code, 0) << compiled.err;
  ASSERT_EQ(interpreted.exit_code, 0) << interpreted.err;
  EXPECT_NE(compiled.err.find("evaluator: compiled (compiled into"), std::string::npos) << compiled.err;
  EXPECT_NE(compiled.out.find("shaking_moment"), std::string::npos);
  EXPECT_EQ(compiled.out, interpreted.out);
}

TEST(Evaluator, WithoutACompilerAutoFallsBackAndCompiledIsRefused) {
  TempDir cache, empty;
  const ScopedEnv xdg("XDG_CACHE_HOME", cache.path().string());
  const ScopedEnv path("PATH", empty.path().string());
  const std::string file = test_mechanism("cart-pendulum.toml");
  const RunResult automatic = simulate(file, "auto");
  ASSERT_EQ(automatic.exit_code, 0) << automatic.err;
  EXPECT_NE(automatic.err.find("evaluator: interpreted (no C++ compiler on PATH)"), std::string::npos) << automatic.err;
  const RunResult compiled = simulate(file, "compiled");
  EXPECT_EQ(compiled.exit_code, 2);
  EXPECT_NE(compiled.err.find("--evaluator: 'compiled' cannot run: no C++ compiler (c++) on PATH"), std::string::npos)
      << compiled.err;
  EXPECT_EQ(compiled.out, "");
  // A shipped mechanism needs no compiler.
  const RunResult shipped = simulate("four-bar", "compiled");
  EXPECT_EQ(shipped.exit_code, 0) << shipped.err;
  EXPECT_NE(shipped.err.find("evaluator: compiled (built in)"), std::string::npos) << shipped.err;
}

}  // namespace
}  // namespace linkage
