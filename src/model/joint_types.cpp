#include "model/joint_types.hpp"

#include <stdexcept>
#include <string_view>
#include <vector>

namespace linkage {

std::string joint_types_with(bool JointTypeInfo::*takes) {
  std::vector<std::string> names;
  for (const JointTypeInfo& info : kJointTypes)
    if (info.*takes)  // "pins", "rolling joints"
      names.push_back(std::string(info.name) + (std::string_view(info.name).ends_with("ing") ? " joints" : "s"));
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return out;
}

std::string drivable_joint_types() {
  std::vector<std::string> names;
  for (const JointTypeInfo& info : kJointTypes)
    if (drivable(info.type)) names.emplace_back(info.name);
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return out;
}

bool has_own_coordinate(JointMotion motion) {
  switch (motion) {
    case JointMotion::revolute:
      return false;
    case JointMotion::prismatic:
    case JointMotion::slotted:
      return true;
    case JointMotion::fixed:
    case JointMotion::rolling:
    case JointMotion::loop:
      return false;
  }
  throw std::logic_error("joint motion out of range");
}

bool carries_body(JointMotion motion) {
  switch (motion) {
    case JointMotion::revolute:
    case JointMotion::prismatic:
    case JointMotion::fixed:
    case JointMotion::rolling:
    case JointMotion::slotted:
      return true;
    case JointMotion::loop:
      return false;
  }
  throw std::logic_error("joint motion out of range");
}

}  // namespace linkage
