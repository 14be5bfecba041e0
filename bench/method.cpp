#include "bench/method.hpp"

namespace linkage::bench {

const char* name(RhsKind kind) {
  switch (kind) {
    case RhsKind::fastest: return "ours";
    case RhsKind::definition: return "definition";
    case RhsKind::user: return "user";
  }
  return "?";
}

std::vector<Method> peer_methods() {
  std::vector<Method> out = odeint_methods();
  for (Method& m : sundials_methods()) out.push_back(std::move(m));
  return out;
}

}  // namespace linkage::bench
