#pragma once
// A CommonMark sample with each structure a lesson may write (a heading, emphasis in a
// link, nested lists, a pipe table, fenced code, nested quotes, math spans), rendered by
// the report tests to the terminal and LaTeX and kept as written in lesson.md.
namespace linkage::test {

inline constexpr const char* kCommonMarkSample =
    "# Bodies and joints\n\n"
    "Read [the *whole* spec](spec.txt) before $\\theta_1$.\n\n"
    "- bodies\n  - block 1\n  - block 2\n- joints\n  1. pin at $O$\n  2. slider\n\n"
    "| name | value |\n| --- | ---: |\n| $\\dot\\theta_1$ | 0.1 |\n| **mass** | 2 |\n\n"
    "```\nlinkage solve --case 1\n```\n\n"
    "> A quote, with *emphasis*,\n> over two lines.\n>\n> > and a quote inside it\n";

}  // namespace linkage::test
