#include "cairn/perception/haptics/rigid_transform_fit.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/SVD>

#include "cairn/common/number_text.h"

namespace cairn::perception {

RigidTransformFit FitRigidTransform(const Eigen::Matrix3Xd& p_C, const Eigen::Matrix3Xd& p_A) {
  if (p_C.cols() != p_A.cols()) {
    throw std::invalid_argument("the correspondences have " + FormatShort(static_cast<long long>(p_C.cols())) +
                                " sensor points but " + FormatShort(static_cast<long long>(p_A.cols())) +
                                " antenna points; give one of each per correspondence");
  }
  if (p_C.cols() < 3) {
    throw std::invalid_argument("a rigid transform needs at least 3 correspondences; got " +
                                FormatShort(static_cast<long long>(p_C.cols())));
  }
  if (!p_C.allFinite() || !p_A.allFinite()) throw std::invalid_argument("a correspondence holds a non-finite point");
  const Eigen::Vector3d c_C = p_C.rowwise().mean();
  const Eigen::Vector3d c_A = p_A.rowwise().mean();
  const Eigen::Matrix3Xd q_C = p_C.colwise() - c_C;
  const Eigen::Matrix3Xd q_A = p_A.colwise() - c_A;
  const Eigen::Matrix3d H = q_C * q_A.transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d sigma = svd.singularValues();
  // Collinear sensor points leave the rotation about their line free: the second singular value vanishes.
  const Eigen::JacobiSVD<Eigen::Matrix3Xd> spread(q_C);
  const Eigen::Vector3d s_C = spread.singularValues();
  if (!(s_C[0] > 0.0) || !(s_C[1] > 1e-9 * s_C[0]) || !(sigma[0] > 0.0)) {
    throw std::invalid_argument("the sensor points are (nearly) collinear, so the rotation is not determined; "
                                "spread the calibration points over the antenna's workspace");
  }
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  const Eigen::Matrix3d R = svd.matrixV() * D * svd.matrixU().transpose();
  RigidTransformFit fit;
  fit.X_AC.linear() = R;
  fit.X_AC.translation() = c_A - R * c_C;
  const Eigen::Matrix3Xd residual = p_A - ((R * p_C).colwise() + fit.X_AC.translation());
  const Eigen::RowVectorXd norms = residual.colwise().norm();
  fit.rms_residual = std::sqrt(norms.array().square().mean());
  fit.max_residual = norms.maxCoeff();
  return fit;
}

}  // namespace cairn::perception
