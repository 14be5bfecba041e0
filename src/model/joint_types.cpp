#include "model/joint_types.hpp"

#include <stdexcept>

namespace linkage {

const JointTypeInfo& joint_type_info(JointType type) {
  static constexpr JointTypeInfo kPin{JointMotion::revolute, "stiffness, damping, rest_angle", true, false, false};
  static constexpr JointTypeInfo kSlider{JointMotion::prismatic, "axis", false, true, true};
  switch (type) {
    case JointType::pin:
      return kPin;
    case JointType::slider:
      return kSlider;
  }
  throw std::logic_error("joint type out of range");
}

const char* joint_type_name(JointType type) { return kJointTypeNames.at(static_cast<std::size_t>(type)); }

bool has_own_coordinate(JointMotion motion) {
  switch (motion) {
    case JointMotion::revolute:
      return false;
    case JointMotion::prismatic:
      return true;
  }
  throw std::logic_error("joint motion out of range");
}

}  // namespace linkage
