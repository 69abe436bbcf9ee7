#include <cairn/planning/stabilization/trajectory_interpolator.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>
#include <cairn/multibody/configuration.h>

namespace cairn::planning {

namespace {

constexpr double kPi = 3.141592653589793;

Eigen::Quaterniond BaseQuaternion(const Eigen::VectorXd& q, int base) {
  return Eigen::Quaterniond(q[base + 3], q[base + 4], q[base + 5], q[base + 6]).normalized();
}

// Natural cubic spline second derivatives through (t_k, y_k) for every column (Thomas algorithm).
Eigen::MatrixXd NaturalSplineSecondDerivatives(const std::vector<double>& t, const Eigen::MatrixXd& y) {
  const Eigen::Index n = y.rows();
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, y.cols());
  if (n < 3) return m;
  const Eigen::Index inner = n - 2;
  Eigen::VectorXd diag(inner), upper(inner), lower(inner);
  Eigen::MatrixXd rhs(inner, y.cols());
  for (Eigen::Index i = 1; i + 1 < n; ++i) {
    const double h0 = t[static_cast<std::size_t>(i)] - t[static_cast<std::size_t>(i - 1)];
    const double h1 = t[static_cast<std::size_t>(i + 1)] - t[static_cast<std::size_t>(i)];
    lower[i - 1] = h0;
    diag[i - 1] = 2.0 * (h0 + h1);
    upper[i - 1] = h1;
    rhs.row(i - 1) = 6.0 * ((y.row(i + 1) - y.row(i)) / h1 - (y.row(i) - y.row(i - 1)) / h0);
  }
  for (Eigen::Index i = 1; i < inner; ++i) {
    const double w = lower[i] / diag[i - 1];
    diag[i] -= w * upper[i - 1];
    rhs.row(i) -= w * rhs.row(i - 1);
  }
  m.row(inner) = rhs.row(inner - 1) / diag[inner - 1];
  for (Eigen::Index i = inner - 2; i >= 0; --i) m.row(i + 1) = (rhs.row(i) - upper[i] * m.row(i + 2)) / diag[i];
  return m;
}

}  // namespace

TrajectoryInterpolator::TrajectoryInterpolator(std::shared_ptr<const multibody::Model> model,
                                               std::vector<InterpolationKnot> knots, const std::string& kind)
    : model_(std::move(model)), knots_(std::move(knots)) {
  if (model_ == nullptr) throw std::invalid_argument("TrajectoryInterpolator: the robot model is null");
  if (kind != "hermite" && kind != "spline") {
    throw std::invalid_argument("TrajectoryInterpolator: interpolation '" + kind + "' is unknown; use hermite or spline");
  }
  spline_ = kind == "spline";
  if (knots_.empty()) throw std::invalid_argument("TrajectoryInterpolator: at least one knot is needed");
  for (std::size_t k = 0; k < knots_.size(); ++k) {
    if (knots_[k].q.size() != model_->nq() || !knots_[k].q.allFinite() || !std::isfinite(knots_[k].time)) {
      throw std::invalid_argument("TrajectoryInterpolator: knot " + std::to_string(k) +
                                  " needs a finite time and " + std::to_string(model_->nq()) +
                                  " finite coordinates");
    }
    if (k > 0 && !(knots_[k].time > knots_[k - 1].time)) {
      throw std::invalid_argument("TrajectoryInterpolator: knot " + std::to_string(k) + " at " +
                                  FormatShort(knots_[k].time) + " s does not come after knot " +
                                  std::to_string(k - 1) + " at " + FormatShort(knots_[k - 1].time) + " s");
    }
  }
  for (const multibody::Joint& joint : model_->joints()) {
    if (joint.type == multibody::JointType::kFloating) {
      if (base_q_ >= 0) throw std::invalid_argument("TrajectoryInterpolator: the model has more than one floating joint");
      base_q_ = joint.idx_q;
    } else if (joint.nq == 1) {
      joint_q_.push_back(joint.idx_q);
    }
  }
  const Eigen::Index channels = 6 + static_cast<Eigen::Index>(joint_q_.size()) + 2;
  values_.resize(static_cast<Eigen::Index>(knots_.size()), channels);
  values_.setZero();
  Eigen::Quaterniond first = Eigen::Quaterniond::Identity();
  if (base_q_ >= 0) first = BaseQuaternion(knots_.front().q, base_q_);
  for (std::size_t k = 0; k < knots_.size(); ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    const Eigen::VectorXd& q = knots_[k].q;
    if (base_q_ >= 0) {
      values_.block<1, 3>(row, 0) = q.segment<3>(base_q_).transpose();
      if (spline_) {
        const Eigen::AngleAxisd relative(first.conjugate() * BaseQuaternion(q, base_q_));
        if (relative.angle() > 0.9 * kPi) {
          throw std::invalid_argument("TrajectoryInterpolator: knot " + std::to_string(k) + " turns the base by " +
                                      FormatShort(relative.angle() * 180.0 / kPi) +
                                      " deg from the first knot, more than the spline's limit of 162 deg; use hermite");
        }
        values_.block<1, 3>(row, 3) = (relative.angle() * relative.axis()).transpose();
      }
    }
    for (std::size_t i = 0; i < joint_q_.size(); ++i) values_(row, 6 + static_cast<Eigen::Index>(i)) = q[joint_q_[i]];
    values_.block<1, 2>(row, channels - 2) = knots_[k].com.transpose();
  }
  if (spline_) {
    std::vector<double> times;
    for (const InterpolationKnot& knot : knots_) times.push_back(knot.time);
    second_ = NaturalSplineSecondDerivatives(times, values_);
  }
}

