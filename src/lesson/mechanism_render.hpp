#pragma once
// A render step's mechanism (mechanism = "NAME|FILE", set, trail, ensemble, compare), checked when the
// lesson is read and built again when the step runs.
#include <memory>
#include <string>

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

}  // namespace linkage::lesson
