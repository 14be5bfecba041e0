#pragma once
// Text put into HTML or XML (the page's title, the equations' MathML and Markdown).
#include <string>
#include <string_view>

namespace linkage {

/// `text` with & < > " ' as character references: safe in an element or an attribute of
/// HTML or XML.
[[nodiscard]] std::string escape_markup(std::string_view text);

}  // namespace linkage
