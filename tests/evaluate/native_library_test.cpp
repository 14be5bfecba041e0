// Native code against the interpreter it replaces: every Op, every case of every shipped
// mechanism at random states, and the cache's refusals and rebuilds. These tests run the
// system's C++ compiler; each uses a cache folder of its own (XDG_CACHE_HOME), never the user's.
#include "evaluate/native_library.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "core/run_program.hpp"
#include "evaluate/case_evaluator.hpp"
#include "evaluate/mechanism_dynamics.hpp"
#include "formulations/case_numbers.hpp"
#include "linkage/embedded_mechanisms.hpp"
#include "model/mechanism_toml.hpp"
#include "structured_agreement.hpp"
#include "support/mechanisms_in_code.hpp"
#include "support/scoped_env.hpp"
#include "support/test_support.hpp"

namespace linkage::eval {
namespace {

namespace fs = std::filesystem;
using GiNaC::ex;
using GiNaC::symbol;
using test::read_text;
using test::ScopedEnv;
using test::TempDir;
using test::write_text;

// A cache of the test's own.
struct Cache {
  TempDir dir;
  ScopedEnv xdg{"XDG_CACHE_HOME", (dir.path() / "cache").string()};
};

std::vector<double> interpreted(const Program& p, const std::vector<double>& in) {
  std::vector<double> out(p.output_count()), scratch(p.scratch_size());
  p.interpret(in.data(), out.data(), scratch.data());
  return out;
}

std::vector<double> ran(const Program& p, const std::vector<double>& in) {
  std::vector<double> out(p.output_count()), scratch(p.scratch_size());
  p.run(in.data(), out.data(), scratch.data());
  return out;
}

// Native and interpreted outputs agree to 1e-13 relative (1 + |x|, as the case tests);
// returns how many differ in any bit.
std::size_t expect_agree(const Program& p, const std::vector<double>& in, const std::string& what) {
  const std::vector<double> a = ran(p, in), b = interpreted(p, in);
  std::size_t differ = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(a[k], b[k], 1e-13 * (1 + std::abs(b[k]))) << what << " output " << k;
    EXPECT_TRUE(std::isfinite(a[k])) << what << " output " << k;
    if (std::bit_cast<std::uint64_t>(a[k]) != std::bit_cast<std::uint64_t>(b[k])) ++differ;
  }
  return differ;
}

// One expression set that compiles to every Op.
Program every_op() {
  const symbol x("x"), y("y"), z("z");
  const std::vector<ex> outputs = {x + y,
                                   x - y,
                                   x * y * 1.5,
                                   x / y,
                                   -GiNaC::exp(z),
                                   GiNaC::sqrt(x),
                                   GiNaC::pow(x, y),
                                   GiNaC::pow(x, 20),
                                   GiNaC::sin(y) * GiNaC::cos(y),
                                   GiNaC::sin(x),
                                   GiNaC::cos(z),
                                   GiNaC::tan(z),
                                   GiNaC::log(y),
                                   GiNaC::abs(z - x),
                                   ex(2.5)};
  return compile(outputs, {x, y, z});
}

std::vector<std::vector<double>> every_op_inputs() { return {{0.7, 1.3, -0.4}, {2.5, 0.2, 1.1}, {1e-3, 7.0, -3.0}}; }

TEST(NativeLibrary, EveryOpAgreesWithTheInterpreter) {
  Cache cache;
  Program p = every_op();
  std::set<Op> ops;
  for (const Instruction& i : p.instructions()) ops.insert(i.op);
  EXPECT_EQ(ops.size(), 14U) << p.dump();  // add sub mul div neg sqrt pow sin cos sincos tan exp log abs
  const NativeAttachment a = attach_native({&p});
  ASSERT_TRUE(a.attached) << a.reason;
  EXPECT_TRUE(a.compiled);
  EXPECT_TRUE(p.native());
  std::size_t differ = 0;
  for (const std::vector<double>& in : every_op_inputs()) differ += expect_agree(p, in, "every op");
  EXPECT_EQ(differ, 0U);  // -ffp-contract=off and the same libm calls: the same bits
  // The second time the cache answers.
  Program again = every_op();
  const NativeAttachment b = attach_native({&again});
  ASSERT_TRUE(b.attached) << b.reason;
  EXPECT_FALSE(b.compiled);
  EXPECT_EQ(b.library, a.library);
  EXPECT_EQ(b.rebuilt, "");
}

// A right-hand side reads q and q' where y keeps them: native code reads the state inputs
// from its second pointer, none of them from the inputs' array.
TEST(NativeLibrary, StateInputsAreReadFromTheState) {
  Cache cache;
  Program p = every_op();
  p.read_state_from(1, 2);  // y and z
  const NativeAttachment a = attach_native({&p});
  ASSERT_TRUE(a.attached) << a.reason;
  for (const std::vector<double>& in : every_op_inputs()) {
    const std::vector<double> state{in[1], in[2]};
    const std::vector<double> elsewhere{in[0], std::nan(""), std::nan("")};  // never read
    std::vector<double> out(p.output_count()), scratch(p.scratch_size());
    p.run(elsewhere.data(), state.data(), out.data(), scratch.data());
    const std::vector<double> reference = interpreted(p, in);
    for (std::size_t k = 0; k < out.size(); ++k)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(out[k]), std::bit_cast<std::uint64_t>(reference[k])) << "output " << k;
  }
}

