#include <cairn/planning/trajectory/configuration_chart.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>
#include <cairn/multibody/joint.h>

namespace cairn::planning {

ConfigurationChart::ConfigurationChart(const multibody::Model& model) : nq_(model.nq()), nv_(model.nv()) {
  for (int j = 1; j < static_cast<int>(model.joints().size()); ++j) {
    const multibody::Joint& joint = model.joint(j);
    if (joint.type == multibody::JointType::kFloating) {
      if (j != 1 || joint.idx_q != 0 || joint.idx_v != 0) {
        throw std::invalid_argument("ConfigurationChart: floating joint '" + joint.name +
                                    "' is not the model's root joint; only a floating root is supported");
      }
      floating_ = true;
    } else if (joint.nq == 1) {
      joint_q_.push_back(joint.idx_q);
      joint_v_.push_back(joint.idx_v);
    }
  }
}

Eigen::VectorXd ConfigurationChart::Normalized(const Eigen::Ref<const Eigen::VectorXd>& q) const {
  if (q.size() != nq_) {
    throw std::invalid_argument("ConfigurationChart: q has " + FormatShort(static_cast<int>(q.size())) +
                                " entries, the model has nq = " + FormatShort(nq_));
  }
  Eigen::VectorXd out = q;
  if (floating_) {
    const double norm = q.segment<4>(3).norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) {
      throw std::invalid_argument("ConfigurationChart: the floating base's quaternion has norm " + FormatShort(norm) +
                                  "; give a nonzero finite quaternion");
    }
    out.segment<4>(3) /= norm;
  }
  return out;
}

Eigen::MatrixXd ConfigurationChart::TangentToCoordinates(const Eigen::Ref<const Eigen::VectorXd>& q,
                                                         const Eigen::Ref<const Eigen::MatrixXd>& J_v) const {
  Eigen::MatrixXd J_q = Eigen::MatrixXd::Zero(J_v.rows(), nq_);
  if (!floating_) {
    J_q = J_v;
    return J_q;
  }
  const Eigen::Vector4d quat = q.segment<4>(3);
  const double norm = quat.norm();
  const Eigen::Vector4d n = quat / norm;
  const Eigen::Quaterniond rotation(n(0), n(1), n(2), n(3));
  const Eigen::Matrix3d R = rotation.toRotationMatrix();
  const Eigen::Vector3d u = n.tail<3>();
  Eigen::Matrix<double, 3, 4> G;
  G.col(0) = -u;
  G.block<3, 3>(0, 1) = n(0) * Eigen::Matrix3d::Identity();
  G(0, 2) += u.z();
  G(0, 3) -= u.y();
  G(1, 1) -= u.z();
  G(1, 3) += u.x();
  G(2, 1) += u.y();
  G(2, 2) -= u.x();
  // v_lin = R^T dp (the body twist's linear part); ω = 2 G(n) dn with dn = (I - n n') dquat / |quat|, and
  // G(n) n = 0, so the projection drops out.
  J_q.leftCols<3>() = J_v.middleCols<3>(3) * R.transpose();
  J_q.middleCols<4>(3) = J_v.leftCols<3>() * ((2.0 / norm) * G);
  for (std::size_t i = 0; i < joint_q_.size(); ++i) J_q.col(joint_q_[i]) = J_v.col(joint_v_[i]);
  return J_q;
}

std::vector<int> ConfigurationChart::CoordinatesMovingBody(const multibody::Model& model, int body) const {
  std::vector<int> columns;
  for (int b = body; b > 0; b = model.parent(b)) {
    const multibody::Joint& joint = model.joint(b);
    for (int k = 0; k < joint.nq; ++k) columns.push_back(joint.idx_q + k);
  }
  std::sort(columns.begin(), columns.end());
  return columns;
}

}  // namespace cairn::planning
