#include <cairn/planning/trajectory/frame_pose_error.h>

#include <cmath>

#include <Eigen/Geometry>

#include <cairn/multibody/data.h>
#include <cairn/multibody/jacobians.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::planning {

namespace {
int FrameIndex(const std::shared_ptr<const multibody::Model>& model, const std::string& frame) {
  if (model == nullptr) throw std::invalid_argument("FramePoseError: the robot model is null; pass a parsed Model");
  return model->GetFrameIndex(frame);
}

std::vector<int> FrameColumns(const std::shared_ptr<const multibody::Model>& model, const std::string& frame) {
  const int index = FrameIndex(model, frame);
  return ConfigurationChart(*model).CoordinatesMovingBody(*model, model->frame(index).body);
}

// log: SO(3) -> R^3 (axis times angle).
Eigen::Vector3d LogRotation(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

// Inverse of the right Jacobian of SO(3) at phi: d log(R exp([w])) = Jr^{-1}(log R) w.
Eigen::Matrix3d InverseRightJacobian(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d S = multibody::Skew(phi);
  if (theta < 1e-6) return Eigen::Matrix3d::Identity() + 0.5 * S + (1.0 / 12.0) * S * S;
  const double c = 1.0 / (theta * theta) - (1.0 + std::cos(theta)) / (2.0 * theta * std::sin(theta));
  return Eigen::Matrix3d::Identity() + 0.5 * S + c * S * S;
}
}  // namespace

FramePoseError::FramePoseError(std::shared_ptr<const multibody::Model> model, const std::string& frame,
                               const multibody::Pose& X_WT)
    : WaypointEvaluator("pose_error(" + frame + ")", model, 6, FrameColumns(model, frame)),
      frame_(FrameIndex(model, frame)),
      X_WT_(X_WT) {}

void FramePoseError::EvalTangent(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> y, Eigen::MatrixXd* J_v) const {
  multibody::Data data(model());
  multibody::ForwardKinematics(model(), data, q);
  const multibody::Pose X_WF = multibody::FramePose(model(), data, frame_);
  const Eigen::Matrix3d R_TF = X_WT_.rotation().transpose() * X_WF.rotation();
  const Eigen::Vector3d phi = LogRotation(R_TF);
  y.head<3>() = X_WF.translation() - X_WT_.translation();
  y.tail<3>() = phi;
  if (J_v == nullptr) return;
  Eigen::MatrixXd J_aligned(6, model().nv());
  Eigen::MatrixXd J_local(6, model().nv());
  multibody::FrameJacobian(model(), data, frame_, multibody::ReferenceFrame::kWorldAligned, J_aligned);
  multibody::FrameJacobian(model(), data, frame_, multibody::ReferenceFrame::kLocal, J_local);
  J_v->topRows<3>() = J_aligned.bottomRows<3>();
  J_v->bottomRows<3>() = InverseRightJacobian(phi) * J_local.topRows<3>();
}

}  // namespace cairn::planning
