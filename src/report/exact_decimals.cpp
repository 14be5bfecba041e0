#include "report/exact_decimals.hpp"

#include <cctype>

namespace linkage {

namespace {

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// A number needing more zeros is left as the file wrote it.
constexpr long kMostZeros = 30;

}  // namespace

std::string exact_decimal_text(const std::string& expression) {
  const std::string& s = expression;
  const std::size_t n = s.size();
  std::string out;
  std::size_t i = 0;
  while (i < n) {
    if (std::isalpha(static_cast<unsigned char>(s[i])) != 0 || s[i] == '_') {
      const std::size_t start = i;
      while (i < n && name_char(s[i])) ++i;
      out += s.substr(start, i - start);
      continue;
    }
    if (!digit(s[i]) && !(s[i] == '.' && i + 1 < n && digit(s[i + 1]))) {
      out += s[i++];
      continue;
    }
    const std::size_t start = i;
    std::string digits;
    long exponent = 0;
    bool decimal = false;
    while (i < n && digit(s[i])) digits += s[i++];
    if (i < n && s[i] == '.') {
      decimal = true;
      for (++i; i < n && digit(s[i]); ++i) {
        digits += s[i];
        --exponent;
      }
    }
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
      std::size_t k = i + 1;
      if (k < n && (s[k] == '+' || s[k] == '-')) ++k;
      const std::size_t first = k;
      while (k < n && digit(s[k])) ++k;
      if (k > first && k - first <= 3) {
        decimal = true;
        exponent += std::stol(s.substr(i + 1, k - i - 1));
        i = k;
      } else if (k > first) {
        out += s.substr(start, k - start);
        i = k;
        continue;
      }
    }
    if (!decimal) {
      out += digits;
      continue;
    }
    if (exponent < -kMostZeros || exponent > kMostZeros) {
      out += s.substr(start, i - start);
      continue;
    }
    // Whole numbers, not 10^k: the reader refuses large exponents.
    const auto nonzero = digits.find_first_not_of('0');
    digits = nonzero == std::string::npos ? "0" : digits.substr(nonzero);
    if (exponent >= 0)
      out += digits + std::string(static_cast<std::size_t>(exponent), '0');
    else
      out += "(" + digits + "/1" + std::string(static_cast<std::size_t>(-exponent), '0') + ")";
  }
  return out;
}

Mechanism with_exact_decimals(Mechanism m) {
  auto fix = [](Quantity& q) { q.text = exact_decimal_text(q.text); };
  auto fix_optional = [&](std::optional<Quantity>& q) {
    if (q) fix(*q);
  };
  auto fix_vector = [&](Vector2Quantity& v) {
    fix(v.x);
    fix(v.y);
  };
  fix_optional(m.gravity);
  for (Definition& d : m.definitions) fix(d.value);
  for (NamedPoint& p : m.ground_points) fix_vector(p.at);
  for (Body& b : m.bodies) {
    fix(b.mass);
    fix_optional(b.length);
    fix_optional(b.width);
    fix_optional(b.radius);
    fix_optional(b.inertia);
    for (NamedPoint& p : b.points) fix_vector(p.at);
  }
  for (Joint& j : m.joints) {
    fix_optional(j.stiffness);
    fix_optional(j.damping);
    fix_optional(j.rest_angle);
    if (j.axis) fix_vector(*j.axis);
  }
  for (Spring& s : m.springs) {
    fix(s.stiffness);
    fix(s.rest_length);
    fix(s.damping);
  }
  for (AppliedForce& f : m.forces) fix_vector(f.value);
  for (AppliedTorque& t : m.torques) fix(t.value);
  return m;
}

}  // namespace linkage
