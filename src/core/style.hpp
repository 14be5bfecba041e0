#pragma once
// How symbols and formulas are spelt in output: Unicode text (θ̈₁), ASCII text (th1'')
// or LaTeX (\ddot{\theta}_1). Every printer takes one.

namespace linkage {

enum class Style { unicode, ascii, latex };

}  // namespace linkage
