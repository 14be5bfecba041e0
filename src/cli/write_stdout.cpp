#include "cli/write_stdout.hpp"

#include <algorithm>
#include <cstdio>

#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace linkage::cli {

void write_stdout(const std::string& text, const std::string& what) {
  constexpr std::size_t kPiece = 1 << 16;
  for (std::size_t at = 0; at < text.size(); at += kPiece) {
    throw_if_interrupted();
    const std::size_t n = std::min(kPiece, text.size() - at);
    if (std::fwrite(text.data() + at, 1, n, stdout) != n || std::fflush(stdout) != 0)
      throw Error::failure("cannot write " + what + " to standard output");
  }
}

}  // namespace linkage::cli
