#pragma once
// A command's derivation of its equations (and of their printed forms), which takes seconds
// for a long chain: a line says so on a terminal once it lasts a second, and a signal
// meanwhile ends the run at once. No file is begun until done(): freeing a long chain's
// expressions by unwinding took seconds.
#include <optional>

#include "core/interrupt.hpp"
#include "core/progress.hpp"

namespace linkage {

class Deriving {
 public:
  explicit Deriving(bool quiet = false);
  Deriving(const Deriving&) = delete;
  Deriving& operator=(const Deriving&) = delete;
  /// The line goes; from now on a signal unwinds, so that files begun are removed.
  void done();

 private:
  ElapsedLine line_;
  std::optional<EndAtOnceOnSignal> end_at_once_;
};

}  // namespace linkage
