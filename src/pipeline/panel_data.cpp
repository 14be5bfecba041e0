#include "pipeline/panel_data.hpp"

#include <algorithm>

#include "columns/expression_column.hpp"
#include "core/error.hpp"
#include "core/name_match.hpp"

namespace linkage {
namespace {

void check_list(const std::vector<std::string>& names, const std::vector<std::string>& valid) {
  if (names.empty()) throw Error::invalid("panel", "empty list; valid: " + join_names(valid));
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::find(valid.begin(), valid.end(), names[i]) == valid.end())
      throw Error::invalid("panel", "'" + names[i] + "' is not a quantity to plot" + did_you_mean(names[i], valid) +
                                        "; valid: " + join_names(valid));
    if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i), names[i]) !=
        names.begin() + static_cast<std::ptrdiff_t>(i))
      throw Error::invalid("panel", "'" + names[i] + "' is named twice");
  }
}

}  // namespace

std::vector<MechanismColumn> mechanism_panel_columns(const std::vector<MechanismColumn>& all,
                                                     const std::vector<std::string>& names, const sym::System* system) {
  std::vector<MechanismColumn> defined = all;  // with the definitions so far: a later one may use them
  std::vector<std::string> valid, named;
  for (const MechanismColumn& c : all) valid.push_back(c.name);
  for (const std::string& name : names) {
    if (!defines_column(name)) {
      named.push_back(name);
      continue;
    }
    defined.push_back(expression_column(defined, system, name, "--panel"));
    valid.push_back(defined.back().name);
    named.push_back(defined.back().name);
  }
  check_list(named, valid);
  std::vector<MechanismColumn> out;
  for (const std::string& name : named)
    out.push_back(
        *std::find_if(defined.begin(), defined.end(), [&](const MechanismColumn& c) { return c.name == name; }));
  return out;
}

PanelData mechanism_panel(const std::vector<MechanismColumn>& columns, double t_end) {
  PanelData data;
  data.t_end = t_end;
  for (const MechanismColumn& c : columns) data.curves.push_back({column_words(c), column_unit_markup(c), {}});
  return data;
}

}  // namespace linkage
