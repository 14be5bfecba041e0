#include "core/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <system_error>

#include "core/error.hpp"

namespace linkage {
namespace fs = std::filesystem;

void require_writable_directory(const fs::path& dir, const std::string& origin) {
  const fs::path folder = dir.empty() ? fs::path(".") : dir;
  std::error_code ec;
  if (!fs::exists(folder, ec))
    throw Error::input(origin + ": folder '" + folder.string() + "' does not exist");
  if (!fs::is_directory(folder, ec))
    throw Error::input(origin + ": '" + folder.string() + "' is not a folder");
  if (::access(folder.c_str(), W_OK) != 0)
    throw Error::input(origin + ": folder '" + folder.string() + "' is not writable");
}

namespace {
fs::path temporary_name(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  fs::path temp = target;
  temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  // Keep the extension last: some writers (libavformat) choose the format from it.
  temp += target.extension();
  return temp;
}
}  // namespace

AtomicFile::AtomicFile(fs::path target, const std::string& origin, bool binary)
    : target_(std::move(target)), temp_(temporary_name(target_)) {
  if (fs::is_directory(target_))
    throw Error::input(origin + ": '" + target_.string() + "' is a folder, expected a file name");
  require_writable_directory(target_.parent_path(), origin);
  stream_.open(temp_, binary ? std::ios::out | std::ios::binary : std::ios::out);
  if (!stream_) throw Error::failure(origin + ": cannot create '" + temp_.string() + "'");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  stream_.close();
  std::error_code ec;
  fs::remove(temp_, ec);
}

void AtomicFile::commit() {
  stream_.flush();
  const bool ok = static_cast<bool>(stream_);
  stream_.close();
  if (!ok) throw Error::failure("cannot write '" + target_.string() + "' (disk full?)");
  std::error_code ec;
  fs::rename(temp_, target_, ec);
  if (ec) throw Error::failure("cannot rename '" + temp_.string() + "' to '" + target_.string() + "': " + ec.message());
  committed_ = true;
}

void write_file_atomically(const fs::path& target, const std::string& content, const std::string& origin) {
  AtomicFile file(target, origin);
  file.stream() << content;
  file.commit();
}

}  // namespace linkage
