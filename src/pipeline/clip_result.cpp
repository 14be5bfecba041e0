#include "pipeline/clip_result.hpp"

namespace linkage {

VideoOptions clip_video_options(const RenderSettings& s, OutputKind kind) {
  VideoOptions v;
  v.format = kind == OutputKind::gif    ? VideoFormat::gif
             : kind == OutputKind::webm ? VideoFormat::webm
                                        : VideoFormat::mp4;
  v.width = s.width;
  v.height = s.height;
  v.fps = s.fps;
  v.setting = "out";
  return v;
}

std::string run_label(const SimulationOptions& s, bool kinematic) {
  if (kinematic) return "Case " + std::to_string(s.case_id) + " \u00b7 kinematic analysis";
  std::string text = "Case " + std::to_string(s.case_id) + " \u00b7 " + std::string(info(s.integrator).name);
  if (s.case_id == 1)  // only Case 1 can drift off the pin, so only there does stabilization matter
    text += s.stabilization == Stabilization::none ? std::string(" \u00b7 no stabilization")
                                                   : " \u00b7 " + std::string(name(s.stabilization));
  return text;
}

std::string_view name(ClipStage stage) { return stage == ClipStage::simulate ? "simulate" : "render"; }

}  // namespace linkage
