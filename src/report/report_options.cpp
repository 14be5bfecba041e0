#include "report/report_options.hpp"

#include <langinfo.h>

#include <clocale>
#include <cstring>
#include <string>

namespace linkage {

Style text_style_from_locale() {
  const char* current = std::setlocale(LC_CTYPE, nullptr);
  const std::string previous = current != nullptr ? current : "C";
  Style style = Style::ascii;
  if (std::setlocale(LC_CTYPE, "") != nullptr) {
    const char* codeset = nl_langinfo(CODESET);
    if (codeset != nullptr && (std::strcmp(codeset, "UTF-8") == 0 || std::strcmp(codeset, "utf8") == 0))
      style = Style::unicode;
  }
  std::setlocale(LC_CTYPE, previous.c_str());
  return style;
}

}  // namespace linkage
