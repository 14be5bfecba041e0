#pragma once
// Running a validated lesson: prints each step to the terminal, writes every artifact
// and the lesson document (lesson.md) into the output folder, reuses artifacts whose
// inputs have not changed, and asks exercises when run step by step.
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "lesson/lesson.hpp"
#include "pipeline/clip_request.hpp"
#include "report/document_writer.hpp"

namespace linkage::lesson {

enum class Quality { draft, final };

/// Frame size and rate of clips and stills at --quality draft (final keeps the step's).
inline constexpr int kDraftWidth = 480, kDraftHeight = 270, kDraftFps = 15;

struct RunnerOptions {
  std::filesystem::path out_dir;  // created with its parents if missing
  bool interactive = false;       // --step: pause steps wait, exercises ask
  Quality quality = Quality::draft;
  DocumentFormat format = DocumentFormat::text;  // of the terminal output
  std::vector<bool> selected;                    // per step (--only); empty: every step
  bool force = false;                            // make everything, cached or not
  std::size_t width = 80;                        // terminal columns for text
  Style style = Style::unicode;
  std::filesystem::path assets;  // theme folder for render steps (empty: built-in palettes)
  bool pdf = false;              // --pdf: compile lesson.tex to lesson.pdf with pdflatex
};

struct RunSummary {
  int steps_run = 0;
  int made = 0;                    // steps that wrote their artifacts
  int reused = 0;                  // steps whose artifacts were reused
  std::filesystem::path document;  // lesson.md; empty when --only ran part of the lesson
  std::filesystem::path handout;   // lesson.tex, likewise
  std::filesystem::path pdf;       // lesson.pdf, with --pdf
};

/// Runs the selected steps. Terminal output goes to `out`, status lines (what was made
/// or reused) to `status`; --step answers are read from `in`.
RunSummary run_lesson(const Lesson& lesson, const RunnerOptions& options, std::istream& in, std::ostream& out,
                      std::ostream& status);

/// The hash a step's artifacts are cached under: its options, its inputs, the quality
/// (render steps only) and the program version.
[[nodiscard]] std::string step_hash(const Step& step, Quality quality);

/// The clip a render step makes at `quality` into `out_dir`: the step's inputs, run and
/// picture; at draft quality 480x270 and at most 15 fps. `mode`: the motion drawn instead
/// of the run's (mode_motion), its caption the default.
[[nodiscard]] CheckedMechanismClip render_clip(const RenderStep& render, Quality quality,
                                               const std::filesystem::path& out_dir,
                                               const std::filesystem::path& assets = {},
                                               const ModeMotion* mode = nullptr);

}  // namespace linkage::lesson
