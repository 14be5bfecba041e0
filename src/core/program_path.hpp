#pragma once
// Whether an external program (pdflatex, pandoc) can be run, before asking it to.
#include <string>

namespace linkage {

/// True when an executable file `program` is in one of $PATH's folders.
[[nodiscard]] bool on_path(const std::string& program);

}  // namespace linkage
