#pragma once
// Output files appear whole or not at all, as trusted Unix tools write them:
//   - a regular file (or a name that does not exist yet) is written to a temporary
//     name beside it and renamed over it on commit(); a symlink keeps pointing where it
//     did and the file it points to is replaced;
//   - a character device or FIFO (/dev/null, a pipe) is opened and written directly;
//   - "-" is standard output (refused for binary output on a terminal).
// Destroying an uncommitted AtomicFile (an error, a signal) deletes the temporary and
// leaves any earlier file of the same name untouched. Temporaries are named
// TARGET.tmp-PID-N.EXT; opening a target removes those a killed run left behind.
//
// Errors are about `setting` (neutral name, e.g. "out"): Error::invalid / failure.
#include <filesystem>
#include <fstream>
#include <iosfwd>
#include <string>

namespace linkage {

class AtomicFile {
 public:
  enum class Kind { replace, direct, standard_output };

  AtomicFile(std::filesystem::path target, const std::string& setting, bool binary = false);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  /// The stream to write.
  [[nodiscard]] std::ostream& stream();
  /// The path libraries that open files themselves (libavformat, libspng, Cairo) should
  /// write: the temporary, the device or FIFO itself, or /dev/stdout.
  [[nodiscard]] const std::filesystem::path& temp_path() const { return temp_; }
  [[nodiscard]] const std::filesystem::path& target() const { return target_; }
  [[nodiscard]] Kind kind() const { return kind_; }
  /// Flushes and closes; for a replaced file renames the temporary over the target.
  /// A failed write is Error::failure naming the target and the system's reason.
  void commit();

 private:
  std::filesystem::path target_;  // as given
  std::filesystem::path final_;   // where the bytes end up (a symlink's file)
  std::filesystem::path temp_;
  std::string setting_;
  Kind kind_ = Kind::replace;
  std::ofstream stream_;
  bool committed_ = false;
};

/// Throws Error::invalid(setting) unless `dir` exists, is a folder and is writable.
void require_writable_directory(const std::filesystem::path& dir, const std::string& setting);

/// Makes `dir` and its parents like `mkdir -p`; Error::invalid(setting) if a part of
/// the path exists and is not a folder, or the folder cannot be made or written.
void ensure_directory(const std::filesystem::path& dir, const std::string& setting);

/// Removes `folder`'s entries named PREFIX.tmp-PID-N... (files or folders) whose process
/// PID is no longer running: what a killed run left behind.
void remove_stale_temporaries(const std::filesystem::path& folder, const std::string& prefix);

/// "NAME.tmp-PID-N" with this process's PID and a fresh N.
[[nodiscard]] std::string temporary_suffix();

/// Writes `content` to `target` atomically.
void write_file_atomically(const std::filesystem::path& target, const std::string& content, const std::string& setting);

/// 'PATH' in single quotes, for messages.
[[nodiscard]] std::string quoted(const std::filesystem::path& path);

/// "cannot write 'FILE': REASON" from errno, for write failures.
[[nodiscard]] std::string write_failure(const std::filesystem::path& file, int error_number);

}  // namespace linkage
