#pragma once
// Output files appear whole or not at all: everything is written to a temporary name
// beside the target and renamed over it on commit(). Destroying an uncommitted
// AtomicFile (an error, Ctrl-C) deletes the temporary and leaves any earlier file of
// the same name untouched.
#include <filesystem>
#include <fstream>
#include <string>

namespace linkage {

class AtomicFile {
 public:
  /// Checks that the target's folder exists and is writable; throws Error::input naming
  /// `origin` (e.g. "--out") otherwise.
  AtomicFile(std::filesystem::path target, const std::string& origin, bool binary = false);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  /// The stream writing the temporary file.
  [[nodiscard]] std::ofstream& stream() { return stream_; }
  /// The temporary path, for libraries that open files themselves (libavformat, Cairo).
  [[nodiscard]] const std::filesystem::path& temp_path() const { return temp_; }
  [[nodiscard]] const std::filesystem::path& target() const { return target_; }
  /// Flushes, closes and renames the temporary over the target.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::ofstream stream_;
  bool committed_ = false;
};

/// Throws Error::input naming `origin` unless `dir` exists, is a folder and is writable.
void require_writable_directory(const std::filesystem::path& dir, const std::string& origin);

/// Writes `content` to `target` atomically.
void write_file_atomically(const std::filesystem::path& target, const std::string& content,
                           const std::string& origin);

}  // namespace linkage
