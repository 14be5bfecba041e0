#pragma once
// GiNaC expressions compiled once into a flat register program, so the numbers of a
// mechanism come from the very expressions that are printed, at the cost of a few
// arithmetic instructions per call: no allocation, no expression tree walked per call.
//
// The register file is one array of doubles: the inputs, then the constants, then the
// temporaries (reused once dead). Every distinct subexpression is computed once, sin and
// cos of one argument by one sincos, integer powers by multiplication. The same inputs
// give the same bits: the order of operations is fixed when compiling.
#include <ginac/ginac.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "evaluate/native_entry.hpp"

namespace linkage::eval {

/// Bumped when emit_cpp's output or the native library's layout changes: part of every
/// fingerprint, so code from another generator is never attached.
inline constexpr std::uint64_t kNativeGeneratorVersion = 2;

enum class Op : std::uint8_t { add, sub, mul, div, neg, sqrt, pow, sin, cos, sincos, tan, exp, log, abs };

/// r[dst] = r[a] op r[b]; for sincos, r[dst] = sin(r[a]) and r[b] = cos(r[a]).
struct Instruction {
  Op op = Op::add;
  std::uint32_t dst = 0;
  std::uint32_t a = 0;
  std::uint32_t b = 0;
};

/// A symbol standing for the value of an expression (compile()'s third argument).
using Definition = std::pair<GiNaC::symbol, GiNaC::ex>;

class Program {
 public:
  Program() = default;  // no inputs, no outputs

  /// Evaluates every output. `scratch` holds scratch_size() doubles; nothing is allocated.
  /// With native code attached, that code runs instead (and `scratch` is not touched).
  void run(const double* inputs, double* outputs, double* scratch) const {
    run(inputs, inputs + state_first_, outputs, scratch);
  }
  /// As run(inputs, ...), with the state inputs (read_state_from) read from `state`
  /// instead: their entries of `inputs` are not read.
  void run(const double* inputs, const double* state, double* outputs, double* scratch) const {
    if (native_ != nullptr)
      native_(inputs, state, outputs);
    else
      interpret(inputs, state, outputs, scratch);
  }
  /// The interpreter alone, whether or not native code is attached: the reference.
  void interpret(const double* inputs, double* outputs, double* scratch) const {
    interpret(inputs, inputs + state_first_, outputs, scratch);
  }
  void interpret(const double* inputs, const double* state, double* outputs, double* scratch) const;

  /// Inputs first .. first + count - 1 are the state: run(inputs, state, ...) reads them
  /// from `state`. Set before fingerprint() and attach(): native code is made for it.
  /// Throws std::invalid_argument for a range beyond the inputs.
  void read_state_from(std::size_t first, std::size_t count);
  [[nodiscard]] std::size_t state_first() const { return state_first_; }
  [[nodiscard]] std::size_t state_count() const { return state_count_; }

  /// Runs `f` instead of the interpreter from now on (nullptr: the interpreter again). `f`
  /// must compute this program (its fingerprint's): native_library.hpp checks that.
  void attach(NativeFunction f) { native_ = f; }
  [[nodiscard]] bool native() const { return native_ != nullptr; }
  /// A 64-bit hash of everything run() computes from (inputs, the state's range, constants'
  /// bits, code, output registers, register count) and kNativeGeneratorVersion: equal programs, equal
  /// fingerprints, on every run and machine.
  [[nodiscard]] std::uint64_t fingerprint() const;

  [[nodiscard]] std::size_t input_count() const { return input_names_.size(); }
  [[nodiscard]] std::size_t output_count() const { return output_registers_.size(); }
  [[nodiscard]] std::size_t scratch_size() const { return register_count_; }
  [[nodiscard]] std::size_t instruction_count() const { return code_.size(); }
  [[nodiscard]] std::size_t constant_count() const { return constants_.size(); }
  [[nodiscard]] const std::vector<Instruction>& instructions() const { return code_; }
  [[nodiscard]] const std::vector<double>& constants() const { return constants_; }
  [[nodiscard]] const std::vector<std::uint32_t>& output_registers() const { return output_registers_; }
  /// One line per register load, instruction and output, e.g. "r7, r8 = sincos(r3)".
  [[nodiscard]] std::string dump() const;

 private:
  friend Program compile(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs,
                         const std::vector<Definition>& definitions);
  Program(std::vector<std::string> input_names, std::vector<double> constants, std::vector<Instruction> code,
          std::vector<std::uint32_t> output_registers, std::size_t register_count)
      : input_names_(std::move(input_names)),
        constants_(std::move(constants)),
        code_(std::move(code)),
        output_registers_(std::move(output_registers)),
        register_count_(register_count) {}

  std::vector<std::string> input_names_;         // registers 0 .. inputs-1
  std::vector<double> constants_;                // the registers after the inputs
  std::vector<Instruction> code_;                // in evaluation order
  std::vector<std::uint32_t> output_registers_;  // where each output ends
  std::size_t register_count_ = 0;
  std::size_t state_first_ = 0;  // read_state_from(): none by default
  std::size_t state_count_ = 0;
  NativeFunction native_ = nullptr;
};

/// Compiles `outputs` over `inputs` (the order of run()'s arrays). Throws
/// std::invalid_argument naming a symbol that is not an input, a duplicate input, a
/// function it cannot compile or a non-real number.
[[nodiscard]] Program compile(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs);
/// As compile(outputs, inputs), where each definition's symbol (in order: a definition may
/// use earlier ones) stands for its expression's value, computed once: steps written over
/// intermediate values, as a linear solve over the entries of A and B (static_solve.hpp).
[[nodiscard]] Program compile(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs,
                              const std::vector<Definition>& definitions);
/// The entries of `outputs`, row by row.
[[nodiscard]] Program compile(const GiNaC::matrix& outputs, const std::vector<GiNaC::symbol>& inputs);
/// The entries of a matrix, row by row; append several to compile A and B as one program.
[[nodiscard]] std::vector<GiNaC::ex> flatten(const GiNaC::matrix& m);

}  // namespace linkage::eval
