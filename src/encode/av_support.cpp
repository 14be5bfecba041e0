#include "encode/av_support.hpp"

extern "C" {
#include <libavutil/log.h>
}

#include <array>
#include <cstdarg>
#include <cstring>
#include <mutex>

#include "core/error.hpp"

namespace linkage::av {
namespace {
thread_local std::array<char, 512> g_last_error{};

extern "C" void quiet_log(void* object, int level, const char* format, va_list args) {
  if (level > AV_LOG_ERROR) return;
  std::array<char, 512> line{};
  int print_prefix = 1;
  av_log_format_line2(object, level, format, args, line.data(), static_cast<int>(line.size()), &print_prefix);
  // Keep the first line only, without its newline.
  line[std::strcspn(line.data(), "\r\n")] = '\0';
  if (line[0] != '\0') g_last_error = line;
}
}  // namespace

void OutputDeleter::operator()(AVFormatContext* p) const {
  if (p->pb != nullptr && (p->oformat->flags & AVFMT_NOFILE) == 0) avio_closep(&p->pb);
  avformat_free_context(p);
}

std::string error_text(int code) {
  std::array<char, AV_ERROR_MAX_STRING_SIZE> text{};
  if (av_strerror(code, text.data(), text.size()) < 0) return "FFmpeg error " + std::to_string(code);
  return text.data();
}

void install_quiet_log() {
  static std::once_flag once;
  std::call_once(once, [] { av_log_set_callback(quiet_log); });
}

std::string take_logged_error() {
  std::string text = g_last_error.data();
  g_last_error[0] = '\0';
  return text;
}

int check(int code, std::string_view what) {
  if (code >= 0) return code;
  std::string message = std::string(what) + ": " + error_text(code);
  if (const std::string logged = take_logged_error(); !logged.empty()) message += " (" + logged + ")";
  throw Error::failure(message);
}

}  // namespace linkage::av
