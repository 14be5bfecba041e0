#pragma once
// A render step's mechanism (mechanism = "NAME|FILE", set, trail, ensemble, compare), checked when the
// lesson is read and built again when the step runs; the equations a step shows.
#include <memory>
#include <string>
#include <vector>

#include "lesson/lesson.hpp"
#include "pipeline/mechanism_clip.hpp"

namespace linkage::lesson {

/// Its settings applied (errors name `origin`), its loops closed, its clip (its output
/// named as the step names it) validated, trails included.
struct MechanismRender {
  std::unique_ptr<sym::System> system;
  std::unique_ptr<sym::System> compared;  // the compared run's, when its settings differ
  GiNaC::exmap state;
  MechanismClip clip;
};
[[nodiscard]] MechanismRender mechanism_render(const RenderStep& render, const std::string& origin);

/// Case `case_id`'s equations as `linkage solve` prints them, for a step that shows them.
[[nodiscard]] EquationsText render_equations(const sym::System& system, int case_id);

}  // namespace linkage::lesson
