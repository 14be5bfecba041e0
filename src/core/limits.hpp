#pragma once
// Bounds on what user text may ask of the program's readers.

namespace linkage {

/// The deepest nesting any reader of user text accepts: braces, \sqrt, ^ and _ in LaTeX
/// math; parentheses, calls, signs and powers in expressions; list levels in Markdown.
/// Far more than any real formula needs, and small enough that a recursive reader
/// cannot exhaust the stack however hostile the text.
inline constexpr int kMaxNesting = 64;

/// One level of a recursive reader for as long as it lives: counts up `depth` and back
/// down, so an exception unwinds the count with the stack.
class NestingLevel {
 public:
  explicit NestingLevel(int& depth) : depth_(depth) { ++depth_; }
  NestingLevel(const NestingLevel&) = delete;
  NestingLevel& operator=(const NestingLevel&) = delete;
  ~NestingLevel() { --depth_; }
  [[nodiscard]] bool too_deep() const { return depth_ > kMaxNesting; }

 private:
  int& depth_;
};

}  // namespace linkage
