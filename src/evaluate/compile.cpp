// compile(): GiNaC expressions to a Program in three passes. Values are numbered as the
// expression DAG is walked (one node per distinct operation on distinct operands, so
// shared subexpressions and shared prefixes of sums and products are computed once);
// the nodes the outputs need are kept; then registers are assigned, a temporary's
// register reused after its last read, and sin and cos of one argument paired.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/interrupt.hpp"
#include "evaluate/program.hpp"
#include "symbolic/system.hpp"

namespace linkage::eval {
namespace {

using Index = std::uint32_t;

// Integer powers up to this are multiplied out; the rounding error of repeated
// multiplication grows with the exponent, so higher ones go to std::pow.
constexpr long kMaxMultipliedPower = 16;

bool is_binary(Op op) { return op == Op::add || op == Op::sub || op == Op::mul || op == Op::div || op == Op::pow; }
bool is_commutative(Op op) { return op == Op::add || op == Op::mul; }

// The value of `op` on constants, folded while compiling with the functions run() uses.
double fold(Op op, double x, double y) {
  switch (op) {
    case Op::add:
      return x + y;
    case Op::sub:
      return x - y;
    case Op::mul:
      return x * y;
    case Op::div:
      return x / y;
    case Op::neg:
      return -x;
    case Op::sqrt:
      return std::sqrt(x);
    case Op::pow:
      return std::pow(x, y);
    case Op::sin:
      return std::sin(x);
    case Op::cos:
      return std::cos(x);
    case Op::tan:
      return std::tan(x);
    case Op::exp:
      return std::exp(x);
    case Op::log:
      return std::log(x);
    case Op::abs:
      return std::fabs(x);
    case Op::sincos:
      break;
  }
  throw std::logic_error("compile: sincos is made only when registers are assigned");
}

std::string printed(const GiNaC::ex& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}

enum class Kind : std::uint8_t { input, constant, operation };

struct Node {
  Kind kind = Kind::operation;
  Op op = Op::add;
  Index a = 0;
  Index b = 0;
  double value = 0.0;  // a constant's
};

// The distinct nodes an operation reads: x * x reads x once.
std::vector<Index> operands(const Node& node) {
  if (!is_binary(node.op) || node.a == node.b) return {node.a};
  return {node.a, node.b};
}

// What compile() makes a Program of.
struct Parts {
  std::vector<std::string> input_names;
  std::vector<double> constants;
  std::vector<Instruction> code;
  std::vector<Index> output_registers;
  std::size_t register_count = 0;
};

class Builder {
 public:
  explicit Builder(const std::vector<GiNaC::symbol>& inputs) {
    for (const GiNaC::symbol& s : inputs) {
      const auto [it, fresh] = inputs_.emplace(s, static_cast<Index>(nodes_.size()));
      if (!fresh) throw std::invalid_argument("compile: input symbol '" + s.get_name() + "' is given twice");
      nodes_.push_back({Kind::input, Op::add, 0, 0, 0.0});
      names_.push_back(s.get_name());
    }
  }

  Index output(const GiNaC::ex& e, std::size_t index) {
    output_ = index;
    return value(e);
  }

  /// From now on `s` stands for the value of `e` (computed once, where first needed).
  void define(const GiNaC::symbol& s, const GiNaC::ex& e) {
    if (inputs_.count(s) != 0 || definitions_.count(s) != 0)
      throw std::invalid_argument("compile: symbol '" + s.get_name() + "' is defined twice");
    definitions_.emplace(s, value(e));
  }

  [[nodiscard]] Parts finish(const std::vector<Index>& outputs) const;

  /// Frees the walk's maps with a signal check between batches (their destructors cannot
  /// check): a long chain's take seconds to free.
  void release() {
    clear_checking(cache_);
    clear_checking(shapes_);
    clear_checking(numbering_);
  }

 private:
  // Every node is the value of an expression's canonical orientation (shape()): e itself,
  // or -e when its shape says negated; callers apply the sign.
  Index value(const GiNaC::ex& e) {
    const Index node = magnitude(e);
    if (!shape(e).negated) return node;
    // -2 x y: x y times the constant -2, not a negation after the product.
    if (GiNaC::is_a<GiNaC::mul>(e) && sym::in_double_range(e).is_equal(e)) return product(e, true);
    return emit(Op::neg, node);
  }

