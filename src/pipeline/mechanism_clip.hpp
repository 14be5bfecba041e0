#pragma once
// Any mechanism's clip, the homework's among them (two-blocks.toml): simulate
// (MechanismSimulation), build each frame's drawing (scene/mechanism_scene), paint it
// (render/mechanism_painter) and encode it: an MP4, a numbered PNG sequence, or one still
// (PNG, SVG or PDF) at settings.at. Outputs appear whole or not at all. Uses settings' size, fps,
// duration, speed, at, title, shown elements, arrow scales and camera (by default it fits
// the whole motion of a grounded mechanism and follows a floating one's centroid).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "integrate/simulation_options.hpp"
#include "pipeline/clip_result.hpp"
#include "pipeline/mode_motion.hpp"
#include "pipeline/trajectory_csv.hpp"
#include "render/mechanism_forces.hpp"
#include "render/paint_layer.hpp"
#include "render/panel.hpp"
#include "render/settings.hpp"
#include "render/theme.hpp"
#include "scene/mechanism_scene.hpp"
#include "symbolic/system.hpp"

namespace linkage {

/// A second run drawn over the main one in a second colour (--compare): its own system
/// (other parameters) or the clip's, its own initial state and simulation options.
struct MechanismRun {
  const sym::System* system = nullptr;  // null: the clip's
  GiNaC::exmap initial;
  SimulationOptions simulation;
  std::string label;                               // the legend row: what differs, "integrator=rk4"
  std::shared_ptr<const TrajectoryTable> table{};  // a trajectory file's run instead of a simulation
  bool centred = false;  // another mechanism: drawn about the main run's centroid when that is followed
  bool aliased = false;  // the table's columns go by the file's [aliases] (x1 for 1.x)
};

/// The compared run of NAME=VALUE items (`linkage render --compare`, a lesson's compare):
/// integrator=NAME, case=N, or settings of `mechanism`'s parameters and initial
/// coordinates, which give the run its own system, kept in `system` (it must outlive the
/// run; without settings the run is the clip's, its initial state the caller's to fill).
/// Error::invalid("compare", ...) naming the item; `flag` spells compare in the message.
[[nodiscard]] MechanismRun mechanism_compared_run(const std::vector<std::string>& items, const Mechanism& mechanism,
                                                  const SimulationOptions& simulation, const std::string& flag,
                                                  std::unique_ptr<sym::System>& system);

/// The columns a trajectory file needs to draw the bodies of `geometry`: t, then per body
/// NAME.x, NAME.y and NAME.theta (no theta for a point mass); with `aliases`, by the names
/// its [aliases] give them (two-blocks: x1, y1, theta1, ...).
[[nodiscard]] std::vector<std::string> mechanism_pose_columns(const MechanismGeometry& geometry,
                                                              const Mechanism* aliases = nullptr);
/// The columns from which a trajectory file's poses follow when it lacks some body's: t and
/// the generalized coordinates of `system` (two-blocks: t, x1, y1, theta1, theta2 by its aliases).
[[nodiscard]] std::vector<std::string> mechanism_coordinate_columns(const sym::System& system,
                                                                    const Mechanism* aliases = nullptr);
/// The poses of `table` at `times`, interpolated linearly: each body's from its own columns
/// (mechanism_pose_columns), else, with `system`, from the generalized coordinates'.
[[nodiscard]] MechanismMotion table_motion(const TrajectoryTable& table, const MechanismGeometry& geometry,
                                           const std::vector<double>& times, const Mechanism* aliases = nullptr,
                                           const sym::System* system = nullptr);

struct MechanismClip {
  SimulationOptions simulation;
  RenderSettings settings;
  Theme theme;
  std::vector<std::string> trails;              // "BODY.POINT": paths over the last trail_seconds
  double trail_seconds = 2.0;                   // > 0
  bool trail_cycle = false;                     // trail_seconds is the driver's period: drawn unfaded
  std::vector<std::string> points;              // "BODY.POINT": their velocity and acceleration arrows
  std::optional<std::filesystem::path> out;     // .mp4, .gif, .webm, or a still: .png, .svg, .pdf
  std::optional<std::filesystem::path> frames;  // a numbered PNG sequence's folder
  int ensemble = 0;                             // 0, or 2..200 runs (the main one among them)
  double spread = 1e-6;                         // the ensemble's largest offset of the first coordinate
  std::optional<MechanismRun> compare;
  /// The system's case as derive_case gives it, when the caller derived it already (to
  /// check the initial state): the runs of that case reuse it rather than derive again.
  std::optional<CaseSystem> derived;
  /// A motion drawn instead of the simulation's (a mode's linear motion, Case 3's state):
  /// samples, trails, arrows and the panel come from it; the HUD shows no energy balance.
  PrescribedState prescribed{};
  std::string hud_run;  // the HUD's run row instead of the case and integrator ("mode 1 · linear, 0.819 Hz")
  /// A page's worked equations of the case as HTML (encode's PageText::equations), made by the caller.
  std::string equations_html;

