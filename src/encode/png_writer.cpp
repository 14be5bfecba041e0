#include "encode/png_writer.hpp"

#include <spng.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "encode/slot_queue.hpp"

namespace linkage {
namespace fs = std::filesystem;
namespace {
using Clock = std::chrono::steady_clock;

struct SpngDeleter {
  void operator()(spng_ctx* context) const { spng_ctx_free(context); }
};
struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::size_t channels(const PngOptions& options) { return options.alpha ? 4 : 3; }

std::size_t image_bytes(int width, int height, const PngOptions& options) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * channels(options);
}

void validate_options(const PngOptions& options) {
  if (options.compression_level < 0 || options.compression_level > 9)
    throw Error::input("PNG compression level " + std::to_string(options.compression_level) + " must be from 0 to 9");
}

// Un-premultiplies one channel: Cairo stores colour already multiplied by alpha.
std::uint8_t straight(std::uint32_t premultiplied, std::uint32_t alpha) {
  return static_cast<std::uint8_t>(std::min<std::uint32_t>(255, (premultiplied * 255 + alpha / 2) / alpha));
}

// Premultiplied native-endian 0xAARRGGBB words -> packed R,G,B(,A) bytes. RGB drops
// alpha, which for opaque frames loses nothing.
void convert_pixels(const Frame& frame, bool alpha, std::uint8_t* out) {
  for (int y = 0; y < frame.height; ++y) {
    const std::uint8_t* row = frame.pixels.data() + static_cast<std::ptrdiff_t>(y) * frame.stride;
    for (int x = 0; x < frame.width; ++x) {
      std::uint32_t word = 0;
      std::memcpy(&word, row + 4 * static_cast<std::ptrdiff_t>(x), sizeof word);
      const std::uint32_t a = word >> 24, r = (word >> 16) & 0xffU, g = (word >> 8) & 0xffU, b = word & 0xffU;
      if (!alpha) {
        out[0] = static_cast<std::uint8_t>(r);
        out[1] = static_cast<std::uint8_t>(g);
        out[2] = static_cast<std::uint8_t>(b);
        out += 3;
        continue;
      }
      if (a == 255 || a == 0) {
        out[0] = static_cast<std::uint8_t>(r);
        out[1] = static_cast<std::uint8_t>(g);
        out[2] = static_cast<std::uint8_t>(b);
      } else {
        out[0] = straight(r, a);
        out[1] = straight(g, a);
        out[2] = straight(b, a);
      }
      out[3] = static_cast<std::uint8_t>(a);
      out += 4;
    }
  }
}

/// Where libspng's bytes go: a FILE, and the system's reason when a write fails (libspng
/// itself would only say "stream error").
struct PngSink {
  std::FILE* file = nullptr;
  int error = 0;  // errno of the failed write
};

int write_to_sink(spng_ctx* /*context*/, void* user, void* data, std::size_t length) {
  auto& sink = *static_cast<PngSink*>(user);
  errno = 0;
  if (std::fwrite(data, 1, length, sink.file) == length) return 0;
  sink.error = errno != 0 ? errno : EIO;
  return SPNG_IO_ERROR;
}

// Compresses packed rows (as convert_pixels makes them) into a new file at `path`.
// Errors name `shown` (the file the user asked for, not a temporary) and, for a failed
// write, the system's reason ("No space left on device").
void encode_png_file(const std::uint8_t* image, int width, int height, const PngOptions& options, const fs::path& path,
                     const fs::path& shown) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
  if (!file) throw Error::failure("cannot create '" + shown.string() + "': " + std::strerror(errno));
  PngSink sink{file.get()};
  const auto check = [&](int status, const char* what) {
    if (status == 0) return;
    if (sink.error != 0) throw Error::failure(write_failure(shown, sink.error));
    throw Error::failure(std::string("cannot write PNG '") + shown.string() + "': " + what + ": " +
                         spng_strerror(status));
  };
  {
    const std::unique_ptr<spng_ctx, SpngDeleter> context(spng_ctx_new(SPNG_CTX_ENCODER));
    if (!context) throw Error::failure("cannot write PNG '" + shown.string() + "': out of memory");
    check(spng_set_png_stream(context.get(), write_to_sink, &sink), "set stream");
    spng_ihdr header{};
    header.width = static_cast<std::uint32_t>(width);
    header.height = static_cast<std::uint32_t>(height);
    header.bit_depth = 8;
    header.color_type = options.alpha ? SPNG_COLOR_TYPE_TRUECOLOR_ALPHA : SPNG_COLOR_TYPE_TRUECOLOR;
    check(spng_set_ihdr(context.get(), &header), "header");
    check(spng_set_option(context.get(), SPNG_IMG_COMPRESSION_LEVEL, options.compression_level), "level");
    check(spng_set_option(context.get(), SPNG_IMG_COMPRESSION_STRATEGY, Z_DEFAULT_STRATEGY), "strategy");
    check(spng_set_option(context.get(), SPNG_FILTER_CHOICE, SPNG_FILTER_CHOICE_NONE), "filter");
    check(spng_encode_image(context.get(), image, image_bytes(width, height, options), SPNG_FMT_PNG,
                            SPNG_ENCODE_FINALIZE),
          "encode");
  }
  // What the FILE still buffers fails here, or on close (e.g. a full disk over NFS).
  errno = 0;
  if (std::fflush(file.get()) != 0 || std::ferror(file.get()) != 0) throw Error::failure(write_failure(shown, errno));
  errno = 0;
  if (std::fclose(file.release()) != 0) throw Error::failure(write_failure(shown, errno));
}

