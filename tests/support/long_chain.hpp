#pragma once
// Long chains (issue 22, F01): a pendulum chain of N uniform rods pinned end to end, the
// first pinned to the ground, written as a mechanism file.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace linkage::test {

struct Rod {
  double length = 0.1, mass = 0.1, theta = -0.5;
};

/// The chain's file: rod i has its length and mass, its points A (towards the ground) and
/// B; joint J1 pins A of rod 1 to the ground's O, joint J<i> pins A of rod i to B of rod i-1.
/// Identical rods share the parameters l and m (with a mass and a length per rod, Case 3's
/// mass matrix has n^3 terms: each entry sums the masses beyond its rows' links).
inline std::string chain_toml(const std::vector<Rod>& rods) {
  bool identical = true;
  for (const Rod& r : rods) identical = identical && r.length == rods[0].length && r.mass == rods[0].mass;
  std::ostringstream f;
  f << "title = \"Chain of " << rods.size() << " rods\"\ngravity = \"g\"\n\n[parameters]\ng = 9.81\n";
  if (identical)
    f << "l = " << rods[0].length << "\nm = " << rods[0].mass << "\n";
  else
    for (std::size_t i = 1; i <= rods.size(); ++i)
      f << "l" << i << " = " << rods[i - 1].length << "\nm" << i << " = " << rods[i - 1].mass << "\n";
  f << "\n[ground]\npoints = { O = [0, 0] }\n";
  for (std::size_t i = 1; i <= rods.size(); ++i) {
    const std::string k = identical ? "" : std::to_string(i);
    f << "\n[[body]]\nname = \"" << i << "\"\nshape = \"rod\"\nmass = \"m" << k << "\"\nlength = \"l" << k
      << "\"\npoints = { A = [\"-l" << k << "/2\", 0], B = [\"l" << k << "/2\", 0] }\n";
  }
  for (std::size_t i = 1; i <= rods.size(); ++i)
    f << "\n[[joint]]\nname = \"J" << i << "\"\ntype = \"pin\"\nbodies = [\""
      << (i == 1 ? "ground" : std::to_string(i - 1)) << "\", \"" << i << "\"]\npoints = [\"" << (i == 1 ? "O" : "B")
      << "\", \"A\"]\n";
  f << "\n[initial]\n";
  for (std::size_t i = 1; i <= rods.size(); ++i) f << "\"" << i << "\" = { theta = " << rods[i - 1].theta << " }\n";
  return f.str();
}

/// N rods of 0.1 m and 0.1 kg, each leaning a little further than the one above.
inline std::vector<Rod> leaning_rods(int n) {
  std::vector<Rod> rods(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) rods[static_cast<std::size_t>(i)].theta = -0.5 - 0.01 * i;
  return rods;
}

/// Writes the chain of `n` leaning rods as FOLDER/chainN.toml; returns its path.
inline std::string write_chain(const std::filesystem::path& folder, int n) {
  const std::filesystem::path path = folder / ("chain" + std::to_string(n) + ".toml");
  std::ofstream(path) << chain_toml(leaning_rods(n));
  return path.string();
}

}  // namespace linkage::test
