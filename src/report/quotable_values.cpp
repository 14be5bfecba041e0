#include "report/quotable_values.hpp"

#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "formulations/linearization.hpp"
#include "report/mechanism_solution.hpp"
#include "symbolic/energy.hpp"

namespace linkage {

struct QuotableValues::Modes {
  Linearization linear;
  ModalAnalysis analysis;
};

QuotableValues::QuotableValues(std::shared_ptr<const sym::System> system) : system_(std::move(system)) {
  const sym::System& s = *system_;
  for (const sym::SymbolInfo& info : s.table().all()) {
    if (info.role == sym::Role::parameter)
      add(info.symbol.get_name(), s.parameter_values().at(info.symbol), info.unit);
    else if (info.role == sym::Role::definition || info.role == sym::Role::inertia)
      add(info.symbol.get_name(), s.constants().at(info.symbol).subs(s.parameter_values()), info.unit);
  }
  // The rest by the names and values of `linkage solve --mechanism --format json`.
  const MechanismSolution solved = work_out_mechanism(system_, case_ids({3}));
  const nlohmann::json json = nlohmann::json::parse(mechanism_json(solved));
  const nlohmann::json& units = json.at("units");
  auto add_all = [&](const nlohmann::json& values) {
    for (const auto& [key, value] : values.items())
      if (value.is_number() && !entries_.contains(key))
        add(key, GiNaC::numeric(value.get<double>()), units.contains(key) ? units.at(key).get<std::string>() : "");
  };
  add_all(json.at("state"));
  add_all(json.at("derived"));
  const nlohmann::json& case3 = json.at("cases").at(0);
  add_all(case3.at("solution"));
  add_all(case3.at("recovered"));
  // The centre of mass at the start, as simulate's com columns.
  const sym::Vec2 com = sym::centre_of_mass(s), com_dot = sym::centre_of_mass_velocity(s);
  const std::pair<const char*, GiNaC::ex> centre[] = {
      {"com.x", com.x}, {"com.y", com.y}, {"com.x_dot", com_dot.x}, {"com.y_dot", com_dot.y}};
  for (const auto& [key, e] : centre)
    add(key, GiNaC::numeric(sym::evaluate(e, solved.values)), std::string(key).ends_with("_dot") ? "m/s" : "m");
  cases_[3] = {case3.at("condition_number").get<double>(), case3.at("residual").get<double>()};
  for (int c = 1; c <= 3; ++c) {
    add("cond" + std::to_string(c), c == 3 ? GiNaC::ex(cases_[3].first) : GiNaC::ex(0), "", c == 3 ? 0 : c);
    add("residual" + std::to_string(c), c == 3 ? GiNaC::ex(cases_[3].second) : GiNaC::ex(0), "", c == 3 ? 0 : c);
  }
  add_modes();
  const Mechanism& m = s.mechanism();
  for (const auto& [key, entry] : entries_) {
    keys_[key] = key;
    keys_[m.aliased(key)] = key;
  }
  for (const auto& [name, key] : keys_) names_.push_back(name);
}

void QuotableValues::add(const std::string& key, const GiNaC::ex& value, const std::string& unit, int case_number) {
  entries_.try_emplace(key, Entry{value, unit, case_number, {}});  // the first of a name wins
}

void QuotableValues::add_modes() {
  const std::size_t count = mode_count(*system_);
  add("modes.count", static_cast<int>(count), "");
  const std::string mechanism = system_->mechanism().name;
  for (std::size_t k = 0; k < count; ++k) {
    const std::string mode = "mode" + std::to_string(k + 1);
    // The mode's value when it is of a kind that has it, else the reason in one line.
    const auto quantity = [&](const std::string& name, const std::string& unit, Mode::Kind kind,
                              std::function<double(const Mode&)> of) {
      entries_.try_emplace(
          mode + "." + name,
          Entry{0, unit, 0, [=](const Modes& modes) {
                  const Mode& m = modes.analysis.modes.at(k);
                  if (m.kind == kind) return of(m);
                  const std::string is =
                      m.kind == Mode::Kind::unstable
                          ? "is unstable (it grows at " + format_significant(m.growth_rate, 3) + " 1/s)"
                      : m.kind == Mode::Kind::neutral
                          ? "is neutral (it moves freely, no stiffness)"
                          : "oscillates (omega " + format_significant(m.omega, 6) + " rad/s)";
                  throw Error::input(mode + "." + name + ": mode " + std::to_string(k + 1) + " of " + mechanism + " " +
                                     is + ": it has no " + name + "; valid: " + mode +
                                     (m.kind == Mode::Kind::unstable ? ".growth_rate" : ".omega"));
                }});
    };
    constexpr double kTwoPi = 2 * std::numbers::pi;
    quantity("omega", "rad/s", Mode::Kind::oscillation, [](const Mode& m) { return m.omega; });
    quantity("frequency_hz", "Hz", Mode::Kind::oscillation, [=](const Mode& m) { return m.omega / kTwoPi; });
    quantity("period", "s", Mode::Kind::oscillation, [=](const Mode& m) { return kTwoPi / m.omega; });
    quantity("damping_ratio", "", Mode::Kind::oscillation, [](const Mode& m) { return m.damping_ratio; });
    quantity("growth_rate", "1/s", Mode::Kind::unstable, [](const Mode& m) { return m.growth_rate; });
    for (std::size_t i = 0; i < system_->coordinates().size(); ++i)
      entries_.try_emplace(system_->coordinates()[i].coordinate.key + "_" + mode,
                           Entry{0, "", 0, [=](const Modes& modes) {
                                   return modes.analysis.modes.at(k).tree_shape[static_cast<Eigen::Index>(i)];
                                 }});
  }
}

bool QuotableValues::has(const std::string& name) const { return keys_.contains(name); }

const QuotableValues::Entry& QuotableValues::entry(const std::string& name) const {
  const auto key = keys_.find(name);
  if (key == keys_.end()) throw std::logic_error("no quotable value '" + name + "'");
  return entries_.at(key->second);
}

GiNaC::ex QuotableValues::value(const std::string& name) const {
  const Entry& e = entry(name);
  if (e.mode) {
    if (!modes_) {
      auto modes = std::make_shared<Modes>();
      modes->linear = linearize(*system_);
      modes->analysis = modal_analysis(modes->linear);
      modes_ = std::move(modes);
    }
    return GiNaC::numeric(e.mode(*modes_));
  }
  if (e.case_number == 0) return e.value;
  auto [it, fresh] = cases_.try_emplace(e.case_number);
  if (fresh) {
    const MechanismSolution solved = work_out_mechanism(system_, {static_cast<CaseId>(e.case_number)});
    const CaseNumbers& n = solved.cases.front().numbers;
    it->second = {n.condition, n.residual};
  }
  return GiNaC::numeric(keys_.at(name).starts_with("cond") ? it->second.first : it->second.second);
}

std::string QuotableValues::unit(const std::string& name) const { return entry(name).unit; }

}  // namespace linkage
