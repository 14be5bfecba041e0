#include "core/input_file.hpp"

#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace linkage {
namespace fs = std::filesystem;

void require_regular_file(const fs::path& path, const std::string& setting) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  const std::string name = quoted(path);
  if (!fs::exists(status)) throw Error::invalid(setting, "file " + name + " does not exist");
  if (fs::is_directory(status)) throw Error::invalid(setting, name + " is a folder, not a file");
  if (fs::is_fifo(status))
    throw Error::invalid(setting, name + " is a FIFO, not a regular file (it would block reading)");
  if (!fs::is_regular_file(status))
    throw Error::invalid(setting, name + " is a device or special file, not a regular file");
}

std::optional<std::string> read_file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace linkage
