#include <cairn/multibody/joint.h>

namespace cairn::multibody {

const char* JointTypeName(JointType type) {
  switch (type) {
    case JointType::kFixed:
      return "fixed";
    case JointType::kRevolute:
      return "revolute";
    case JointType::kPrismatic:
      return "prismatic";
    case JointType::kFloating:
      return "floating";
  }
  return "unknown";
}

}  // namespace cairn::multibody
