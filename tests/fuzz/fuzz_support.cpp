#include "fuzz/fuzz_support.hpp"

#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <string>

namespace linkage::fuzz {

const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    const std::filesystem::path f =
        std::filesystem::temp_directory_path() / ("linkage-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(f);
    return f;
  }();
  return folder;
}

std::filesystem::path write_input(const char* name, const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = scratch_folder() / name;
  // A new file each time: truncating one makes ext4 write it out on close (slow).
  std::error_code ec;
  std::filesystem::remove(path, ec);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) throw std::runtime_error("cannot write " + path.string());
  return path;
}

namespace {
std::size_t accepted = 0;
}  // namespace

void note_accepted() { ++accepted; }

std::size_t accepted_count() { return accepted; }

}  // namespace linkage::fuzz
