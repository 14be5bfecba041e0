#include "core/input_file.hpp"

#include <unistd.h>

#include <cerrno>
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
  // Why the file cannot be looked at, by errno: only a missing one "does not exist".
  if (ec && ec != std::errc::no_such_file_or_directory) {
    if (ec == std::errc::too_many_symbolic_link_levels)
      throw Error::invalid(setting, name + " is a symbolic link loop (a link that leads back to itself)");
    if (ec == std::errc::permission_denied)
      throw Error::invalid(setting,
                           "cannot read " + name + ": permission denied (a folder on its path may not be entered)");
    if (ec == std::errc::not_a_directory)
      throw Error::invalid(setting, name + ": a part of the path before the file name is a file, not a folder");
    throw Error::invalid(setting, "cannot look at " + name + ": " + ec.message());
  }
  if (!fs::exists(status)) throw Error::invalid(setting, "file " + name + " does not exist");
  if (fs::is_directory(status)) throw Error::invalid(setting, name + " is a folder, not a file");
  if (fs::is_fifo(status))
    throw Error::invalid(setting, name + " is a FIFO, not a regular file (it would block reading)");
  if (!fs::is_regular_file(status))
    throw Error::invalid(setting, name + " is a device or special file, not a regular file");
  if (::access(path.c_str(), R_OK) != 0 && errno == EACCES)
    throw Error::invalid(setting, "cannot read " + name + ": permission denied (the file is not readable by you)");
}

std::optional<std::string> read_file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace linkage
