#include <cairn/multibody/geometry.h>

namespace cairn::multibody {

const char* GeometryTypeName(GeometryType type) {
  switch (type) {
    case GeometryType::kBox:
      return "box";
    case GeometryType::kSphere:
      return "sphere";
    case GeometryType::kCylinder:
      return "cylinder";
    case GeometryType::kCapsule:
      return "capsule";
    case GeometryType::kMesh:
      return "mesh";
  }
  return "unknown";
}

}  // namespace cairn::multibody