  [[nodiscard]] bool is_still() const;
  /// Checks the outputs, settings, simulation and trails before any work: Error::invalid
  /// about "out", "frames", "size", ...; Error::input naming --trail for a bad point.
  void validate(const sym::System& system) const;
};

/// `clip` made to draw `motion` (a mode's, mode_motion): its prescribed states (none for the
/// nonlinear one) and the HUD's run row. (Its caption, the default, goes into the request.)
void show_mode(MechanismClip& clip, const ModeMotion& motion);

/// One period of the drivers' motion, s: 2 pi/|omega| when every driver turns a pin at a
/// constant rate omega (theta0 + omega*t) with one period; else Error::invalid("trail_length")
/// naming the motion and why (`--trail-length cycle`).
[[nodiscard]] double driver_cycle_seconds(const sym::System& system);
/// A trail's length as `--trail-length` gives it: empty, the default 2 s; seconds; or "cycle".
[[nodiscard]] double trail_seconds_of(const sym::System& system, const std::string& trail_length);

/// The camera `settings` ask for (camera_chosen), else fit for a grounded mechanism and
/// follow for a floating one.
[[nodiscard]] CameraMode mechanism_camera_mode(const RenderSettings& settings, const MechanismGeometry& geometry);
/// The camera of the first frame for `mode`: follow, about the centroid at the zoom that
/// holds the widest reach (each frame re-centres it on scene.centroid(k)); fixed,
/// settings.view; fit, the whole motion and its arrows with a band on top for the title
/// (a clip keeps a strip beside it for the legend when some frame has no clear corner).
[[nodiscard]] Camera mechanism_camera(const MechanismScene& scene, const RenderSettings& settings, CameraMode mode);

/// `motion`'s poses as `linkage simulate` writes them by default: t, then each body's x, y
/// and theta (mechanism_pose_columns, by the names the mechanism's tables use), rad, one
/// row per sample. What a page offers for download, and what `render --compare` reads back.
[[nodiscard]] std::string motion_csv(const sym::System& system, const MechanismMotion& motion);

/// The motion at `frame_times` (increasing) from one run; with `trail_steps` > 1 also the
/// poses at that many steps per frame interval or more (trail_times, the frame times among
/// them), more where the bodies turn fast (no body more than 3 degrees between two at the
/// interval's starting rates doubled, up to 256 a frame), so a trail stays smooth however
/// fast a point moves between frames. Adds the run's
/// samples, seconds and warning to `result`. With `panel`, also the panel's columns at
/// every frame time and between them, at least 4000 samples over the clip (settings.panel,
/// checked by validate()). `derived`: the system's case, used when it is the one `options`
/// runs (MechanismClip::derived). `accelerations`: every sample with its kinematics
/// (the acceleration arrows'). Records each frame's energy balance (MechanismMotion), except
/// for a `prescribed` motion (MechanismClip::prescribed), which replaces the simulation's states.
MechanismMotion sample_mechanism_motion(const sym::System& system, const GiNaC::exmap& initial,
                                        const SimulationOptions& options, const std::vector<double>& frame_times,
                                        int trail_steps, ClipResult& result, const ClipProgress& progress = {},
                                        const std::vector<std::string>& panel_names = {}, PanelData* panel = nullptr,
                                        const std::optional<CaseSystem>& derived = {}, bool accelerations = false,
                                        const PrescribedState& prescribed = {});

/// The ensemble's other runs: `initial` with the first generalized coordinate moved by
/// spread k / (n - 1), k = 1 .. n - 1 (evenly spaced, no randomness), loops closed again.
std::vector<GiNaC::exmap> ensemble_states(const sym::System& system, const GiNaC::exmap& initial, int n, double spread);

/// The other runs' motions at `times`, each as sample_mechanism_motion gives it without
/// trails: the ensemble's (ensemble_states), then the compared run's (its duration that
/// of `options`). Adds their samples and the compared run's warnings to `result`.
std::vector<MechanismMotion> overlay_motions(const sym::System& system, const GiNaC::exmap& initial,
                                             const MechanismClip& clip, const SimulationOptions& options,
                                             const std::vector<double>& times, ClipResult& result);

/// A clip's motion drawn frame by frame as produce_mechanism_clip draws it (the motion and
/// overlays sampled, each frame's MechanismScene painted by the mechanism painter inside
/// the frame's layout), without encoding: produce_mechanism_clip encodes these frames,
/// `linkage bench render` times them. Samples the motion when made (adding its figures to
/// `result`); polls for Ctrl-C.
class MechanismClipFrames {
 public:
  MechanismClipFrames(const sym::System& system, const GiNaC::exmap& initial, const MechanismClip& clip,
                      ClipResult& result, const ClipProgress& progress = {});
  ~MechanismClipFrames();
  MechanismClipFrames(const MechanismClipFrames&) = delete;
  MechanismClipFrames& operator=(const MechanismClipFrames&) = delete;