void require_frame_size(const Frame& frame, int width, int height) {
  if (frame.width != width || frame.height != height)
    throw Error::failure("frame of " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                         " given to a " + std::to_string(width) + "x" + std::to_string(height) + " PNG sequence");
}

int name_digits(std::int64_t expected_frames) {
  int digits = 1;
  for (std::int64_t last = std::max<std::int64_t>(expected_frames - 1, 0); last >= 10; last /= 10) ++digits;
  return std::max(digits, 5);
}

constexpr const char* kStagingPrefix = ".linkage-frames";

fs::path staging_name(const fs::path& folder) { return folder / (kStagingPrefix + temporary_suffix()); }

/// frame_DDDDD.png with five or more digits: a name of our own sequences.
bool is_sequence_name(const std::string& name) {
  constexpr std::string_view head = "frame_", tail = ".png";
  if (name.size() < head.size() + 5 + tail.size() || name.rfind(head, 0) != 0 ||
      name.compare(name.size() - tail.size(), tail.size(), tail) != 0)
    return false;
  return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(head.size()),
                     name.end() - static_cast<std::ptrdiff_t>(tail.size()),
                     [](char c) { return c >= '0' && c <= '9'; });
}
}  // namespace

void write_png(const Frame& frame, const fs::path& target, const std::string& origin, const PngOptions& options) {
  validate_options(options);
  std::vector<std::uint8_t> image(image_bytes(frame.width, frame.height, options));
  convert_pixels(frame, options.alpha, image.data());
  AtomicFile file(target, origin, true);
  encode_png_file(image.data(), frame.width, frame.height, options, file.temp_path(), target);
  file.commit();
}

struct PngSequenceWriter::Impl {
  struct Slot {
    std::vector<std::uint8_t> image;
    std::int64_t index = 0;
  };

  fs::path folder;
  fs::path staging;
  int width = 0, height = 0;
  PngOptions options;
  int digits = 5;
  std::vector<Slot> slots;
  std::int64_t next_index = 0;
  double convert_seconds = 0;
  mutable std::mutex encode_mutex;
  double encode_seconds = 0;
  bool finished = false;
  std::unique_ptr<SlotQueue> queue;  // last: its workers stop before the slots go

  ~Impl() {
    queue.reset();
    if (finished || staging.empty()) return;
    std::error_code ec;
    fs::remove_all(staging, ec);
  }

  [[nodiscard]] std::string name(std::int64_t index) const {
    std::array<char, 40> text{};
    std::snprintf(text.data(), text.size(), "frame_%0*lld.png", digits, static_cast<long long>(index));
    return text.data();
  }

  void compress(std::size_t slot_number) {
    const Slot& slot = slots[slot_number];
    const auto start = Clock::now();
    encode_png_file(slot.image.data(), width, height, options, staging / name(slot.index), folder / name(slot.index));
    const double seconds = seconds_since(start);
    const std::lock_guard lock(encode_mutex);
    encode_seconds += seconds;
  }
};

