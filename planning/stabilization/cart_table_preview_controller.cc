#include <cairn/planning/stabilization/cart_table_preview_controller.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include <cairn/common/number_text.h>
#include <cairn/planning/stabilization/discrete_riccati.h>

namespace cairn::planning {

namespace {
void Check(const char* name, double value, double lo, double hi, const char* unit) {
  if (!(value > lo && value <= hi) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string("CartTablePreviewController: ") + name + " " + FormatShort(value) + unit +
                                " must be in (" + FormatShort(lo) + ", " + FormatShort(hi) + "]");
  }
}
}  // namespace

CartTablePreviewController::CartTablePreviewController(double dt, double com_height, double gravity, double preview,
                                                       double q, double r)
    : dt_(dt), com_height_(com_height), gravity_(gravity) {
  Check("dt", dt, 0.0, 0.1, " s");
  Check("com_height", com_height, 0.0, 100.0, " m");
  Check("gravity", gravity, 0.0, 1000.0, " m/s^2");
  Check("q", q, 0.0, 1e12, "");
  Check("r", r, 0.0, 1e12, "");
  if (!(preview >= dt && preview <= 5.0) || preview / dt > 50000.0) {
    throw std::invalid_argument("CartTablePreviewController: preview " + FormatShort(preview) + " s must be in [dt = " +
                                FormatShort(dt) + " s, 5 s] and at most 50000 samples");
  }
  a_ << 1.0, dt, dt * dt / 2.0, 0.0, 1.0, dt, 0.0, 0.0, 1.0;
  b_ << dt * dt * dt / 6.0, dt * dt / 2.0, dt;
  c_ << 1.0, 0.0, -com_height / gravity;
  Eigen::Matrix4d at = Eigen::Matrix4d::Zero();
  at(0, 0) = 1.0;
  at.block<1, 3>(0, 1) = c_ * a_;
  at.block<3, 3>(1, 1) = a_;
  Eigen::Vector4d bt;
  bt << c_ * b_, b_;
  Eigen::Vector4d it = Eigen::Vector4d::UnitX();
  Eigen::Matrix4d qt = Eigen::Matrix4d::Zero();
  qt(0, 0) = q;
  Eigen::Matrix<double, 1, 1> rt;
  rt(0, 0) = r;
  const Eigen::Matrix4d p = SolveDiscreteAlgebraicRiccati(at, bt, qt, rt);
  const double s = r + bt.dot(p * bt);
  gi_ = bt.dot(p * it) / s;
  Eigen::Matrix<double, 4, 3> ft;
  ft.row(0) = c_ * a_;
  ft.block<3, 3>(1, 0) = a_;
  gx_ = (bt.transpose() * p * ft) / s;
  const Eigen::Matrix4d ac = at - bt * (bt.transpose() * p * at) / s;
  const auto n = static_cast<Eigen::Index>(std::llround(preview / dt));
  gd_.resize(n);
  gd_[0] = -gi_;
  Eigen::Vector4d x = -ac.transpose() * p * it;
  for (Eigen::Index j = 1; j < n; ++j) {
    gd_[j] = bt.dot(x) / s;
    x = ac.transpose() * x;
  }
}

CartTableMotion CartTablePreviewController::Track(const Eigen::VectorXd& zmp_reference, double start) const {
  if (zmp_reference.size() == 0 || !zmp_reference.allFinite() || !std::isfinite(start)) {
    throw std::invalid_argument("CartTablePreviewController::Track: the reference must be non-empty and finite");
  }
  const Eigen::Index n = zmp_reference.size(), horizon = gd_.size();
  CartTableMotion motion;
  motion.position.resize(n);
  motion.velocity.resize(n);
  motion.acceleration.resize(n);
  motion.zmp.resize(n);
  Eigen::Vector3d x(start, 0.0, 0.0);
  double error_sum = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    motion.position[k] = x[0];
    motion.velocity[k] = x[1];
    motion.acceleration[k] = x[2];
    const double p = c_ * x;
    motion.zmp[k] = p;
    error_sum += p - zmp_reference[k];
    double preview = 0.0;
    for (Eigen::Index j = 0; j < horizon; ++j) preview += gd_[j] * zmp_reference[std::min(k + j + 1, n - 1)];
    const double u = -gi_ * error_sum - gx_ * x - preview;
    x = a_ * x + b_ * u;
  }
  return motion;
}

}  // namespace cairn::planning