  /// The clip's frame count (settings.frame_count()).
  [[nodiscard]] long count() const;
  /// Frame k (0 .. count() - 1) into `frame`, of the settings' size.
  void draw(std::size_t k, Frame& frame);
  /// Frame k's painting, each step onto its layer's context (render/paint_layer.hpp), the
  /// panel, equations and caption onto PaintLayer::around's: composited, frame k.
  void draw_layers(std::size_t k, const LayerContexts& at);
  /// Frame k's time, s; where in the frame the motion is drawn (the arrows' pixels are in it).
  [[nodiscard]] double time(std::size_t k) const;
  [[nodiscard]] Rect scene_rect() const;
  /// The drawing's figures so far (frames, trail points, seconds).
  [[nodiscard]] const RenderStats& stats() const;
  /// The camera of frame k (a following one is centred on the centroid at k; the grid
  /// streaks from where frame k - 1's put it), and the draw list of the frame drawn last.
  [[nodiscard]] Camera camera(std::size_t k) const;
  [[nodiscard]] const MechanismDrawList& list() const;
  /// Where the frame drawn last put its legend, scale bar and labels.
  [[nodiscard]] const ForceLayout& layout() const;
  /// The motion drawn: one sample per frame.
  [[nodiscard]] const MechanismMotion& motion() const;
  /// The panel's data as plotted, and where its plots put it in a frame (empty without one).
  [[nodiscard]] const PanelData& panel() const;
  [[nodiscard]] std::vector<PanelPart> panel_parts() const;

 private:
  struct Drawn;
  std::unique_ptr<Drawn> drawn_;
};

/// Produces every output of `clip` for `system` from `initial` (generalized coordinates
/// and rates with every loop closed, sym::checked_initial_state). Polls for Ctrl-C.
ClipResult produce_mechanism_clip(const sym::System& system, const GiNaC::exmap& initial, const MechanismClip& clip,
                                  const ClipProgress& progress = {});

}  // namespace linkage
