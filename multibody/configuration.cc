#include <cairn/multibody/configuration.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>
#include <cairn/multibody/joint_motion.h>

namespace cairn::multibody {
namespace {

void CheckQ(const Model& model, Eigen::Index size, const char* caller, const char* name = "q") {
  if (size != model.nq()) {
    throw std::invalid_argument(std::string(caller) + ": " + name + " has size " + std::to_string(size) +
                                " but model '" + model.name() + "' has nq = " + std::to_string(model.nq()));
  }
}

void CheckV(const Model& model, Eigen::Index size, const char* caller) {
  if (size != model.nv()) {
    throw std::invalid_argument(std::string(caller) + ": v has size " + std::to_string(size) + " but model '" +
                                model.name() + "' has nv = " + std::to_string(model.nv()));
  }
}

// V(ω) of the SE(3) exponential: p = V(ω) v. Taylor series below a small angle keep full precision.
Eigen::Matrix3d LeftJacobianSO3(const Eigen::Vector3d& w) {
  const double theta2 = w.squaredNorm();
  const Eigen::Matrix3d W = Skew(w);
  double a, b;
  if (theta2 < 1e-8) {
    a = 0.5 - theta2 / 24.0;
    b = 1.0 / 6.0 - theta2 / 120.0;
  } else {
    const double theta = std::sqrt(theta2);
    a = (1.0 - std::cos(theta)) / theta2;
    b = (theta - std::sin(theta)) / (theta2 * theta);
  }
  return Eigen::Matrix3d::Identity() + a * W + b * W * W;
}

Eigen::Matrix3d InverseLeftJacobianSO3(const Eigen::Vector3d& w) {
  const double theta2 = w.squaredNorm();
  const Eigen::Matrix3d W = Skew(w);
  double c;
  if (theta2 < 1e-8) {
    c = 1.0 / 12.0 + theta2 / 720.0;
  } else {
    const double theta = std::sqrt(theta2);
    c = (1.0 - theta * std::sin(theta) / (2.0 * (1.0 - std::cos(theta)))) / theta2;
  }
  return Eigen::Matrix3d::Identity() - 0.5 * W + c * W * W;
}

Eigen::Quaterniond ExpSO3(const Eigen::Vector3d& w) {
  const double theta = w.norm();
  if (theta < 1e-12) return Eigen::Quaterniond(1.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z()).normalized();
  return Eigen::Quaterniond(Eigen::AngleAxisd(theta, w / theta));
}

Eigen::Vector3d LogSO3(const Eigen::Quaterniond& quat) {
  Eigen::Quaterniond q = quat.normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // shortest rotation
  const double s = q.vec().norm();
  if (s < 1e-12) return 2.0 * q.vec() / q.w();
  const double theta = 2.0 * std::atan2(s, q.w());
  return theta * q.vec() / s;
}

Eigen::Quaterniond ReadQuaternion(const Eigen::Ref<const Eigen::VectorXd>& q, int idx) {
  return Eigen::Quaterniond(q[idx], q[idx + 1], q[idx + 2], q[idx + 3]);
}

void WriteQuaternion(const Eigen::Quaterniond& quat, Eigen::Ref<Eigen::VectorXd> q, int idx) {
  q[idx] = quat.w();
  q[idx + 1] = quat.x();
  q[idx + 2] = quat.y();
  q[idx + 3] = quat.z();
}

}  // namespace

Eigen::VectorXd NeutralConfiguration(const Model& model) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.nq());
  for (const Joint& joint : model.joints()) {
    if (joint.type == JointType::kFloating) q[joint.idx_q + 3] = 1.0;
  }
  return q;
}

Eigen::VectorXd Integrate(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q,
                          const Eigen::Ref<const Eigen::VectorXd>& v, double dt) {
  CheckQ(model, q.size(), "Integrate");
  CheckV(model, v.size(), "Integrate");
  Eigen::VectorXd out = q;
  for (const Joint& joint : model.joints()) {
    switch (joint.type) {
      case JointType::kFixed:
        break;
      case JointType::kRevolute:
      case JointType::kPrismatic:
        out[joint.idx_q] += v[joint.idx_v] * dt;
        break;
      case JointType::kFloating: {
        const Eigen::Vector3d w = v.segment<3>(joint.idx_v) * dt;
        const Eigen::Vector3d lin = v.segment<3>(joint.idx_v + 3) * dt;
        const Eigen::Quaterniond quat = ReadQuaternion(q, joint.idx_q + 3).normalized();
        out.segment<3>(joint.idx_q) += quat.toRotationMatrix() * (LeftJacobianSO3(w) * lin);
        WriteQuaternion((quat * ExpSO3(w)).normalized(), out, joint.idx_q + 3);
        break;
      }
    }
  }
  return out;
}