  Index magnitude(const GiNaC::ex& e) {
    if (const auto it = cache_.find(e); it != cache_.end()) return it->second;
    // One output can take seconds (a long chain's kinetic energy, sums nested per link).
    throw_if_interrupted();
    const Index node = compute(e);
    cache_.emplace(e, node);
    return node;
  }

  Index compute(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      if (const auto defined = definitions_.find(e); defined != definitions_.end()) return defined->second;
      const auto it = inputs_.find(e);
      if (it == inputs_.end())
        throw std::invalid_argument("compile: symbol '" + printed(e) + "' in output " + std::to_string(output_) +
                                    " is not among the inputs (" + input_list() + ")");
      return it->second;
    }
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
      const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
      return number(n.is_real() ? GiNaC::abs(n) : n, e);
    }
    if (GiNaC::is_a<GiNaC::constant>(e)) {
      const GiNaC::ex v = e.evalf();
      if (!GiNaC::is_a<GiNaC::numeric>(v)) fail(e, "a constant without a numeric value");
      return number(GiNaC::ex_to<GiNaC::numeric>(v), e);
    }
    if (GiNaC::is_a<GiNaC::add>(e)) return sum(e);
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      const GiNaC::ex distributed = sym::in_double_range(e);
      if (distributed.is_equal(e)) return product(e);
      const Index node = magnitude(distributed);
      return shape(distributed).negated == shape(e).negated ? node : emit(Op::neg, node);
    }
    if (GiNaC::is_a<GiNaC::power>(e)) return power(e.op(0), e.op(1));
    if (GiNaC::is_a<GiNaC::function>(e)) return function(e);
    fail(e, "a " + std::string(GiNaC::ex_to<GiNaC::basic>(e).class_name()));
  }

  [[noreturn]] void fail(const GiNaC::ex& e, const std::string& what) const {
    throw std::invalid_argument("compile: output " + std::to_string(output_) + " contains " + printed(e) + ", " + what +
                                ", which cannot be evaluated");
  }

  std::string input_list() const {
    std::string list;
    for (const std::string& n : names_) list += (list.empty() ? "" : ", ") + n;
    return list.empty() ? "none" : list;
  }

  Index number(const GiNaC::numeric& n, const GiNaC::ex& source) {
    if (!n.is_real()) fail(source, "a complex number");
    return constant(sym::to_double(n));
  }

  Index constant(double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    if (const auto it = constants_.find(bits); it != constants_.end()) return it->second;
    const auto node = static_cast<Index>(nodes_.size());
    nodes_.push_back({Kind::constant, Op::add, 0, 0, v});
    constants_.emplace(bits, node);
    return node;
  }

  Index emit(Op op, Index a, Index b = 0) {
    if (!is_binary(op)) b = 0;
    if (const std::optional<Index> absorbed = absorb_negation(op, a, b)) return *absorbed;
    if (is_commutative(op) && b < a) std::swap(a, b);
    const bool constant_operands =
        nodes_[a].kind == Kind::constant && (!is_binary(op) || nodes_[b].kind == Kind::constant);
    if (constant_operands) return constant(fold(op, nodes_[a].value, nodes_[b].value));
    const auto key = std::make_tuple(op, a, b);
    if (const auto it = numbering_.find(key); it != numbering_.end()) return it->second;
    const auto node = static_cast<Index>(nodes_.size());
    nodes_.push_back({Kind::operation, op, a, b, 0.0});
    numbering_.emplace(key, node);
    return node;
  }

  // The operand of a negation node, if `k` is one.
  std::optional<Index> negated(Index k) const {
    if (nodes_[k].kind == Kind::operation && nodes_[k].op == Op::neg) return nodes_[k].a;
    return std::nullopt;
  }

  // op on a negation, rewritten where IEEE arithmetic gives the same bits, signed zeros
  // included: a + (-y) is a - y and a - (-y) is a + y by definition, addition commutes,
  // (-x) y = -(x y) and (-x) / y = -(x / y) exactly, -(-x) = x, |-x| = |x|. The negation
  // then moves out of products into the sum that takes it in, so the code does not spend
  // an instruction on it. (-x) - b is left alone: -(x + b) differs where x + b cancels
  // (+0 against -0).
  std::optional<Index> absorb_negation(Op op, Index a, Index b) {
    const std::optional<Index> x = negated(a);
    const std::optional<Index> y = is_binary(op) ? negated(b) : std::nullopt;
    const auto constant_value = [&](Index k) -> std::optional<double> {
      if (nodes_[k].kind == Kind::constant) return nodes_[k].value;
      return std::nullopt;
    };
    switch (op) {
      case Op::neg:
      case Op::abs:
        if (x) return op == Op::neg ? *x : emit(Op::abs, *x);
        break;
      case Op::add:
        if (y) return emit(Op::sub, a, *y);
        if (x) return emit(Op::sub, b, *x);
        break;
      case Op::sub:
        if (y) return emit(Op::add, a, *y);
        break;
      case Op::mul:
      case Op::div:
        if (x && y) return emit(op, *x, *y);
        // A constant takes the sign: (-x) c = x (-c), c / (-y) = (-c) / y.
        if (x && constant_value(b)) return emit(op, *x, constant(-*constant_value(b)));
        if (y && constant_value(a)) return emit(op, constant(-*constant_value(a)), *y);
        if (x) return emit(Op::neg, emit(op, *x, b));
        if (y) return emit(Op::neg, emit(op, a, *y));
        break;
      case Op::sqrt:
      case Op::pow:
      case Op::sin:
      case Op::cos:
      case Op::sincos:
      case Op::tan:
      case Op::exp:
      case Op::log:
        break;
    }
    return std::nullopt;
  }

  // acc op operand, or the operand alone for the first; each term or factor is folded in
  // as soon as it is computed, so few temporaries are live at once.
  Index accumulate(Op op, std::optional<Index> acc, Index operand) { return acc ? emit(op, *acc, operand) : operand; }

  // GiNaC orders the terms of sums and products by hash values that change from run to
  // run (they involve addresses), and it makes the first term of a sum positive where the
  // sum is a factor or a base ((a - b)^2 may come as (b - a)^2): so operands are walked in
  // an order of their own structure, and each sum is computed in an orientation of its
  // own. The same inputs then give the same program and the same bits every run.
  struct Shape {
    std::uint64_t hash = 0;  // of the canonical orientation
    bool negated = false;    // the expression is minus its canonical orientation
  };

  static std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h * 0x100000001b3ULL;
  }
  static std::uint64_t mix_text(std::uint64_t h, const std::string& t) {
    for (const char c : t) h = mix(h, static_cast<unsigned char>(c));
    return h;
  }

  Shape shape(const GiNaC::ex& e) {
    if (const auto it = shapes_.find(e); it != shapes_.end()) return it->second;
    throw_if_interrupted();  // walking a long chain's unexpanded angular momentum takes seconds
    constexpr std::uint64_t seed = 0xcbf29ce484222325ULL;
    Shape out;
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      out.hash = mix_text(mix(seed, 1), GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    } else if (GiNaC::is_a<GiNaC::numeric>(e)) {
      const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
      out = {mix_text(mix(seed, 2), printed(GiNaC::abs(n))), n.is_real() && n.is_negative()};
    } else if (e.nops() == 0) {
      out.hash = mix_text(mix(seed, 2), printed(e));
    } else if (GiNaC::is_a<GiNaC::add>(e)) {
      // A sum is a set of signed terms; of it and its negation, the smaller set is canonical.
      std::vector<std::pair<std::uint64_t, bool>> as_is, flipped;
      for (std::size_t k = 0; k < e.nops(); ++k) {
        const Shape t = shape(e.op(k));
        as_is.emplace_back(t.hash, t.negated);
        flipped.emplace_back(t.hash, !t.negated);
      }
      std::sort(as_is.begin(), as_is.end());
      std::sort(flipped.begin(), flipped.end());
      out.negated = flipped < as_is;
      out.hash = mix(seed, 3);
      for (const auto& [h, negative] : out.negated ? flipped : as_is) out.hash = mix(mix(out.hash, h), negative);
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
      std::vector<std::uint64_t> parts;
      for (std::size_t k = 0; k < e.nops(); ++k) {
        const Shape f = shape(e.op(k));
        out.negated = out.negated != f.negated;
        // -x is x times the coefficient -1: a coefficient of magnitude 1 is only a sign.
        const bool unit =
            GiNaC::is_a<GiNaC::numeric>(e.op(k)) && GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e.op(k))) == 1;
        if (!unit) parts.push_back(f.hash);
      }
      std::sort(parts.begin(), parts.end());  // a product is a set of factors: order-free
      out.hash = mix(seed, 4);
      for (const std::uint64_t part : parts) out.hash = mix(out.hash, part);
      if (parts.size() == 1) out.hash = parts.front();  // -x has x's shape
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
      const Shape base = shape(e.op(0)), exponent = shape(e.op(1));
      if (is_integer(e.op(1))) {  // (-b)^k = (-1)^k b^k
        out.negated = base.negated && !GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_even();
        out.hash = mix(mix(mix(seed, 6), base.hash), mix(exponent.hash, exponent.negated));
      } else {
        out.hash = mix(mix(mix(mix(seed, 7), base.hash), base.negated), mix(exponent.hash, exponent.negated));
      }
    } else {
      out.hash = GiNaC::is_a<GiNaC::function>(e) ? mix_text(mix(seed, 5), GiNaC::ex_to<GiNaC::function>(e).get_name())
                                                 : mix(seed, 8);
      for (std::size_t k = 0; k < e.nops(); ++k) {
        const Shape a = shape(e.op(k));
        out.hash = mix(mix(out.hash, a.hash), a.negated);
      }
    }
    shapes_.emplace(e, out);
    return out;
  }

  template <class Map>
  static void clear_checking(Map& map) {
    constexpr std::size_t kBatch = 4096;
    std::size_t k = 0;
    for (auto it = map.begin(); it != map.end(); ++k) {
      if (k % kBatch == 0) throw_if_interrupted();
      it = map.erase(it);
    }
  }

  static bool is_integer(const GiNaC::ex& e) {
    return GiNaC::is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_integer();
  }

  struct Signed {
    Index node;
    bool negative;
  };

  // The canonical orientation of a sum: its terms by their shapes, each as a magnitude
  // and a sign, so the sum subtracts instead of negating.
  Index sum(const GiNaC::ex& e) {
    const bool flip = shape(e).negated;
    std::vector<std::tuple<std::uint64_t, bool, std::size_t>> keyed;
    for (std::size_t k = 0; k < e.nops(); ++k) {
      const Shape t = shape(e.op(k));
      keyed.emplace_back(t.hash, t.negated != flip, k);
    }
    std::sort(keyed.begin(), keyed.end());
    std::optional<Index> acc;
    std::vector<Index> leading_negatives;  // subtracted once a positive term starts the sum
    for (const auto& [hash, negative, k] : keyed) {
      const Signed term{magnitude(e.op(k)), negative};
      if (acc)
        acc = emit(term.negative ? Op::sub : Op::add, *acc, term.node);
      else if (term.negative)
        leading_negatives.push_back(term.node);
      else
        acc = term.node;
    }
    if (!acc) {
      std::optional<Index> total;
      for (const Index t : leading_negatives) total = accumulate(Op::add, total, t);
      return emit(Op::neg, *total);
    }
    for (const Index t : leading_negatives) acc = emit(Op::sub, *acc, t);
    return *acc;
  }

  // coefficient * (numerator factors) / (denominator factors). Factors multiply in the
  // order they were first computed, so products of the same early factors (parameters,
  // m D) share their prefix; the coefficient comes last, so 2 m D and -m D share m D, and
  // a negative one is a negative constant, not a negation.
  Index product(const GiNaC::ex& e, bool negative = false) {
    // The canonical orientation: the coefficient's magnitude times each factor's own.
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
    for (std::size_t k = 0; k < e.nops(); ++k) keyed.emplace_back(shape(e.op(k)).hash, k);
    std::sort(keyed.begin(), keyed.end());
    GiNaC::numeric coefficient = 1;
    std::vector<Index> numerator, denominator;
    for (const auto& [hash, k] : keyed) {
      const GiNaC::ex f = e.op(k);
      if (GiNaC::is_a<GiNaC::numeric>(f)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(f);
        coefficient *= n.is_real() ? GiNaC::abs(n) : n;
      } else if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
                 GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_negative()) {
        denominator.push_back(power(f.op(0), -f.op(1)));
      } else {
        numerator.push_back(magnitude(f));
      }
    }
    const auto chain = [this](std::vector<Index>& factors) {
      std::sort(factors.begin(), factors.end());
      std::optional<Index> acc;
      for (const Index f : factors) acc = accumulate(Op::mul, acc, f);
      return *acc;
    };
    if (negative) coefficient = -coefficient;
    if (numerator.empty()) return emit(Op::div, number(coefficient, e), chain(denominator));
    Index result = chain(numerator);
    if (!denominator.empty()) result = emit(Op::div, result, chain(denominator));
    if (coefficient == 1) return result;
    if (coefficient == -1) return emit(Op::neg, result);
    return emit(Op::mul, result, number(coefficient, e));
  }

  // The canonical orientation of base^exponent: an integer power of the base's own (the
  // sign is shape()'s), any other power of the base's value.
  Index power(const GiNaC::ex& base, const GiNaC::ex& exponent) {
    if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
      const GiNaC::numeric& k = GiNaC::ex_to<GiNaC::numeric>(exponent);
      const bool negative = k.is_negative();
      const GiNaC::numeric size = GiNaC::abs(k);
      std::optional<Index> positive;
      if (k.is_integer() && size <= kMaxMultipliedPower) {
        positive = integer_power(magnitude(base), size.to_long());
      } else if (k.is_integer()) {
        positive = emit(Op::pow, magnitude(base), constant(sym::to_double(size)));
      } else if (k.is_rational() && k.denom() == 2 && size <= kMaxMultipliedPower) {
        // x^(p/2) = x^((p-1)/2) sqrt(x)
        const Index b = value(base);
        const Index root = emit(Op::sqrt, b);
        const long whole = (size.numer().to_long() - 1) / 2;
        positive = whole == 0 ? root : emit(Op::mul, integer_power(b, whole), root);
      }
      if (positive) return negative ? emit(Op::div, constant(1.0), *positive) : *positive;
    }
    return emit(Op::pow, value(base), value(exponent));
  }

  // x^2 = x x, x^3 = x^2 x, x^4 = x^2 x^2: square-and-multiply, the squares shared.
  Index integer_power(Index base, long n) {
    if (n == 1) return base;
    if (n % 2 == 0) {
      const Index half = integer_power(base, n / 2);
      return emit(Op::mul, half, half);
    }
    return emit(Op::mul, integer_power(base, n - 1), base);
  }

  Index function(const GiNaC::ex& e) {
    static const std::map<std::string, Op> kFunctions = {{"sin", Op::sin}, {"cos", Op::cos}, {"tan", Op::tan},
                                                         {"exp", Op::exp}, {"log", Op::log}, {"abs", Op::abs}};
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    const auto it = kFunctions.find(name);
    if (it == kFunctions.end() || e.nops() != 1)
      fail(e, "the function " + name + " (valid: sin, cos, tan, exp, log, abs, powers)");
    return emit(it->second, value(e.op(0)));
  }

  std::vector<Node> nodes_;
  std::vector<std::string> names_;
  std::map<GiNaC::ex, Index, GiNaC::ex_is_less> inputs_;
  std::map<GiNaC::ex, Index, GiNaC::ex_is_less> definitions_;
  GiNaC::exhashmap<Index> cache_;
  GiNaC::exhashmap<Shape> shapes_;
  // Looked up once per operation emitted: hashed, as a long chain's case emits 10^5 of them.
  struct KeyHash {
    std::size_t operator()(const std::tuple<Op, Index, Index>& k) const noexcept {
      const std::uint64_t ab = (std::uint64_t{std::get<1>(k)} << 32) | std::get<2>(k);
      return std::hash<std::uint64_t>{}(ab * 0x9e3779b97f4a7c15ULL ^ static_cast<std::uint64_t>(std::get<0>(k)));
    }
  };
  std::unordered_map<std::tuple<Op, Index, Index>, Index, KeyHash> numbering_;
  std::map<std::uint64_t, Index> constants_;
  std::size_t output_ = 0;
};

