#pragma once
// Every mode of small vibration in one still (`linkage render --modes-sheet`, issue 26): a
// panel per mode, the mechanism at the equilibrium (faint) and displaced to +A (solid) and
// -A (outlined) along the mode's shape, loops closed at each, the path of its points
// between them as trails; one camera for every panel, so amplitudes compare. A mode that
// does not oscillate gets a panel of the equilibrium alone that says so. Each panel is a
// mechanism frame from the scene and its painter, as a clip's.
#include <cairo.h>

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "formulations/linearization.hpp"
#include "pipeline/mechanism_clip.hpp"
#include "render/camera.hpp"
#include "symbolic/system.hpp"

namespace linkage {

struct ModesSheetPanel {
  int number = 0;  // from 1, as `linkage modes` numbers them
  Mode::Kind kind = Mode::Kind::oscillation;
  Eigen::VectorXd plus, minus;           // tree coordinates at +A and -A, loops closed (empty: no motion drawn)
  std::string heading;                   // "mode 1 · 0.819 Hz (5.15 rad/s)"
  std::string shape;                     // "2.theta : 3.theta = 0.707 : 1", or what the mode does instead
  MechanismMotion motion;                // -A to +A (the equilibrium alone when the mode does not oscillate)
  std::vector<double> equilibrium_pose;  // per body x, y, theta at the equilibrium
  MechanismDrawList list;                // the panel's drawing: +A, ghosts of -A and the equilibrium, the trails
};

class ModesSheet {
 public:
  /// The sheet of `modes` at `amplitude` (the largest tree coordinate's displacement, as
  /// --mode's), drawn with `clip`'s settings (size, theme, title, elements shown; kept by
  /// reference); Error::invalid("amplitude", ...) for an amplitude not finite and > 0,
  /// ("size", ...) for a size with no room for the panels.
  ModesSheet(const sym::System& system, const Linearization& linear, const ModalAnalysis& modes, double amplitude,
             const MechanismClip& clip);
  ModesSheet(const ModesSheet&) = delete;
  ModesSheet& operator=(const ModesSheet&) = delete;

  [[nodiscard]] const std::vector<ModesSheetPanel>& panels() const { return panels_; }
  /// The line under the title: the amplitude and what is drawn how.
  [[nodiscard]] const std::string& subtitle() const { return subtitle_; }
  /// The camera of every panel (the same view and scale, the panel's picture its frame).
  [[nodiscard]] const Camera& camera() const { return camera_; }
  /// The grid: 1 to 3 panels a row, as many rows as needed.
  [[nodiscard]] int columns() const { return columns_; }
  [[nodiscard]] int rows() const { return rows_; }

  /// The whole sheet onto `cr` at the origin, the settings' width x height.
  void paint(cairo_t* cr) const;
  /// Writes it to `out` (.png, .svg or .pdf) atomically; `origin` names the flag or key in errors.
  void write(const std::filesystem::path& out, const std::string& origin) const;

 private:
  struct Cell;  // a panel's picture and caption band, px
  [[nodiscard]] Cell cell(std::size_t index) const;

  const MechanismClip& clip_;
  std::vector<ModesSheetPanel> panels_;
  std::string subtitle_;
  int columns_ = 1, rows_ = 1;
  double top_ = 0, caption_ = 0;  // px: the title band's and each caption band's height
  Camera camera_;
};

/// What a sheet does not combine with, as render options and lesson keys name them: a
/// motion of its own (a mode's, overlaid runs, a time) or what only a motion draws.
inline constexpr std::array<std::string_view, 11> kModesSheetConflicts{
    "mode", "nonlinear", "ensemble", "compare", "at", "panel", "trail", "trail_length", "points", "view", "camera"};

/// The sheet of `system`'s modes about its equilibrium (linearize, modal_analysis) written
/// to `out`; linearize's Error::input when it has none (no degree of freedom, no equilibrium).
void produce_modes_sheet(const sym::System& system, const MechanismClip& clip, double amplitude,
                         const std::filesystem::path& out, const std::string& origin);

}  // namespace linkage
