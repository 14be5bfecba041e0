#include "pipeline/panel_data.hpp"

#include <algorithm>
#include <optional>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/name_match.hpp"
#include "integrate/series.hpp"

namespace linkage {
namespace {

std::vector<std::string> homework_names() {
  std::vector<std::string> names;
  for (const SeriesInfo& s : kSeries) names.emplace_back(s.name);
  return names;
}

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

void validate_homework_panel(const std::vector<std::string>& names) { check_list(names, homework_names()); }

PanelData homework_panel(const std::vector<std::string>& names, Simulation& sim, const Motion& motion,
                         const Params& params, const BodyState& initial, double t_end) {
  validate_homework_panel(names);
  PanelData data;
  data.t_end = t_end;
  std::vector<std::size_t> series;
  bool dynamics = false;
  for (const std::string& name : names) {
    const std::size_t i = *find_series(name);
    series.push_back(i);
    dynamics = dynamics || kSeries[i].needs_dynamics;
    data.curves.push_back({std::string(kSeries[i].label), std::string(kSeries[i].unit), {}});
  }
  const SeriesOrigin origin = SeriesOrigin::at(params, initial);
  for (const MotionSample& sample : motion.samples) {
    throw_if_interrupted();
    data.t.push_back(sample.t);
    std::optional<Dynamics> d;
    if (dynamics) d = sim.dynamics(sample.state);
    for (std::size_t c = 0; c < series.size(); ++c)
      data.curves[c].values.push_back(series_value(series[c], origin, sample.t, sample.state, d ? &*d : nullptr));
  }
  return data;
}

std::vector<MechanismColumn> mechanism_panel_columns(const std::vector<MechanismColumn>& all,
                                                     const std::vector<std::string>& names) {
  std::vector<std::string> valid;
  for (const MechanismColumn& c : all) valid.push_back(c.name);
  check_list(names, valid);
  std::vector<MechanismColumn> out;
  for (const std::string& name : names)
    out.push_back(*std::find_if(all.begin(), all.end(), [&](const MechanismColumn& c) { return c.name == name; }));
  return out;
}

PanelData mechanism_panel(const std::vector<MechanismColumn>& columns, double t_end) {
  PanelData data;
  data.t_end = t_end;
  for (const MechanismColumn& c : columns) data.curves.push_back({column_words(c), column_unit_markup(c), {}});
  return data;
}

}  // namespace linkage
