#include <cairn/planning/trajectory/waist_roll_error.h>

#include <stdexcept>

#include <cairn/multibody/data.h>
#include <cairn/multibody/jacobians.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::planning {

namespace {
int FrameOf(const std::shared_ptr<const multibody::Model>& model, const std::string& frame) {
  if (model == nullptr) throw std::invalid_argument("WaistRollError: the robot model is null");
  return model->GetFrameIndex(frame);
}

std::vector<int> Columns(const std::shared_ptr<const multibody::Model>& model, const std::string& frame) {
  const int index = FrameOf(model, frame);
  return ConfigurationChart(*model).CoordinatesMovingBody(*model, model->frame(index).body);
}
}  // namespace

WaistRollError::WaistRollError(std::shared_ptr<const multibody::Model> model, const std::string& frame)
    : WaypointEvaluator("waist_roll(" + frame + ")", model, 1, Columns(model, frame)),
      frame_(FrameOf(model, frame)) {}

void WaistRollError::EvalTangent(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> y, Eigen::MatrixXd* J_v) const {
  multibody::Data data(model());
  multibody::ForwardKinematics(model(), data, q);
  const Eigen::Vector3d y_W = multibody::FramePose(model(), data, frame_).rotation().col(1);
  y(0) = y_W.z();
  if (J_v == nullptr) return;
  Eigen::MatrixXd J(6, model().nv());
  multibody::FrameJacobian(model(), data, frame_, multibody::ReferenceFrame::kWorldAligned, J);
  // d(y_W) = ω × y_W, so d(e_z . y_W) = ω . (y_W × e_z).
  const Eigen::Vector3d g = y_W.cross(Eigen::Vector3d::UnitZ());
  *J_v = g.transpose() * J.topRows<3>();
}

}  // namespace cairn::planning
