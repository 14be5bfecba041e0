#include "evaluate/emit_cpp.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace linkage::eval {

std::string cpp_literal(double value) {
  if (std::isnan(value)) return "__builtin_nan(\"\")";
  if (std::isinf(value)) return value > 0 ? "__builtin_inf()" : "(-__builtin_inf())";
  std::array<char, 64> buffer{};
  const auto [end, error] =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), std::fabs(value), std::chars_format::hex);
  if (error != std::errc{}) throw std::logic_error("cpp_literal: to_chars failed");
  std::string digits = "0x";
  digits.append(buffer.data(), end);
  return std::signbit(value) ? "(-" + digits + ")" : digits;
}

namespace {

// "t12": a local's name (appended, not "t" + ...: GCC 12 warns falsely on that).
std::string local(char letter, std::size_t k) {
  std::string name(1, letter);
  name += std::to_string(k);
  return name;
}

// The builtin the interpreter's std:: function of a one-argument op becomes.
const char* builtin(Op op) {
  switch (op) {
    case Op::sqrt:
      return "__builtin_sqrt";
    case Op::sin:
      return "__builtin_sin";
    case Op::cos:
      return "__builtin_cos";
    case Op::tan:
      return "__builtin_tan";
    case Op::exp:
      return "__builtin_exp";
    case Op::log:
      return "__builtin_log";
    case Op::abs:
      return "__builtin_fabs";
    case Op::add:
    case Op::sub:
    case Op::mul:
    case Op::div:
    case Op::neg:
    case Op::pow:
    case Op::sincos:
      break;
  }
  throw std::logic_error("emit_cpp: not a one-argument function");
}

}  // namespace

std::string emit_cpp(const Program& program, std::string_view function_name) {
  const std::size_t inputs = program.input_count();
  // What each register holds at this point of the program: a local's name or a literal.
  std::vector<std::string> value(program.scratch_size());
  std::string out;
  out.reserve(64 * (program.instruction_count() + program.output_count() + inputs) + 256);
  out += "extern \"C\" void ";
  out += function_name;
  out += "(const double* in, const double* state, double* out) {\n";
  for (std::size_t k = 0; k < inputs; ++k) {
    value[k] = local('i', k);
    const bool from_state = k >= program.state_first() && k - program.state_first() < program.state_count();
    out += "  const double " + value[k] + " = " + (from_state ? "state[" : "in[") +
           std::to_string(from_state ? k - program.state_first() : k) + "];\n";
  }
  for (std::size_t k = 0; k < program.constant_count(); ++k) value[inputs + k] = cpp_literal(program.constants()[k]);
  std::size_t n = 0;
  for (const Instruction& i : program.instructions()) {
    const std::string t = local('t', n++);
    const std::string& a = value[i.a];
    const std::string& b = value[i.b];
    std::string rhs;
    switch (i.op) {
      case Op::add:
        rhs = a + " + " + b;
        break;
      case Op::sub:
        rhs = a + " - " + b;
        break;
      case Op::mul:
        rhs = a + " * " + b;
        break;
      case Op::div:
        rhs = a + " / " + b;
        break;
      case Op::neg:
        rhs = "-" + a;
        break;
      case Op::pow:
        rhs = "__builtin_pow(" + a + ", " + b + ")";
        break;
      case Op::sincos: {
        // Both outputs of one call: the sine into dst, the cosine into b.
        out += "  double " + t + "s, " + t + "c;\n";
        out += "  __builtin_sincos(" + a + ", &" + t + "s, &" + t + "c);\n";
        value[i.dst] = t + "s";
        value[i.b] = t + "c";
        continue;
      }
      case Op::sqrt:
      case Op::sin:
      case Op::cos:
      case Op::tan:
      case Op::exp:
      case Op::log:
      case Op::abs:
        rhs = std::string(builtin(i.op)) + "(" + a + ")";
        break;
    }
    out += "  const double " + t + " = " + rhs + ";\n";
    value[i.dst] = t;
  }
  for (std::size_t k = 0; k < program.output_count(); ++k)
    out += "  out[" + std::to_string(k) + "] = " + value[program.output_registers()[k]] + ";\n";
  out += "}\n";
  return out;
}

}  // namespace linkage::eval
