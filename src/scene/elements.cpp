#include "scene/elements.hpp"

#include "core/error.hpp"
#include "core/name_match.hpp"

namespace linkage {

ElementSet ElementSet::defaults() {
  ElementSet set;
  for (const ElementInfo& info : kElements)
    if (info.shown_by_default) set.show(info.element);
  return set;
}

ElementSet ElementSet::all() {
  ElementSet set;
  for (const ElementInfo& info : kElements) set.show(info.element);
  return set;
}

std::string_view name(Element e) { return kElements[static_cast<std::size_t>(e)].name; }

std::string element_name_list() {
  std::string list;
  for (const ElementInfo& info : kElements) {
    if (!list.empty()) list += ", ";
    list += info.name;
  }
  return list;
}

Element parse_element(std::string_view text, const std::string& origin) {
  std::vector<std::string> names;
  for (const ElementInfo& info : kElements) {
    if (info.name == text) return info.element;
    names.emplace_back(info.name);
  }
  for (const auto& [alias, element] : kElementAliases)
    if (alias == text) return element;
  throw Error::invalid(origin, "'" + std::string(text) + "' is not an element" + did_you_mean(text, names) +
                                   "; valid: " + element_name_list());
}

namespace {
// Calls `apply` on each name of a comma-separated list; empty names are errors too.
template <typename Apply>
void for_each_name(const std::string& list, const std::string& origin, Apply apply) {
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    const std::string_view item =
        std::string_view(list).substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    apply(parse_element(item, origin));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
}
}  // namespace

void apply_show_hide(ElementSet& set, const std::vector<std::string>& show, const std::vector<std::string>& hide) {
  for (const std::string& list : show) for_each_name(list, "show", [&](Element e) { set.show(e); });
  for (const std::string& list : hide) for_each_name(list, "hide", [&](Element e) { set.hide(e); });
}

}  // namespace linkage
