#pragma once
// Files the user gives to read (a config, a lesson, a lesson's text): they must be
// regular files. A FIFO would block the program forever and a device (/dev/zero) never
// ends or reads as empty, so both are refused up front.
#include <filesystem>
#include <optional>
#include <string>

namespace linkage {

/// Error::invalid(setting) unless `path` exists and is a readable regular file (a symlink
/// to one is fine): a missing file, a symbolic link loop, a path through a file, a folder
/// or a file not readable for permissions, a folder, a FIFO or a device each get their own message.
void require_regular_file(const std::filesystem::path& path, const std::string& setting);

/// The whole of a file's bytes, or nullopt when it cannot be opened.
[[nodiscard]] std::optional<std::string> read_file_text(const std::filesystem::path& path);

}  // namespace linkage
