#pragma once
// Bytes in the gzip format (RFC 1952) through zlib: what a page carries its frames in,
// for the browser's own DecompressionStream('gzip') to open.
#include <string>
#include <string_view>

namespace linkage {

/// `data` gzip-compressed at zlib's best level; no file name or time in the header, so
/// the same data gives the same bytes.
[[nodiscard]] std::string gzip(std::string_view data);

}  // namespace linkage
