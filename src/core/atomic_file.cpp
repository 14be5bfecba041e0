#include "core/atomic_file.hpp"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <iostream>
#include <system_error>

#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace linkage {
namespace fs = std::filesystem;

namespace {

bool process_alive(long pid) { return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH; }

/// The file a symlink chain ends at (possibly not existing yet).
fs::path resolve_links(const fs::path& target) {
  fs::path path = target;
  std::error_code ec;
  for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(path, ec)); ++hops) {
    const fs::path next = fs::read_symlink(path, ec);
    if (ec) break;
    path = next.is_absolute() ? next : path.parent_path() / next;
  }
  return path;
}
}  // namespace

std::string quoted(const fs::path& p) {
  std::string text(1, '\'');  // appended, not "'" + ...: GCC 12 misreads that as overlapping (-Wrestrict)
  text += p.string();
  text += '\'';
  return text;
}

std::string temporary_suffix() {
  file_begun();  // a temporary is about to be made
  static std::atomic<unsigned> counter{0};
  return ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

std::string write_failure(const fs::path& file, int error_number) {
  return "cannot write " + quoted(file) + ": " + (error_number != 0 ? std::strerror(error_number) : "write error");
}

void require_writable_directory(const fs::path& dir, const std::string& setting) {
  const fs::path folder = dir.empty() ? fs::path(".") : dir;
  std::error_code ec;
  if (!fs::exists(folder, ec)) throw Error::invalid(setting, "folder " + quoted(folder) + " does not exist");
  if (!fs::is_directory(folder, ec)) throw Error::invalid(setting, quoted(folder) + " is not a folder");
  if (::access(folder.c_str(), W_OK) != 0)
    throw Error::invalid(setting, "folder " + quoted(folder) + " is not writable");
}

void ensure_directory(const fs::path& dir, const std::string& setting) {
  file_begun();
  std::error_code ec;
  for (fs::path part = dir; !part.empty() && part != part.root_path(); part = part.parent_path()) {
    const fs::file_status status = fs::status(part, ec);
    if (fs::exists(status) && !fs::is_directory(status))
      throw Error::invalid(setting, quoted(part) + " exists and is not a folder");
    if (fs::exists(status)) break;
    if (part == part.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  if (ec) throw Error::invalid(setting, "cannot make the folder " + quoted(dir) + ": " + ec.message());
  require_writable_directory(dir, setting);
}

void remove_stale_temporaries(const fs::path& folder, const std::string& prefix) {
  std::error_code ec;
  const std::string start = prefix + ".tmp-";
  for (fs::directory_iterator it(folder.empty() ? fs::path(".") : folder, ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(start, 0) != 0) continue;
    long pid = 0;
    const char* first = name.data() + start.size();
    const char* last = name.data() + name.size();
    const auto [ptr, error] = std::from_chars(first, last, pid);
    if (error != std::errc() || ptr == first || ptr == last || *ptr != '-' || pid <= 0) continue;
    if (pid == ::getpid() || process_alive(pid)) continue;
    std::error_code ignored;
    fs::remove_all(it->path(), ignored);
  }
}

AtomicFile::AtomicFile(fs::path target, const std::string& setting, bool binary)
    : target_(std::move(target)), setting_(setting) {
  const auto mode = binary ? std::ios::out | std::ios::binary : std::ios::out;
  if (target_ == "-") {
    if (binary && ::isatty(STDOUT_FILENO) != 0)
      throw Error::invalid(setting, "'-' is standard output, a terminal; binary output needs a file or a pipe");
    kind_ = Kind::standard_output;
    final_ = temp_ = "/dev/stdout";
    return;
  }
  final_ = resolve_links(target_);
  std::error_code ec;
  const fs::file_status status = fs::status(final_, ec);
  if (fs::is_directory(status)) throw Error::invalid(setting, quoted(target_) + " is a folder, expected a file name");
  if (fs::is_character_file(status) || fs::is_fifo(status)) {
    kind_ = Kind::direct;
    temp_ = final_;
    stream_.open(final_, mode);
    if (!stream_) throw Error::failure(setting, "cannot open " + quoted(target_) + ": " + std::strerror(errno));
    return;
  }
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw Error::invalid(setting, quoted(target_) + " is not a regular file, a character device or a FIFO");
  require_writable_directory(final_.parent_path(), setting);
  remove_stale_temporaries(final_.parent_path(), final_.filename().string());
  temp_ = final_;
  temp_ += temporary_suffix();
  // Keep the extension last: some writers (libavformat) choose the format from it.
  temp_ += final_.extension();
  stream_.open(temp_, mode);
  if (!stream_) throw Error::failure(setting, "cannot create " + quoted(temp_) + ": " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (committed_ || kind_ != Kind::replace) return;
  stream_.close();
  std::error_code ec;
  fs::remove(temp_, ec);
}

std::ostream& AtomicFile::stream() {
  if (kind_ == Kind::standard_output) return std::cout;
  return stream_;
}

void AtomicFile::commit() {
  errno = 0;
  std::ostream& out = stream();
  out.flush();
  const bool ok = static_cast<bool>(out);
  const int error_number = errno;
  if (kind_ != Kind::standard_output) stream_.close();
  if (!ok || (kind_ != Kind::standard_output && stream_.fail()))
    throw Error::failure(setting_, write_failure(target_, error_number));
  if (kind_ == Kind::replace) {
    std::error_code ec;
    fs::rename(temp_, final_, ec);
    if (ec) throw Error::failure(setting_, "cannot replace " + quoted(target_) + ": " + ec.message());
  }
  committed_ = true;
}

void write_file_atomically(const fs::path& target, const std::string& content, const std::string& setting) {
  AtomicFile file(target, setting);
  file.stream() << content;
  file.commit();
}

}  // namespace linkage
