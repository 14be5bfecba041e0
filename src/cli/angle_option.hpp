#pragma once
// --angles rad|deg, for every command that prints or plots angles: parsed where it is
// used (parse_angle_unit, naming --angles), so a bad value is reported like any other.
#include <CLI/CLI.hpp>
#include <string>

namespace linkage::cli {

inline void add_angle_option(CLI::App* sub, std::string& angles, const std::string& what) {
  sub->add_option("--angles", angles, "Unit of " + what + ": rad or deg (default rad); inputs stay in rad")
      ->type_name("rad|deg");
}

}  // namespace linkage::cli
