#pragma once

#include <memory>
#include <string>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/model.h>
#include <cairn/multibody/urdf_parser.h>

namespace cairn::planning::test {

/// The project's humanoid with a quaternion floating base, parsed once per process.
inline std::shared_ptr<const multibody::Model> Humanoid() {
  static const std::shared_ptr<const multibody::Model> model = [] {
    multibody::UrdfOptions options;
    options.floating_base = true;
    return std::make_shared<const multibody::Model>(
        multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf", options));
  }();
  return model;
}

/// A standing posture with slightly bent knees: pelvis at `height`, feet under the hips.
inline Eigen::VectorXd BentKneePosture(const multibody::Model& model, double height = 0.82) {
  Eigen::VectorXd q = multibody::NeutralConfiguration(model);
  q(2) = height;
  for (const char* side : {"l_", "r_"}) {
    const std::string s(side);
    q(model.joint(model.GetJointIndex(s + "hip_pitch")).idx_q) = -0.3;
    q(model.joint(model.GetJointIndex(s + "knee")).idx_q) = 0.6;
    q(model.joint(model.GetJointIndex(s + "ankle_pitch")).idx_q) = -0.3;
  }
  return q;
}

}  // namespace cairn::planning::test