std::size_t TrajectoryInterpolator::Segment(double t) const {
  // The segment [k, k+1] containing t (t within the knots' range, at least two knots).
  auto it = std::upper_bound(knots_.begin(), knots_.end(), t,
                             [](double value, const InterpolationKnot& knot) { return value < knot.time; });
  std::size_t k = static_cast<std::size_t>(it - knots_.begin());
  k = k == 0 ? 0 : k - 1;
  return std::min(k, knots_.size() - 2);
}

Eigen::VectorXd TrajectoryInterpolator::Channels(double t, Eigen::VectorXd* rate) const {
  const Eigen::Index channels = values_.cols();
  if (knots_.size() == 1 || t <= start_time() || t >= end_time()) {
    if (rate != nullptr) *rate = Eigen::VectorXd::Zero(channels);
    return t >= end_time() ? Eigen::VectorXd(values_.row(values_.rows() - 1)) : Eigen::VectorXd(values_.row(0));
  }
  const std::size_t k = Segment(t);
  const auto r0 = static_cast<Eigen::Index>(k), r1 = r0 + 1;
  const double h = knots_[k + 1].time - knots_[k].time;
  const double s = (t - knots_[k].time) / h;
  if (!spline_) {
    const double blend = s * s * (3.0 - 2.0 * s);
    const double blend_rate = 6.0 * s * (1.0 - s) / h;
    const Eigen::VectorXd delta = values_.row(r1) - values_.row(r0);
    if (rate != nullptr) *rate = blend_rate * delta;
    return Eigen::VectorXd(values_.row(r0).transpose()) + blend * delta;
  }
  const double a = 1.0 - s, b = s;
  const Eigen::VectorXd y0 = values_.row(r0), y1 = values_.row(r1), m0 = second_.row(r0), m1 = second_.row(r1);
  if (rate != nullptr) {
    *rate = (y1 - y0) / h + ((3.0 * b * b - 1.0) * m1 - (3.0 * a * a - 1.0) * m0) * h / 6.0;
  }
  return a * y0 + b * y1 + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0;
}

