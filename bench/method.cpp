#include "bench/method.hpp"

namespace linkage::bench {

const char* name(RhsKind kind) {
  switch (kind) {
    case RhsKind::fastest:
      return "ours";
    case RhsKind::definition:
      return "definition";
    case RhsKind::user:
      return "user";
    case RhsKind::general:
      return "general";
  }
  return "?";
}

std::string PeerLibrary::not_built_note() const {
  return "peer " + library + " (" + integrators + ") not built: install " + package + " and re-run cmake";
}

// LINKAGE_PEER_*: 1 when bench/CMakeLists.txt found the library and compiled its peer.
std::vector<PeerLibrary> peer_libraries() {
  return {
      {"Boost.Odeint",
       "RKF78, dense Dopri5, Bulirsch-Stoer",
       "libboost-dev",
       {"odeint-rkf78", "odeint-dopri5", "odeint-bs"},
       LINKAGE_PEER_ODEINT == 1},
      {"SUNDIALS", "CVODE, IDA", "libsundials-dev", {"cvode-adams", "ida"}, LINKAGE_PEER_SUNDIALS == 1},
  };
}

std::vector<std::string> peers_not_built() {
  std::vector<std::string> out;
  for (const PeerLibrary& peer : peer_libraries())
    if (!peer.built) out.push_back(peer.library);
  return out;
}

std::vector<Method> peer_methods() {
  std::vector<Method> out;
#if LINKAGE_PEER_ODEINT
  out = odeint_methods();
#endif
#if LINKAGE_PEER_SUNDIALS
  for (Method& m : sundials_methods()) out.push_back(std::move(m));
#endif
  return out;
}

}  // namespace linkage::bench
