#include "core/deriving.hpp"

namespace linkage {

Deriving::Deriving(bool quiet) : line_("linkage: deriving the equations", quiet) {
  end_at_once_.emplace([this] { line_.finish(); });
}

void Deriving::done() {
  end_at_once_.reset();
  line_.finish();
}

}  // namespace linkage
