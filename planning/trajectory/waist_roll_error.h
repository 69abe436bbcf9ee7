#pragma once

#include <memory>
#include <string>

#include <cairn/planning/trajectory/waypoint_evaluator.h>

namespace cairn::planning {

/// The waist link's roll with respect to the world (thesis f_roll, eq. 2.9d), as the world-z component of the
/// link's y axis: R_WL(2, 1) = sin(roll) cos(pitch) in roll-pitch-yaw terms. It is zero exactly when the roll is
/// zero (for |pitch| < 90 degrees), and smooth everywhere, unlike the Euler angle itself.
class WaistRollError final : public WaypointEvaluator {
 public:
  /// Throws std::invalid_argument for an unknown frame.
  WaistRollError(std::shared_ptr<const multibody::Model> model, const std::string& frame);

 private:
  void EvalTangent(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> y, Eigen::MatrixXd* J_v) const override;

  int frame_;
};

}  // namespace cairn::planning