Parts Builder::finish(const std::vector<Index>& outputs) const {
  const std::size_t n = nodes_.size();
  constexpr std::size_t kNever = std::numeric_limits<std::size_t>::max();
  // Keep what the outputs need; a node's last read decides when its register is free.
  std::vector<bool> live(n, false);
  std::vector<std::size_t> last_read(n, 0);
  for (const Index o : outputs) {
    live[o] = true;
    last_read[o] = kNever;
  }
  for (std::size_t k = n; k-- > 0;) {
    if (!live[k] || nodes_[k].kind != Kind::operation) continue;
    for (const Index operand : operands(nodes_[k])) {
      live[operand] = true;
      last_read[operand] = std::max(last_read[operand], k);
    }
  }
  // sin and cos of one argument: one sincos where the first of the two stood.
  std::map<Index, Index> sin_of, cos_of;
  for (std::size_t k = 0; k < n; ++k) {
    if (!live[k] || nodes_[k].kind != Kind::operation) continue;
    if (nodes_[k].op == Op::sin) sin_of[nodes_[k].a] = static_cast<Index>(k);
    if (nodes_[k].op == Op::cos) cos_of[nodes_[k].a] = static_cast<Index>(k);
  }
  std::vector<std::optional<Index>> partner(n);
  for (const auto& [argument, s] : sin_of) {
    if (const auto it = cos_of.find(argument); it != cos_of.end()) {
      partner[s] = it->second;
      partner[it->second] = s;
    }
  }

  Parts parts;
  parts.input_names = names_;
  std::vector<Index> reg(n, 0);
  Index next = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (nodes_[k].kind == Kind::input) reg[k] = next++;
  for (std::size_t k = 0; k < n; ++k) {
    if (nodes_[k].kind == Kind::constant && live[k]) {
      reg[k] = next++;
      parts.constants.push_back(nodes_[k].value);
    }
  }
  std::vector<Index> free;  // temporaries past their last read, reused last-freed first
  const auto allocate = [&] {
    if (free.empty()) return next++;
    const Index r = free.back();
    free.pop_back();
    return r;
  };
  std::vector<bool> done(n, false);
  for (std::size_t k = 0; k < n; ++k) {
    const Node& node = nodes_[k];
    if (!live[k] || node.kind != Kind::operation) continue;
    for (const Index operand : operands(node))
      if (nodes_[operand].kind == Kind::operation && last_read[operand] == k) free.push_back(reg[operand]);
    if (done[k]) continue;
    if (partner[k]) {
      const Index other = *partner[k];
      const Index s = node.op == Op::sin ? static_cast<Index>(k) : other;
      const Index c = node.op == Op::sin ? other : static_cast<Index>(k);
      reg[s] = allocate();
      reg[c] = allocate();
      done[other] = true;
      parts.code.push_back({Op::sincos, reg[s], reg[node.a], reg[c]});
      continue;
    }
    reg[k] = allocate();
    parts.code.push_back({node.op, reg[k], reg[node.a], is_binary(node.op) ? reg[node.b] : 0});
  }
  for (const Index o : outputs) parts.output_registers.push_back(reg[o]);
  parts.register_count = next;
  return parts;
}

}  // namespace

Program compile(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs) {
  return compile(outputs, inputs, {});
}

Program compile(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs,
                const std::vector<Definition>& definitions) {
  Builder builder(inputs);
  for (const auto& [symbol, expression] : definitions) builder.define(symbol, expression);
  std::vector<Index> nodes;
  nodes.reserve(outputs.size());
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    throw_if_interrupted();  // a long chain's case has thousands of outputs
    nodes.push_back(builder.output(outputs[k], k));
  }
  Parts parts = builder.finish(nodes);
  builder.release();
  return Program(std::move(parts.input_names), std::move(parts.constants), std::move(parts.code),
                 std::move(parts.output_registers), parts.register_count);
}

Program compile(const GiNaC::matrix& outputs, const std::vector<GiNaC::symbol>& inputs) {
  return compile(flatten(outputs), inputs);
}

std::vector<GiNaC::ex> flatten(const GiNaC::matrix& m) {
  std::vector<GiNaC::ex> entries;
  entries.reserve(m.nops());
  for (unsigned i = 0; i < m.rows(); ++i)
    for (unsigned j = 0; j < m.cols(); ++j) entries.push_back(m(i, j));
  return entries;
}

}  // namespace linkage::eval
