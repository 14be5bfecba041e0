#include "model/mechanism.hpp"

namespace linkage {

const Body* Mechanism::find_body(const std::string& body_name) const {
  for (const Body& body : bodies)
    if (body.name == body_name) return &body;
  return nullptr;
}

std::string Mechanism::aliased(const std::string& key) const {
  for (const Alias& a : aliases)
    if (a.key == key) return a.name;
  return key;
}

std::string Mechanism::unaliased(const std::string& alias) const {
  for (const Alias& a : aliases)
    if (a.name == alias) return a.key;
  return alias;
}
std::string Mechanism::named(const std::string& key) const { return speaks_aliases ? aliased(key) : key; }

int Mechanism::body_index(const std::string& body_name) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == body_name) return static_cast<int>(i);
  return -1;
}

const Joint* Mechanism::find_joint(const std::string& joint_name) const {
  for (const Joint& joint : joints)
    if (joint.name == joint_name) return &joint;
  return nullptr;
}

std::string where(const SourcePos& pos) {
  if (pos.file.empty()) return {};
  if (pos.line <= 0) return pos.file + ": ";
  return pos.file + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column) + ": ";
}

}  // namespace linkage