TEST(NativeLibrary, SourceIsTheSameForTheSamePrograms) {
  const Program a = every_op(), b = every_op();
  const symbol x("x");
  const Program c = compile({GiNaC::sin(x)}, {x});
  EXPECT_EQ(a.fingerprint(), b.fingerprint());
  EXPECT_NE(a.fingerprint(), c.fingerprint());
  const NativeSource one = native_source({&a, &c}), two = native_source({&c, &b, &a});
  EXPECT_EQ(one.text, two.text);
  EXPECT_EQ(one.hash, two.hash);
  EXPECT_EQ(one.functions, 2U);
}

// Every case of every shipped mechanism: A and B natively, three random states each.
TEST(NativeLibrary, EveryShippedMechanismAgreesWithTheInterpreter) {
  Cache cache;
  std::vector<std::unique_ptr<sym::System>> systems;
  std::vector<std::unique_ptr<CaseEvaluator>> evaluators;
  std::vector<std::string> names;
  std::vector<Program*> programs;
  for (const EmbeddedMechanism& shipped : kEmbeddedMechanisms) {
    systems.push_back(std::make_unique<sym::System>(load_mechanism(std::string(shipped.name))));
    for (CaseId id : kAllCases) {
      evaluators.push_back(std::make_unique<CaseEvaluator>(*systems.back(), derive_case(*systems.back(), id)));
      names.push_back(std::string(shipped.name) + " Case " + std::to_string(case_number(id)));
      for (Program* p : evaluators.back()->programs()) programs.push_back(p);
    }
  }
  const NativeAttachment a = attach_native(programs);
  ASSERT_TRUE(a.attached) << a.reason;
  std::mt19937 rng(24);
  std::size_t differ = 0, outputs = 0;
  for (std::size_t k = 0; k < evaluators.size(); ++k) {
    const sym::System& system = *systems[k / kAllCases.size()];
    for (int trial = 0; trial < 3; ++trial) {
      const GiNaC::exmap values = state_values(system, built::random_state(system, rng), 0.3 * trial);
      for (Program* p : evaluators[k]->programs()) {
        ASSERT_TRUE(p->native());
        differ += expect_agree(*p, evaluators[k]->inputs(values), names[k]);
        outputs += p->output_count();
      }
    }
  }
  EXPECT_GT(outputs, 0U);
  RecordProperty("outputs_compared", static_cast<int>(outputs));
  RecordProperty("outputs_not_bit_identical", static_cast<int>(differ));
}

// Everything a sample reports, in one list.
std::vector<double> flat(const MechanismSample& s) {
  std::vector<double> out;
  for (const std::vector<double>* part : {&s.pose, &s.rates, &s.slider, &s.force, &s.constraint, &s.constraint_rate,
                                          &s.accelerations, &s.slider_accelerations, &s.points})
    out.insert(out.end(), part->begin(), part->end());
  for (const double v : {s.kinetic, s.potential, s.power, s.momentum_x, s.momentum_y, s.angular_momentum})
    out.push_back(v);
  out.insert(out.end(), s.com.begin(), s.com.end());
  return out;
}