Eigen::VectorXd Difference(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q0,
                           const Eigen::Ref<const Eigen::VectorXd>& q1) {
  CheckQ(model, q0.size(), "Difference", "q0");
  CheckQ(model, q1.size(), "Difference", "q1");
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model.nv());
  for (const Joint& joint : model.joints()) {
    switch (joint.type) {
      case JointType::kFixed:
        break;
      case JointType::kRevolute:
      case JointType::kPrismatic:
        v[joint.idx_v] = q1[joint.idx_q] - q0[joint.idx_q];
        break;
      case JointType::kFloating: {
        const Eigen::Quaterniond a = ReadQuaternion(q0, joint.idx_q + 3).normalized();
        const Eigen::Quaterniond b = ReadQuaternion(q1, joint.idx_q + 3).normalized();
        const Eigen::Vector3d w = LogSO3(a.conjugate() * b);
        const Eigen::Vector3d dp =
            a.toRotationMatrix().transpose() * (q1.segment<3>(joint.idx_q) - q0.segment<3>(joint.idx_q));
        v.segment<3>(joint.idx_v) = w;
        v.segment<3>(joint.idx_v + 3) = InverseLeftJacobianSO3(w) * dp;
        break;
      }
    }
  }
  return v;
}

Eigen::VectorXd ConfigurationRate(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q,
                                  const Eigen::Ref<const Eigen::VectorXd>& v) {
  CheckQ(model, q.size(), "ConfigurationRate");
  CheckV(model, v.size(), "ConfigurationRate");
  Eigen::VectorXd qdot = Eigen::VectorXd::Zero(model.nq());
  for (const Joint& joint : model.joints()) {
    switch (joint.type) {
      case JointType::kFixed:
        break;
      case JointType::kRevolute:
      case JointType::kPrismatic:
        qdot[joint.idx_q] = v[joint.idx_v];
        break;
      case JointType::kFloating: {
        const Eigen::Quaterniond quat = ReadQuaternion(q, joint.idx_q + 3);
        qdot.segment<3>(joint.idx_q) = quat.normalized().toRotationMatrix() * v.segment<3>(joint.idx_v + 3);
        const Eigen::Vector3d w = v.segment<3>(joint.idx_v);
        const Eigen::Quaterniond rate = quat * Eigen::Quaterniond(0.0, w.x(), w.y(), w.z());
        qdot[joint.idx_q + 3] = 0.5 * rate.w();
        qdot[joint.idx_q + 4] = 0.5 * rate.x();
        qdot[joint.idx_q + 5] = 0.5 * rate.y();
        qdot[joint.idx_q + 6] = 0.5 * rate.z();
        break;
      }
    }
  }
  return qdot;
}

void NormalizeConfiguration(const Model& model, Eigen::Ref<Eigen::VectorXd> q) {
  CheckQ(model, q.size(), "NormalizeConfiguration");
  for (const Joint& joint : model.joints()) {
    if (joint.type != JointType::kFloating) continue;
    const double norm = q.segment<4>(joint.idx_q + 3).norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) {
      throw std::invalid_argument("NormalizeConfiguration: floating joint '" + joint.name +
                                  "' has a zero or non-finite quaternion; set it to (1, 0, 0, 0)");
    }
    q.segment<4>(joint.idx_q + 3) /= norm;
  }
}

Eigen::VectorXd RandomConfiguration(const Model& model, std::mt19937& rng, double unlimited_range) {
  if (!(unlimited_range >= 0.0) || !std::isfinite(unlimited_range)) {
    throw std::invalid_argument("RandomConfiguration: unlimited_range " + FormatShort(unlimited_range) +
                                " must be finite and >= 0 (e.g. pi for unlimited angles)");
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::VectorXd q = NeutralConfiguration(model);
  for (const Joint& joint : model.joints()) {
    switch (joint.type) {
      case JointType::kFixed:
        break;
      case JointType::kRevolute:
      case JointType::kPrismatic: {
        const double lo = std::isfinite(joint.lower_limit) ? joint.lower_limit : -unlimited_range;
        const double hi = std::isfinite(joint.upper_limit) ? joint.upper_limit : unlimited_range;
        q[joint.idx_q] = lo + (hi - lo) * unit(rng);
        break;
      }
      case JointType::kFloating: {
        for (int k = 0; k < 3; ++k) q[joint.idx_q + k] = unlimited_range * (2.0 * unit(rng) - 1.0);
        // A normalized 4-D Gaussian is uniform on the unit sphere, hence a uniform rotation.
        Eigen::Vector4d g;
        for (int k = 0; k < 4; ++k) g[k] = normal(rng);
        q.segment<4>(joint.idx_q + 3) = g.normalized();
        break;
      }
    }
  }
  return q;
}

bool IsWithinPositionLimits(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q, double tolerance) {
  if (!(tolerance >= 0.0)) {
    throw std::invalid_argument("IsWithinPositionLimits: tolerance " + FormatShort(tolerance) + " must be >= 0");
  }
  if (model.nq() == 0) {
    CheckQ(model, q.size(), "IsWithinPositionLimits");
    return true;
  }
  return PositionLimitViolation(model, q).cwiseAbs().maxCoeff() <= tolerance;
}

Eigen::VectorXd PositionLimitViolation(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q) {
  CheckQ(model, q.size(), "PositionLimitViolation");
  Eigen::VectorXd violation = Eigen::VectorXd::Zero(model.nq());
  for (const Joint& joint : model.joints()) {
    if (joint.type != JointType::kRevolute && joint.type != JointType::kPrismatic) continue;
    const double x = q[joint.idx_q];
    if (x > joint.upper_limit) violation[joint.idx_q] = x - joint.upper_limit;
    if (x < joint.lower_limit) violation[joint.idx_q] = x - joint.lower_limit;
  }
  return violation;
}

Eigen::VectorXd ClampToPositionLimits(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& q) {
  return q - PositionLimitViolation(model, q);
}

}  // namespace cairn::multibody
