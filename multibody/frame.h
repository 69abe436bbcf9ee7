#pragma once

#include <string>

#include <cairn/multibody/pose.h>

namespace cairn::multibody {

/// A named frame rigidly attached to a body. Every body has a frame of its own name (X_BF = identity); extra
/// frames (sole frames, sensor frames) are added by ModelBuilder::AddFrame.
struct Frame {
  /// Frame name (unique among frames).
  std::string name;
  /// Index of the body the frame is attached to.
  int body = 0;
  /// Pose of the frame in the body frame.
  Pose X_BF;
};

}  // namespace cairn::multibody
