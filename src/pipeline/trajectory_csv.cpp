#include "pipeline/trajectory_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <numbers>
#include <string_view>

#include "core/error.hpp"
#include "core/name_match.hpp"
#include "core/number_format.hpp"

namespace linkage {
namespace {

// Pieces joined (report's concat is not among this module's dependencies).
[[maybe_unused]] std::string concat(std::initializer_list<std::string_view> pieces) {
  std::string out;
  for (const std::string_view piece : pieces) out.append(piece);
  return out;
}

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trimmed(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

}  // namespace

std::optional<std::size_t> TrajectoryTable::find(std::string_view name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return static_cast<std::size_t>(it - names.begin());
}

double TrajectoryTable::at(std::size_t column, double time) const {
  const std::vector<double>& v = values[column];
  if (time <= t.front()) return v.front();
  if (time >= t.back()) return v.back();
  const auto next = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin());
  const std::size_t before = next - 1;
  const double f = (time - t[before]) / (t[next] - t[before]);
  return v[before] + f * (v[next] - v[before]);
}

TrajectoryTable read_trajectory_csv(const std::filesystem::path& file, const std::vector<std::string>& needed,
                                    const std::string& purpose, double start, double end) {
  TrajectoryTable table;
  table.file = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error::input(table.file + ": cannot read the trajectory file (no such file, or not readable)");
  const auto where = [&](long line) { return table.file + ":" + std::to_string(line); };
  std::string line;
  long number = 0;
  // The header: the first line that is not blank.
  while (std::getline(in, line)) {
    ++number;
    if (!trimmed(line).empty()) break;
  }
  std::string_view header = trimmed(line);
  if (header.starts_with('#')) header = trimmed(header.substr(1));
  if (header.empty())
    throw Error::input(table.file + ": empty; expected a header line such as " + join_names(needed, ""));
  std::vector<double> factor;
  for (const std::string_view field : fields(header)) {
    std::string name(field);
    double to_si = 1;
    if (const auto open = name.find(" ("); open != std::string::npos && name.ends_with(')')) {
      const std::string unit = name.substr(open + 2, name.size() - open - 3);
      if (unit == "deg") to_si = std::numbers::pi / 180;
      name = name.substr(0, open);
    }
    table.names.push_back(name);
    factor.push_back(to_si);
  }
  for (const std::string& name : needed)
    if (!table.find(name))
      throw Error::input(
          concat({table.file, ": no column '", name, "'; ", purpose, " needs the columns ", join_names(needed, ""),
                  " (as linkage simulate writes them); the header has ", join_names(table.names, "")}));
  const std::size_t t_column = *table.find("t");
  table.values.assign(table.names.size(), {});
  std::vector<long> lines;
  while (std::getline(in, line)) {
    ++number;
    if (trimmed(line).empty()) continue;
    const std::vector<std::string_view> row = fields(line);
    if (row.size() != table.names.size())
      throw Error::input(concat({where(number), ": ", std::to_string(row.size()), " fields; the header has ",
                                 std::to_string(table.names.size())}));
    for (std::size_t c = 0; c < row.size(); ++c) {
      double value = 0;
      const std::string_view text = row[c];
      const std::string_view digits = text.starts_with('+') ? text.substr(1) : text;
      const auto [stop, error] = text.empty() ? std::from_chars_result{nullptr, std::errc::invalid_argument}
                                              : std::from_chars(digits.data(), digits.data() + digits.size(), value);
      if (error != std::errc{} || stop != digits.data() + digits.size())
        throw Error::input(
            concat({where(number), ": ", table.names[c], " = '", std::string(text), "' is not a number"}));
      if (!std::isfinite(value))
        throw Error::input(concat(
            {where(number), ": ", table.names[c], " is ", std::string(text), "; every value must be a finite number"}));
      table.values[c].push_back(value * factor[c]);
    }
    const std::vector<double>& t = table.values[t_column];
    if (t.size() > 1 && !(t.back() > t[t.size() - 2]))
      throw Error::input(
          concat({where(number), ": t = ", format_significant(t.back(), 6),
                  " s does not increase (the row before has t = ", format_significant(t[t.size() - 2], 6), " s)"}));
    lines.push_back(number);
  }
  table.t = table.values[t_column];
  if (table.t.empty()) throw Error::input(table.file + ": has a header but no rows");
  if (table.t.front() > start + 1e-9)
    throw Error::input(concat({where(lines.front()), ": the first row has t = ", format_significant(table.t.front(), 6),
                               " s, after the clip's start at ", format_significant(start, 6),
                               " s; the trajectory must cover the clip"}));
  if (table.t.back() < end - 1e-9)
    throw Error::input(concat({where(lines.back()), ": the last row has t = ", format_significant(table.t.back(), 6),
                               " s, before the clip's end at ", format_significant(end, 6),
                               " s; simulate at least that long, or render a shorter --duration"}));
  return table;
}

}  // namespace linkage
