#pragma once
// What the fuzz targets share: a scratch folder for inputs that must be files (the
// readers under test take a path), made once per process.
#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace linkage::fuzz {

/// Writes `size` bytes to `name` in this process's scratch folder and returns its path.
std::filesystem::path write_input(const char* name, const std::uint8_t* data, std::size_t size);

/// This process's scratch folder (made on first use).
const std::filesystem::path& scratch_folder();

/// Called by a target for an input its reader accepted; the driver mutates those further.
void note_accepted();
/// How many inputs were accepted so far.
std::size_t accepted_count();

}  // namespace linkage::fuzz

/// libFuzzer's entry point, defined by each target.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