// MechanismDynamics::attach_native: every program of every case of every shipped
// mechanism (the tree recursion's too) native; y' and the whole sample, with the
// kinematics, as the interpreter gives them, with and without Baumgarte's terms.
TEST(NativeLibrary, MechanismDynamicsAgreesWithTheInterpreter) {
  Cache cache;
  std::mt19937 rng(2024);
  std::size_t differ = 0, compared = 0;
  for (const EmbeddedMechanism& shipped : kEmbeddedMechanisms) {
    const sym::System system(load_mechanism(std::string(shipped.name)));
    for (CaseId id : kAllCases) {
      const std::string what = std::string(shipped.name) + " Case " + std::to_string(case_number(id));
      MechanismDynamics native(system, id);
      MechanismDynamics interpreted(system, id);
      const NativeAttachment a = native.attach_native(true);
      ASSERT_TRUE(a.attached) << what << ": " << a.reason;
      for (int trial = 0; trial < 3; ++trial) {
        const Eigen::VectorXd y = native.initial_state(built::random_state(system, rng));
        const double t = 0.3 * trial;
        if (trial == 2) {  // the constraints' program in the right-hand side too
          native.set_baumgarte(5.0, 7.0);
          interpreted.set_baumgarte(5.0, 7.0);
        }
        Eigen::VectorXd dn, di;
        ASSERT_EQ(native.derivative(t, y, dn), interpreted.derivative(t, y, di)) << what;
        MechanismSample sn, si;
        native.sample(t, y, sn, true);
        interpreted.sample(t, y, si, true);
        std::vector<double> n(dn.begin(), dn.end()), i(di.begin(), di.end());
        const std::vector<double> fn = flat(sn), fi = flat(si);
        n.insert(n.end(), fn.begin(), fn.end());
        i.insert(i.end(), fi.begin(), fi.end());
        ASSERT_EQ(n.size(), i.size()) << what;
        for (std::size_t k = 0; k < n.size(); ++k) {
          EXPECT_NEAR(n[k], i[k], 1e-13 * (1 + std::abs(i[k]))) << what << " value " << k << " trial " << trial;
          if (std::bit_cast<std::uint64_t>(n[k]) != std::bit_cast<std::uint64_t>(i[k])) ++differ;
        }
        compared += n.size();
      }
    }
  }
  RecordProperty("values_compared", static_cast<int>(compared));
  RecordProperty("values_not_bit_identical", static_cast<int>(differ));
}

// With native code attached, y' comes from A's structure (fixed-size LU up to 8 rows, the
// Schur complement of M for [M G; J 0], the recursion for long trees): the same
// accelerations as the general path, to 1e-12 relative to the largest, at random states
// of every case of every shipped mechanism, with and without Baumgarte's terms.
TEST(NativeLibrary, StructuredSolveAgreesWithTheGeneralPath) {
  Cache cache;
  std::mt19937 rng(77);
  for (const EmbeddedMechanism& shipped : kEmbeddedMechanisms) {
    const sym::System system(load_mechanism(std::string(shipped.name)));
    for (CaseId id : kAllCases) {
      const std::string what = std::string(shipped.name) + " Case " + std::to_string(case_number(id));
      MechanismDynamics native(system, id);
      ASSERT_TRUE(native.attach_native().attached) << what;
      test::expect_structured_agrees(system, native, rng, what);
    }
  }
}

// A parallelogram four-bar with every link in line (a dead point): J M^-1 J^T is
// singular, and the structured solve says so as the LU of A (unknowns()) does, in every
// case.
TEST(NativeLibrary, StructuredSolveFindsTheDeadPoint) {
  Cache cache;
  Mechanism mechanism = load_mechanism("four-bar");
  for (Parameter& p : mechanism.parameters) {
    if (p.name == "a" || p.name == "c") p.value = 0.2;
    if (p.name == "b" || p.name == "d") p.value = 0.3;
  }
  const sym::System system(std::move(mechanism));
  GiNaC::exmap state = system.initial_state();
  for (const sym::GeneralizedCoordinate& g : system.coordinates()) {
    state[g.symbols.q] = GiNaC::numeric(0);
    state[g.symbols.q_dot] = GiNaC::numeric(1);
  }
  for (CaseId id : kAllCases) {
    const std::string what = "Case " + std::to_string(case_number(id));
    MechanismDynamics native(system, id);
    MechanismDynamics general(system, id);
    ASSERT_TRUE(native.attach_native().attached) << what;
    native.solve_by_structure(true);
    const Eigen::VectorXd y = native.initial_state(state);
    Eigen::VectorXd dn, u;
    EXPECT_EQ(general.unknowns(0, y, u), 0.0) << what;
    EXPECT_FALSE(native.derivative(0, y, dn)) << what;
    EXPECT_TRUE(dn.hasNaN()) << what;
  }
}

// Garbage where the cached library should be: deleted, rebuilt, and right.
TEST(NativeLibrary, CorruptCacheEntryIsRebuilt) {
  Cache cache;
  Program p = every_op();
  const NativeSource source = native_source({&p});
  fs::create_directories(native_cache_folder());
  const fs::path entry = native_cache_folder() / (source.hash + ".so");
  write_text(entry, "not a shared object");
  const NativeAttachment a = attach_native({&p});
  ASSERT_TRUE(a.attached) << a.reason;
  EXPECT_TRUE(a.compiled);
  EXPECT_NE(a.rebuilt.find("does not load"), std::string::npos) << a.rebuilt;
  EXPECT_NE(read_text(entry), "not a shared object");
  for (const std::vector<double>& in : every_op_inputs()) expect_agree(p, in, "rebuilt");
}

