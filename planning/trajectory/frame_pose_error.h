#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include <cairn/multibody/pose.h>
#include <cairn/planning/trajectory/waypoint_evaluator.h>

namespace cairn::planning {

/// The 6-D pose error of a frame against a target (thesis f_stance, eq. 2.9b): rows 0-2 the position error
/// p_WF(q) - p_WT in world axes (m), rows 3-5 the axis-angle vector log(R_WT' R_WF(q)) in the target's axes (rad).
/// Zero exactly when the frame sits on the target. The rotation rows' Jacobian uses the inverse right Jacobian
/// of SO(3), so it is exact away from the 180-degree cut (errors near pi are reported, but the derivative is
/// not meaningful there: targets are expected within a few tens of degrees of the initial guess).
class FramePoseError final : public WaypointEvaluator {
 public:
  /// Throws std::invalid_argument for an unknown frame (listing the closest names).
  FramePoseError(std::shared_ptr<const multibody::Model> model, const std::string& frame,
                 const multibody::Pose& X_WT);

  /// The frame index.
  int frame() const { return frame_; }

  /// The target pose.
  const multibody::Pose& target() const { return X_WT_; }

 private:
  void EvalTangent(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> y, Eigen::MatrixXd* J_v) const override;

  int frame_;
  multibody::Pose X_WT_;
};

}  // namespace cairn::planning