PngSequenceWriter::PngSequenceWriter(const fs::path& folder, int width, int height, const std::string& origin,
                                     const PngOptions& options, int threads, std::int64_t expected_frames)
    : impl_(std::make_unique<Impl>()) {
  validate_options(options);
  if (width <= 0 || height <= 0)
    throw Error::invalid(origin,
                         "frame size " + std::to_string(width) + "x" + std::to_string(height) + " must be positive");
  if (threads < 1 || threads > 64)
    throw Error::invalid(origin, "PNG worker threads " + std::to_string(threads) + " must be from 1 to 64");
  require_writable_directory(folder, origin);
  remove_stale_temporaries(folder, kStagingPrefix);
  Impl& impl = *impl_;
  impl.folder = folder.empty() ? fs::path(".") : folder;
  impl.width = width;
  impl.height = height;
  impl.options = options;
  impl.digits = name_digits(expected_frames);
  // One slot per worker, one being filled, one queued: workers never wait on the caller's conversion.
  impl.slots.resize(static_cast<std::size_t>(threads) + 2);
  for (auto& slot : impl.slots) slot.image.resize(image_bytes(width, height, options));
  const fs::path staging = staging_name(impl.folder);
  std::error_code ec;
  if (!fs::create_directory(staging, ec))
    throw Error::failure(origin, "cannot create '" + staging.string() + "': " + (ec ? ec.message() : "exists"));
  impl.staging = staging;
  impl.queue =
      std::make_unique<SlotQueue>(impl.slots.size(), threads, [&impl](std::size_t slot) { impl.compress(slot); });
}

PngSequenceWriter::~PngSequenceWriter() = default;

void PngSequenceWriter::write(const Frame& frame) {
  Impl& impl = *impl_;
  if (impl.finished) throw Error::failure("PngSequenceWriter::write() after finish()");
  require_frame_size(frame, impl.width, impl.height);
  const std::size_t slot = impl.queue->acquire();
  const auto start = Clock::now();
  convert_pixels(frame, impl.options.alpha, impl.slots[slot].image.data());
  impl.slots[slot].index = impl.next_index++;
  impl.convert_seconds += seconds_since(start);
  impl.queue->submit(slot);
}

void PngSequenceWriter::finish() {
  Impl& impl = *impl_;
  if (impl.finished) return;
  impl.queue->finish();
  throw_if_interrupted();  // a signal before the sequence is whole leaves none of it
  for (std::int64_t index = 0; index < impl.next_index; ++index) {
    const std::string name = impl.name(index);
    std::error_code ec;
    fs::rename(impl.staging / name, impl.folder / name, ec);
    if (ec) throw Error::failure("cannot move '" + name + "' into '" + impl.folder.string() + "': " + ec.message());
  }
  std::error_code ec;
  fs::remove(impl.staging, ec);
  if (ec) throw Error::failure("cannot remove the staging folder '" + impl.staging.string() + "': " + ec.message());
  // Frames of an earlier, longer (or differently numbered) sequence would read as part
  // of this one: remove our own numbered names this run did not write, nothing else.
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(impl.folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!is_sequence_name(name) || !it->is_regular_file()) continue;
    const std::string digits = name.substr(6, name.size() - 10);
    const bool ours =
        static_cast<int>(digits.size()) == impl.digits && digits.size() <= 18 && std::stoll(digits) < impl.next_index;
    if (!ours) stale.push_back(it->path());
  }
  for (const fs::path& file : stale) fs::remove(file, ec);
  impl.finished = true;
}

std::string PngSequenceWriter::file_name(std::int64_t index) const { return impl_->name(index); }

PngStats PngSequenceWriter::stats() const {
  const Impl& impl = *impl_;
  PngStats stats;
  stats.frames = impl.next_index;
  stats.convert_seconds = impl.convert_seconds;
  {
    const std::lock_guard lock(impl.encode_mutex);
    stats.encode_seconds = impl.encode_seconds;
  }
  stats.wait_seconds = impl.queue->waits().producer_wait_seconds;
  return stats;
}

}  // namespace linkage
