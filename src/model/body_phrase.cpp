#include "model/body_phrase.hpp"

#include <cctype>

namespace linkage {
namespace {

// Exhaustive: a shape added to the enum must name its noun here.
const char* shape_noun(Shape shape) {
  switch (shape) {
    case Shape::rectangle:
      return "block";
    case Shape::rod:
      return "rod";
    case Shape::disc:
      return "disc";
    case Shape::ring:
      return "ring";
    case Shape::point:
      return "mass";
  }
  return "body";
}

}  // namespace

std::string body_phrase(const Body& body) {
  bool numeric = !body.name.empty();
  for (char c : body.name) numeric = numeric && std::isdigit(static_cast<unsigned char>(c)) != 0;
  return numeric ? std::string(shape_noun(body.shape)) + " " + body.name : body.name;
}

}  // namespace linkage
