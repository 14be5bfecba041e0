#pragma once
// A command's whole output to standard output, for solve, modes and mechanisms alike.
#include <string>

namespace linkage::cli {

/// `text` to stdout in pieces, with a signal check between them (a long chain's solution
/// is megabytes), flushed; Error::failure "cannot write `what` to standard output".
void write_stdout(const std::string& text, const std::string& what);

}  // namespace linkage::cli
