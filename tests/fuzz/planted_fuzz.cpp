// A target with a planted fault, for the test that the driver finds and reports one: it
// throws on any input holding both "[[" and "{{", which only mutations of its seed make.
#include <stdexcept>
#include <string_view>

#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  if (input.find("[[") != std::string_view::npos && input.find("{{") != std::string_view::npos)
    throw std::logic_error("planted fault");
  linkage::fuzz::note_accepted();
  return 0;
}
