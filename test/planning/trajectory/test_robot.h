#pragma once

#include <memory>
#include <string>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/model.h>
#include <cairn/multibody/urdf_parser.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include "test_paths.h"

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

/// A found plan of `steps` straight steps of `length` m along x (right foot first), feet 0.2 m apart, with the
/// timing t_ds = 0.2 s, t_sw = 0.6 s; the last step brings the feet together.
inline FootstepPlan StraightPlan(int steps, double length) {
  FootstepPlan plan;
  plan.found = true;
  plan.start.left = {0.0, 0.1, 0.0, 0.0};
  plan.start.right = {0.0, -0.1, 0.0, 0.0};
  plan.first_side = FootSide::kRight;
  double x_left = 0.0, x_right = 0.0;
  for (int k = 0; k < steps; ++k) {
    PlannedStep step;
    step.side = k % 2 == 0 ? FootSide::kRight : FootSide::kLeft;
    double& x = step.side == FootSide::kLeft ? x_left : x_right;
    const double other = step.side == FootSide::kLeft ? x_right : x_left;
    x = k + 1 == steps ? other : other + length;
    step.pose = {x, step.side == FootSide::kLeft ? 0.1 : -0.1, 0.0, 0.0};
    step.transition.feasible = true;
    step.transition.parameters = {0.2, 0.6, 0.8};
    step.transition.duration = 0.8;
    plan.steps.push_back(step);
  }
  plan.UpdateTotals();
  return plan;
}

}  // namespace cairn::planning::test
