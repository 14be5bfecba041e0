#pragma once
// A trajectory table read back to be drawn over a clip (render --compare FILE.csv): what
// `linkage simulate` writes (the homework's t,x1,y1,theta1,theta2 or a mechanism's
// t,1.x,1.y,1.theta,...), or a student's own integrator's output in the same columns.
// Positions between rows are interpolated linearly in t.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace linkage {

struct TrajectoryTable {
  std::string file;                         // as given, for messages
  std::vector<std::string> names;           // the header's, a unit suffix dropped ("theta1 (deg)": "theta1")
  std::vector<double> t;                    // s, increasing
  std::vector<std::vector<double>> values;  // [column][row]; angles given in deg converted to rad

  /// The column named `name`, if any.
  [[nodiscard]] std::optional<std::size_t> find(std::string_view name) const;
  /// Column `column` at `time` (clamped to the table's span), linear between rows.
  [[nodiscard]] double at(std::size_t column, double time) const;
};

/// Reads `file`: a header line of comma-separated names (a leading "# " as NumPy's
/// savetxt writes it is allowed; "NAME (deg)" columns are converted to rad), then rows of
/// as many numbers. Error::input naming the file, and file:line for a bad row: a column
/// of `needed` missing ("... needs t, x1, ... (`purpose`)"), a field that is not a
/// number, a NaN or infinity, t not increasing, or a table not covering start .. end s.
[[nodiscard]] TrajectoryTable read_trajectory_csv(const std::filesystem::path& file,
                                                  const std::vector<std::string>& needed, const std::string& purpose,
                                                  double start, double end);

}  // namespace linkage
