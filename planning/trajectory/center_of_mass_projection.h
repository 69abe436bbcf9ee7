#pragma once

#include <memory>

#include <Eigen/Core>

#include <cairn/planning/trajectory/waypoint_evaluator.h>

namespace cairn::planning {

/// A (m x 2) times the horizontal projection of the centre of mass, minus `offset`: with the support polygon
/// written as half-planes A p <= b, the rows bounded above by b - margin keep the COM inside (thesis f_xy,
/// eq. 2.9c); with A = I and offset = a target point it is a COM-target residual for inverse kinematics.
class CenterOfMassProjection final : public WaypointEvaluator {
 public:
  /// Throws std::invalid_argument if A does not have 2 columns or has no row, or a non-finite entry, or the
  /// offset (empty means zero) does not have one finite entry per row.
  CenterOfMassProjection(std::shared_ptr<const multibody::Model> model, const Eigen::MatrixXd& A,
                         const Eigen::VectorXd& offset = Eigen::VectorXd());

 private:
  void EvalTangent(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> y, Eigen::MatrixXd* J_v) const override;

  Eigen::MatrixXd A_;
  Eigen::VectorXd offset_;
};

}  // namespace cairn::planning
