#include "evaluate/program.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace linkage::eval {

void Program::interpret(const double* inputs, const double* state, double* outputs, double* scratch) const {
  double* r = scratch;
  std::copy_n(inputs, input_names_.size(), r);
  std::copy_n(state, state_count_, r + state_first_);
  std::copy(constants_.begin(), constants_.end(), r + input_names_.size());
  for (const Instruction& i : code_) {
    switch (i.op) {
      case Op::add:
        r[i.dst] = r[i.a] + r[i.b];
        break;
      case Op::sub:
        r[i.dst] = r[i.a] - r[i.b];
        break;
      case Op::mul:
        r[i.dst] = r[i.a] * r[i.b];
        break;
      case Op::div:
        r[i.dst] = r[i.a] / r[i.b];
        break;
      case Op::neg:
        r[i.dst] = -r[i.a];
        break;
      case Op::sqrt:
        r[i.dst] = std::sqrt(r[i.a]);
        break;
      case Op::pow:
        r[i.dst] = std::pow(r[i.a], r[i.b]);
        break;
      case Op::sin:
        r[i.dst] = std::sin(r[i.a]);
        break;
      case Op::cos:
        r[i.dst] = std::cos(r[i.a]);
        break;
      case Op::sincos: {
        double s = 0.0;
        double c = 0.0;
        ::sincos(r[i.a], &s, &c);
        r[i.dst] = s;
        r[i.b] = c;
        break;
      }
      case Op::tan:
        r[i.dst] = std::tan(r[i.a]);
        break;
      case Op::exp:
        r[i.dst] = std::exp(r[i.a]);
        break;
      case Op::log:
        r[i.dst] = std::log(r[i.a]);
        break;
      case Op::abs:
        r[i.dst] = std::fabs(r[i.a]);
        break;
    }
  }
  for (std::size_t k = 0; k < output_registers_.size(); ++k) outputs[k] = r[output_registers_[k]];
}

namespace {

// FNV-1a over 64-bit words, byte by byte: the same on every machine and run.
struct Fnv {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  void add(std::uint64_t v) {
    for (int k = 0; k < 8; ++k) {
      h ^= (v >> (8 * k)) & 0xffU;
      h *= 0x100000001b3ULL;
    }
  }
};

}  // namespace

void Program::read_state_from(std::size_t first, std::size_t count) {
  if (first > input_names_.size() || count > input_names_.size() - first)
    throw std::invalid_argument("Program::read_state_from: inputs " + std::to_string(first) + " .. " +
                                std::to_string(first + count) + " are beyond its " +
                                std::to_string(input_names_.size()) + " inputs");
  state_first_ = first;
  state_count_ = count;
}

std::uint64_t Program::fingerprint() const {
  Fnv f;
  f.add(kNativeGeneratorVersion);
  f.add(input_names_.size());
  f.add(state_first_);
  f.add(state_count_);
  f.add(constants_.size());
  for (const double c : constants_) f.add(std::bit_cast<std::uint64_t>(c));
  f.add(code_.size());
  for (const Instruction& i : code_) {
    f.add(static_cast<std::uint64_t>(i.op));
    f.add(i.dst);
    f.add(i.a);
    f.add(i.b);
  }
  f.add(output_registers_.size());
  for (const std::uint32_t r : output_registers_) f.add(r);
  f.add(register_count_);
  return f.h;
}

namespace {

const char* infix(Op op) {
  switch (op) {
    case Op::add:
      return " + ";
    case Op::sub:
      return " - ";
    case Op::mul:
      return " * ";
    case Op::div:
      return " / ";
    case Op::neg:
    case Op::sqrt:
    case Op::pow:
    case Op::sin:
    case Op::cos:
    case Op::sincos:
    case Op::tan:
    case Op::exp:
    case Op::log:
    case Op::abs:
      return nullptr;
  }
  return nullptr;
}

const char* name(Op op) {
  switch (op) {
    case Op::neg:
      return "-";
    case Op::sqrt:
      return "sqrt";
    case Op::pow:
      return "pow";
    case Op::sin:
      return "sin";
    case Op::cos:
      return "cos";
    case Op::sincos:
      return "sincos";
    case Op::tan:
      return "tan";
    case Op::exp:
      return "exp";
    case Op::log:
      return "log";
    case Op::abs:
      return "abs";
    case Op::add:
    case Op::sub:
    case Op::mul:
    case Op::div:
      return "?";
  }
  return "?";
}

}  // namespace

std::string Program::dump() const {
  std::ostringstream out;
  out.precision(17);
  for (std::size_t k = 0; k < input_names_.size(); ++k) out << 'r' << k << " = input " << input_names_[k] << '\n';
  for (std::size_t k = 0; k < constants_.size(); ++k)
    out << 'r' << input_names_.size() + k << " = " << constants_[k] << '\n';
  for (const Instruction& i : code_) {
    if (const char* op = infix(i.op))
      out << 'r' << i.dst << " = r" << i.a << op << 'r' << i.b << '\n';
    else if (i.op == Op::sincos)
      out << 'r' << i.dst << ", r" << i.b << " = sincos(r" << i.a << ")\n";
    else if (i.op == Op::neg)
      out << 'r' << i.dst << " = -r" << i.a << '\n';
    else if (i.op == Op::pow)
      out << 'r' << i.dst << " = pow(r" << i.a << ", r" << i.b << ")\n";
    else
      out << 'r' << i.dst << " = " << name(i.op) << "(r" << i.a << ")\n";
  }
  for (std::size_t k = 0; k < output_registers_.size(); ++k)
    out << "out" << k << " = r" << output_registers_[k] << '\n';
  return out.str();
}

}  // namespace linkage::eval
