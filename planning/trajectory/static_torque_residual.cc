#include <cairn/planning/trajectory/static_torque_residual.h>

#include <cmath>
#include <numeric>
#include <stdexcept>

#include <cairn/common/number_text.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/gravity_torques.h>
#include <cairn/multibody/jacobians.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/pose.h>

namespace cairn::planning {

namespace {
int NumJoints(const std::shared_ptr<const multibody::Model>& model, const std::vector<TorqueSupport>& supports,
              const Eigen::VectorXd& scale) {
  if (model == nullptr) throw std::invalid_argument("StaticTorqueResidual: the robot model is null");
  if (supports.empty()) throw std::invalid_argument("StaticTorqueResidual: no supports; give at least one contact frame");
  double sum = 0.0;
  for (const TorqueSupport& s : supports) {
    model->GetFrameIndex(s.frame);
    if (!(s.share > 0.0 && s.share <= 1.0)) {
      throw std::invalid_argument("StaticTorqueResidual: support '" + s.frame + "' has share " + FormatShort(s.share) +
                                  "; shares lie in (0, 1]");
    }
    sum += s.share;
  }
  if (std::abs(sum - 1.0) > 1e-9) {
    throw std::invalid_argument("StaticTorqueResidual: the support shares sum to " + FormatShort(sum) +
                                "; they must sum to 1");
  }
  const int n = static_cast<int>(ConfigurationChart(*model).joint_coordinates().size());
  if (scale.size() != n || !scale.allFinite() || (n > 0 && !(scale.minCoeff() > 0.0))) {
    throw std::invalid_argument("StaticTorqueResidual: scale has " + FormatShort(static_cast<int>(scale.size())) +
                                " entries; give one finite positive entry per joint (" + FormatShort(n) + ")");
  }
  return n;
}

std::vector<int> AllColumns(const std::shared_ptr<const multibody::Model>& model) {
  std::vector<int> columns(static_cast<std::size_t>(model->nq()));
  std::iota(columns.begin(), columns.end(), 0);
  return columns;
}
}  // namespace

StaticTorqueResidual::StaticTorqueResidual(std::shared_ptr<const multibody::Model> model,
                                           const std::vector<TorqueSupport>& supports, const Eigen::VectorXd& scale)
    : WaypointEvaluator("static_torques", model, NumJoints(model, supports, scale), AllColumns(model)), scale_(scale) {
  const multibody::Model& m = this->model();
  for (const TorqueSupport& s : supports) {
    frames_.push_back(m.GetFrameIndex(s.frame));
    shares_.push_back(s.share);
    const int body = m.frame(frames_.back()).body;
    std::vector<char> carries(static_cast<std::size_t>(m.nv()));
    for (int k = 0; k < m.nv(); ++k) carries[static_cast<std::size_t>(k)] = m.IsAncestorOrSelf(m.velocity_joint(k), body);
    carries_support_.push_back(std::move(carries));
  }
  moves_axis_ = Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>(m.nv(), m.nv());
  for (int k = 0; k < m.nv(); ++k) {
    for (int j = 0; j < m.nv(); ++j) moves_axis_(k, j) = m.IsAncestorOrSelf(m.velocity_joint(j), m.velocity_joint(k));
  }
}

Eigen::VectorXd StaticTorqueResidual::JointTorques(const Eigen::Ref<const Eigen::VectorXd>& q) const {
  Eigen::VectorXd r = Eval(q);
  return r.cwiseQuotient(scale_);
}

void StaticTorqueResidual::EvalTangent(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> y,
                                       Eigen::MatrixXd* J_v) const {
  const multibody::Model& m = model();
  const int nv = m.nv();
  multibody::Data data(m);
  if (J_v != nullptr) {
    multibody::GravityTorquesDerivative(m, data, q);
  } else {
    multibody::GravityTorques(m, data, q);
  }
  const Eigen::VectorXd tau_g = data.gravity_torques;
  const Eigen::MatrixXd dtau_g = data.gravity_torques_derivative;
  multibody::CenterOfMassJacobian(m, data, q);  // also the poses, the COM and the world motion subspaces
  const Eigen::Vector3d f = -m.total_mass() * m.gravity();
  multibody::Vector6d W;
  W.head<3>() = data.com.cross(f);
  W.tail<3>() = f;
  Eigen::VectorXd tau = tau_g;
  Eigen::MatrixXd dtau;
  if (J_v != nullptr) dtau = dtau_g;
  Eigen::MatrixXd J_c(6, nv);
  for (std::size_t c = 0; c < frames_.size(); ++c) {
    multibody::FrameJacobian(m, data, frames_[c], multibody::ReferenceFrame::kWorld, J_c);
    for (int k = 0; k < nv; ++k) {
      if (!carries_support_[c][static_cast<std::size_t>(k)]) continue;
      const multibody::Vector6d S_k = J_c.col(k);
      tau(k) -= shares_[c] * S_k.dot(W);
      if (J_v == nullptr) continue;
      for (int j = 0; j < nv; ++j) {
        double d = S_k.head<3>().dot(Eigen::Vector3d(data.com_jacobian.col(j)).cross(f));
        if (moves_axis_(k, j)) {
          const multibody::Vector6d S_j = data.joint_motion_world.col(j);
          d += multibody::CrossMotion(S_j, S_k).dot(W);
        }
        dtau(k, j) -= shares_[c] * d;
      }
    }
  }
  const std::vector<int>& joint_v = chart().joint_velocities();
  for (std::size_t i = 0; i < joint_v.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    y(row) = scale_(row) * tau(joint_v[i]);
    if (J_v != nullptr) J_v->row(row) = scale_(row) * dtau.row(joint_v[i]);
  }
}

}  // namespace cairn::planning
