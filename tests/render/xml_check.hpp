#pragma once
// A small XML well-formedness check for the SVG tests: one root element, properly
// nested and closed tags, quoted attributes without duplicates, valid entity and
// character references, comments and processing instructions. Returns "" when the
// text is well-formed, else what is wrong and where.
#include <cctype>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace linkage::test {

inline std::string xml_error(std::string_view text) {
  std::vector<std::string> open;
  std::size_t i = 0, roots = 0;
  const auto at = [&](std::size_t pos) { return " at byte " + std::to_string(pos); };
  const auto is_name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' || c == ':';
  };
  const auto read_name = [&](std::string& name) {
    const std::size_t start = i;
    while (i < text.size() && is_name_char(text[i])) ++i;
    name = std::string(text.substr(start, i - start));
    return !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) && name[0] != '-' && name[0] != '.';
  };
  const auto skip_space = [&] {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  };
  const auto check_references = [&](std::string_view chunk, std::size_t where) -> std::string {
    for (std::size_t a = chunk.find('&'); a != std::string_view::npos; a = chunk.find('&', a + 1)) {
      const std::size_t semicolon = chunk.find(';', a);
      if (semicolon == std::string_view::npos) return "unterminated reference" + at(where + a);
      const std::string_view ref = chunk.substr(a + 1, semicolon - a - 1);
      static const std::set<std::string_view> named{"amp", "lt", "gt", "quot", "apos"};
      const bool numeric = ref.size() > 1 && ref[0] == '#';
      if (!numeric && named.count(ref) == 0) return "unknown entity &" + std::string(ref) + ";" + at(where + a);
    }
    if (chunk.find('<') != std::string_view::npos) return "'<' in text or attribute" + at(where);
    return "";
  };

  while (i < text.size()) {
    if (text[i] != '<') {
      const std::size_t next = text.find('<', i);
      const std::string_view chunk = text.substr(i, next == std::string_view::npos ? std::string_view::npos : next - i);
      if (open.empty() && chunk.find_first_not_of(" \t\r\n") != std::string_view::npos)
        return "text outside the root element" + at(i);
      if (std::string e = check_references(chunk, i); !e.empty()) return e;
      if (next == std::string_view::npos) break;
      i = next;
      continue;
    }
    if (text.substr(i, 4) == "<!--") {
      const std::size_t end = text.find("-->", i + 4);
      if (end == std::string_view::npos) return "unterminated comment" + at(i);
      i = end + 3;
    } else if (text.substr(i, 2) == "<?") {
      const std::size_t end = text.find("?>", i + 2);
      if (end == std::string_view::npos) return "unterminated processing instruction" + at(i);
      i = end + 2;
    } else if (text.substr(i, 9) == "<![CDATA[") {
      const std::size_t end = text.find("]]>", i + 9);
      if (end == std::string_view::npos || open.empty()) return "bad CDATA section" + at(i);
      i = end + 3;
    } else if (text.substr(i, 2) == "<!") {
      const std::size_t end = text.find('>', i + 2);
      if (end == std::string_view::npos || !open.empty() || roots > 0) return "misplaced declaration" + at(i);
      i = end + 1;
    } else if (text.substr(i, 2) == "</") {
      i += 2;
      std::string name;
      if (!read_name(name)) return "bad closing tag" + at(i);
      skip_space();
      if (i >= text.size() || text[i] != '>') return "bad closing tag </" + name + at(i);
      if (open.empty() || open.back() != name)
        return "</" + name + "> closes " + (open.empty() ? std::string("nothing") : "<" + open.back() + ">") + at(i);
      open.pop_back();
      ++i;
    } else {
      ++i;
      std::string name;
      if (!read_name(name)) return "bad tag name" + at(i);
      if (open.empty() && roots++ > 0) return "a second root element <" + name + ">" + at(i);
      std::set<std::string> attributes;
      while (true) {
        skip_space();
        if (i >= text.size()) return "unterminated tag <" + name + ">";
        if (text[i] == '>') {
          open.push_back(name);
          ++i;
          break;
        }
        if (text.substr(i, 2) == "/>") {
          i += 2;
          break;
        }
        std::string attribute;
        if (!read_name(attribute)) return "bad attribute in <" + name + ">" + at(i);
        if (!attributes.insert(attribute).second)
          return "duplicate attribute " + attribute + " in <" + name + ">" + at(i);
        skip_space();
        if (i >= text.size() || text[i] != '=') return "attribute " + attribute + " has no value" + at(i);
        ++i;
        skip_space();
        if (i >= text.size() || (text[i] != '"' && text[i] != '\'')) return "unquoted value of " + attribute + at(i);
        const char quote = text[i];
        const std::size_t end = text.find(quote, i + 1);
        if (end == std::string_view::npos) return "unterminated value of " + attribute + at(i);
        if (std::string e = check_references(text.substr(i + 1, end - i - 1), i + 1); !e.empty()) return e;
        i = end + 1;
      }
    }
  }
  if (!open.empty()) return "<" + open.back() + "> is never closed";
  if (roots != 1) return "no root element";
  return "";
}

}  // namespace linkage::test