// A library at the right name from another generator version: rebuilt, never used.
TEST(NativeLibrary, OtherVersionIsRebuilt) {
  Cache cache;
  Program p = every_op();
  const NativeSource source = native_source({&p});
  fs::create_directories(native_cache_folder());
  const std::string version = "linkage_native_version = " + std::to_string(kNativeGeneratorVersion) + "ULL";
  std::string other = source.text;
  const std::size_t at = other.find(version);
  ASSERT_NE(at, std::string::npos);
  other.replace(at, version.size(), "linkage_native_version = 999ULL");
  const fs::path cpp = cache.dir / "other.cpp";
  write_text(cpp, other);
  const fs::path entry = native_cache_folder() / (source.hash + ".so");
  ProgramRun run;
  run.argv = {"c++", "-O2", "-fPIC", "-shared", "-o", entry.string(), cpp.string()};
  run.capture_output = true;
  const ProgramResult built = run_program(run);
  ASSERT_TRUE(built.succeeded()) << built.output;
  const NativeAttachment a = attach_native({&p});
  ASSERT_TRUE(a.attached) << a.reason;
  EXPECT_TRUE(a.compiled);
  EXPECT_NE(a.rebuilt.find("generator version 999"), std::string::npos) << a.rebuilt;
  for (const std::vector<double>& in : every_op_inputs()) expect_agree(p, in, "rebuilt");
}

// Loading a shared object runs its code: not from a folder others can write.
TEST(NativeLibrary, CacheFolderWritableByOthersIsRefused) {
  Cache cache;
  Program p = every_op();
  fs::create_directories(native_cache_folder());
  fs::permissions(native_cache_folder(), fs::perms::all);
  const NativeAttachment a = attach_native({&p});
  EXPECT_FALSE(a.attached);
  EXPECT_FALSE(a.compiled);
  EXPECT_NE(a.reason.find("can be written by other users"), std::string::npos) << a.reason;
  EXPECT_FALSE(p.native());
  const std::vector<double> in = every_op_inputs()[0];
  EXPECT_EQ(ran(p, in), interpreted(p, in));
}

TEST(NativeLibrary, CachedFileWritableByOthersIsRefused) {
  Cache cache;
  Program p = every_op();
  ASSERT_TRUE(attach_native({&p}).attached);
  Program q = every_op();
  const fs::path entry = native_cache_folder() / (native_source({&q}).hash + ".so");
  fs::permissions(entry, fs::perms::group_write, fs::perm_options::add);
  const NativeAttachment a = attach_native({&q});
  EXPECT_FALSE(a.attached);
  EXPECT_NE(a.reason.find("can be written by other users"), std::string::npos) << a.reason;
  EXPECT_FALSE(q.native());
}

// No compiler on PATH: the interpreter runs, and says why.
TEST(NativeLibrary, NoCompilerFallsBackToTheInterpreter) {
  Cache cache;
  fs::create_directories(cache.dir / "empty");
  Program p = every_op();
  const std::vector<double> in = every_op_inputs()[1];
  const std::vector<double> before = ran(p, in);
  NativeAttachment a;
  {
    const ScopedEnv path("PATH", (cache.dir / "empty").string());
    a = attach_native({&p});
  }
  EXPECT_FALSE(a.attached);
  EXPECT_EQ(a.reason, "no C++ compiler (c++) on PATH");
  EXPECT_FALSE(p.native());
  EXPECT_EQ(ran(p, in), before);
}

// A compile that fails: the interpreter runs, the reason keeps the compiler's first error
// line, and no temporary is left in the cache. The stand-in compiler prints what g++ does.
TEST(NativeLibrary, FailedCompileFallsBackWithTheFirstErrorLine) {
  Cache cache;
  const fs::path bin = cache.dir / "bin";
  fs::create_directories(bin);
  write_text(bin / "c++",
             "#!/bin/sh\necho 'In file included from x.cpp:1:'\necho 'x.cpp:2:3: error: boom'\n"
             "echo 'x.cpp:4:5: error: second'\nexit 1\n");
  fs::permissions(bin / "c++", fs::perms::owner_all);
  Program p = every_op();
  NativeAttachment a;
  {
    const ScopedEnv path("PATH", bin.string());
    a = attach_native({&p});
  }
  EXPECT_FALSE(a.attached);
  EXPECT_TRUE(a.compiled);
  EXPECT_NE(a.reason.find("c++ failed: x.cpp:2:3: error: boom"), std::string::npos) << a.reason;
  EXPECT_EQ(a.reason.find("second"), std::string::npos) << a.reason;
  EXPECT_FALSE(p.native());
  EXPECT_TRUE(fs::is_empty(native_cache_folder()));
}

}  // namespace
}  // namespace linkage::eval