Eigen::VectorXd TrajectoryInterpolator::Assemble(double t, const Eigen::VectorXd& c) const {
  Eigen::VectorXd q = knots_.front().q;
  for (std::size_t i = 0; i < joint_q_.size(); ++i) q[joint_q_[i]] = c[6 + static_cast<Eigen::Index>(i)];
  if (base_q_ >= 0) {
    q.segment<3>(base_q_) = c.head<3>();
    Eigen::Quaterniond orientation;
    if (spline_) {
      const Eigen::Vector3d r = c.segment<3>(3);
      const double angle = r.norm();
      const Eigen::Quaterniond relative =
          angle > 1e-12 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, r / angle)) : Eigen::Quaterniond::Identity();
      orientation = BaseQuaternion(knots_.front().q, base_q_) * relative;
    } else if (knots_.size() == 1 || t <= start_time()) {
      orientation = BaseQuaternion(knots_.front().q, base_q_);
    } else if (t >= end_time()) {
      orientation = BaseQuaternion(knots_.back().q, base_q_);
    } else {
      const std::size_t k = Segment(t);
      const double s = (t - knots_[k].time) / (knots_[k + 1].time - knots_[k].time);
      orientation = BaseQuaternion(knots_[k].q, base_q_).slerp(s * s * (3.0 - 2.0 * s), BaseQuaternion(knots_[k + 1].q, base_q_));
    }
    orientation.normalize();
    q[base_q_ + 3] = orientation.w();
    q[base_q_ + 4] = orientation.x();
    q[base_q_ + 5] = orientation.y();
    q[base_q_ + 6] = orientation.z();
  }
  return q;
}

Eigen::VectorXd TrajectoryInterpolator::Position(double t) const { return Assemble(t, Channels(t, nullptr)); }

void TrajectoryInterpolator::Evaluate(double t, Eigen::VectorXd* q, Eigen::VectorXd* v) const {
  Eigen::VectorXd rate;
  const Eigen::VectorXd c = Channels(t, &rate);
  *q = Assemble(t, c);
  *v = Eigen::VectorXd::Zero(model_->nv());
  for (const multibody::Joint& joint : model_->joints()) {
    if (joint.nq != 1) continue;
    const auto it = std::find(joint_q_.begin(), joint_q_.end(), joint.idx_q);
    (*v)[joint.idx_v] = rate[6 + static_cast<Eigen::Index>(it - joint_q_.begin())];
  }
  if (base_q_ >= 0) {
    // Body twist [w; v] of the base: v = R^T p', and w the body rate of the slerp (constant axis log(R_k^T R_k+1)
    // scaled by the smoothstep's rate) or of R_0 exp(r(t)) (the right Jacobian of SO(3) times r').
    const Eigen::Quaterniond orientation((*q)[base_q_ + 3], (*q)[base_q_ + 4], (*q)[base_q_ + 5], (*q)[base_q_ + 6]);
    Eigen::Vector3d omega = Eigen::Vector3d::Zero();
    const bool moving = knots_.size() > 1 && t > start_time() && t < end_time();
    if (moving && !spline_) {
      const std::size_t k = Segment(t);
      const double h = knots_[k + 1].time - knots_[k].time;
      const double s = (t - knots_[k].time) / h;
      const Eigen::AngleAxisd step(BaseQuaternion(knots_[k].q, base_q_).conjugate() *
                                   BaseQuaternion(knots_[k + 1].q, base_q_));
      omega = 6.0 * s * (1.0 - s) / h * step.angle() * step.axis();
    } else if (moving) {
      const Eigen::Vector3d r = c.segment<3>(3), r_dot = rate.segment<3>(3);
      const double angle = r.norm();
      Eigen::Matrix3d hat;
      hat << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
      Eigen::Matrix3d jacobian = Eigen::Matrix3d::Identity() - 0.5 * hat;
      if (angle > 1e-6) {
        jacobian = Eigen::Matrix3d::Identity() - (1.0 - std::cos(angle)) / (angle * angle) * hat +
                   (angle - std::sin(angle)) / (angle * angle * angle) * hat * hat;
      }
      omega = jacobian * r_dot;
    }
    for (const multibody::Joint& joint : model_->joints()) {
      if (joint.type != multibody::JointType::kFloating) continue;
      v->segment<3>(joint.idx_v) = omega;
      v->segment<3>(joint.idx_v + 3) = orientation.toRotationMatrix().transpose() * rate.head<3>();
    }
  }
}

Eigen::Vector2d TrajectoryInterpolator::ReferenceZmp(double t) const {
  return Channels(t, nullptr).tail<2>();
}

int TrajectoryInterpolator::Contacts(double t) const {
  if (knots_.size() == 1 || t <= start_time()) return knots_.front().contacts;
  if (t >= end_time()) return knots_.back().contacts;
  const std::size_t k = Segment(t);
  return knots_[k].contacts & knots_[k + 1].contacts;
}

}  // namespace cairn::planning
