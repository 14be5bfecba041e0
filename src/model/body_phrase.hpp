#pragma once
// How a text names a body: "rod 2" for a body named by a number, else its name.
#include <string>

#include "model/mechanism.hpp"

namespace linkage {

/// "block 1", "rod 2", "disc 3", "ring 4", "mass 5" for a numbered body; "crank" as named.
[[nodiscard]] std::string body_phrase(const Body& body);

}  // namespace linkage
