#pragma once
// A small table of results (a simulation's summary, a comparison of runs): header cells
// and rows of text, the first column naming the rows. Printers lay it out; the lesson
// cache stores it as JSON.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace linkage {

struct ResultTable {
  std::vector<std::string> headers;
  std::vector<std::vector<std::string>> rows;
};

[[nodiscard]] inline nlohmann::json to_json(const ResultTable& table) {
  return {{"headers", table.headers}, {"rows", table.rows}};
}

[[nodiscard]] inline ResultTable table_from_json(const nlohmann::json& json) {
  ResultTable t;
  t.headers = json.at("headers").get<std::vector<std::string>>();
  t.rows = json.at("rows").get<std::vector<std::vector<std::string>>>();
  return t;
}

}  // namespace linkage
