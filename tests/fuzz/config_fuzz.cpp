// Fuzz target: the --config reader (TOML inputs) on arbitrary bytes. Refusing the input
// (linkage::Error with exit code 2) is the only allowed failure.
#include "core/error.hpp"
#include "fuzz/fuzz_support.hpp"
#include "model/inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = linkage::fuzz::write_input("inputs.toml", data, size);
  try {
    linkage::Inputs inputs;
    inputs.apply_file(file);
    inputs.validate();
    linkage::fuzz::note_accepted();
  } catch (const linkage::Error& e) {
    if (e.code() != linkage::ExitCode::bad_input) throw;
  }
  return 0;
}
