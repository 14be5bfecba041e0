// Fuzz target: the lesson reader on arbitrary bytes. Refusing the input (linkage::Error
// with exit code 2) is the only allowed failure; anything else escapes to the driver (or
// libFuzzer) as a finding.
#include "core/error.hpp"
#include "fuzz/fuzz_support.hpp"
#include "lesson/lesson.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = linkage::fuzz::write_input("lesson.toml", data, size);
  try {
    const linkage::lesson::Lesson lesson = linkage::lesson::parse_lesson(file);
    (void)lesson.artifacts();
    linkage::fuzz::note_accepted();
  } catch (const linkage::Error& e) {
    if (e.code() != linkage::ExitCode::bad_input) throw;
  }
  return 0;
}
