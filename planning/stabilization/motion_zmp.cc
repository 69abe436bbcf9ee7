#include <cairn/planning/stabilization/motion_zmp.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <cairn/common/number_text.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/dynamics.h>

namespace cairn::planning {

namespace {
void CheckSamples(const char* caller, const multibody::Model& model, const std::vector<Eigen::VectorXd>& q,
                  double period) {
  if (q.size() < 3) {
    throw std::invalid_argument(std::string(caller) + ": " + std::to_string(q.size()) +
                                " samples given; at least 3 are needed to difference twice");
  }
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument(std::string(caller) + ": period " + FormatShort(period) +
                                " s must be positive and finite");
  }
  for (std::size_t k = 0; k < q.size(); ++k) {
    if (q[k].size() != model.nq() || !q[k].allFinite()) {
      throw std::invalid_argument(std::string(caller) + ": sample " + std::to_string(k) + " must have " +
                                  std::to_string(model.nq()) + " finite coordinates (it has " +
                                  std::to_string(q[k].size()) + ")");
    }
  }
}
}  // namespace

std::vector<Eigen::VectorXd> SampleVelocities(const multibody::Model& model, const std::vector<Eigen::VectorXd>& q,
                                              double period) {
  CheckSamples("SampleVelocities", model, q, period);
  const std::size_t n = q.size();
  std::vector<Eigen::VectorXd> v(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k == 0 ? 0 : k - 1, b = k + 1 == n ? n - 1 : k + 1;
    v[k] = multibody::Difference(model, q[a], q[b]) / (period * static_cast<double>(b - a));
  }
  return v;
}

std::vector<Eigen::Vector2d> ComputeMotionZmp(const multibody::Model& model, const std::vector<Eigen::VectorXd>& q,
                                              double period, const std::vector<double>& ground_height) {
  CheckSamples("ComputeMotionZmp", model, q, period);
  const std::size_t n = q.size();
  if (ground_height.size() != 1 && ground_height.size() != n) {
    throw std::invalid_argument("ComputeMotionZmp: " + std::to_string(ground_height.size()) +
                                " ground heights given for " + std::to_string(n) + " samples; give 1 or " +
                                std::to_string(n));
  }
  const std::vector<Eigen::VectorXd> v = SampleVelocities(model, q, period);
  multibody::Data data(model);
  std::vector<multibody::Vector6d> h(n);
  std::vector<Eigen::Vector3d> c(n);
  for (std::size_t k = 0; k < n; ++k) {
    h[k] = multibody::CentroidalMomentum(model, data, q[k], v[k]);
    c[k] = multibody::CenterOfMass(model, data, q[k]);
  }
  const double mass = model.total_mass();
  const Eigen::Vector3d gravity = model.gravity();
  std::vector<Eigen::Vector2d> zmp(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k == 0 ? 0 : k - 1, b = k + 1 == n ? n - 1 : k + 1;
    const multibody::Vector6d rate = (h[b] - h[a]) / (period * static_cast<double>(b - a));
    const Eigen::Vector3d f = rate.tail<3>() - mass * gravity;
    const Eigen::Vector3d k_dot = rate.head<3>();
    const double z_g = ground_height.size() == 1 ? ground_height[0] : ground_height[k];
    if (!(f.z() > 1e-6 * mass * gravity.norm())) {
      zmp[k].setConstant(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    const double height = c[k].z() - z_g;
    zmp[k] = Eigen::Vector2d(c[k].x() - (height * f.x() + k_dot.y()) / f.z(),
                             c[k].y() - (height * f.y() - k_dot.x()) / f.z());
  }
  return zmp;
}

}  // namespace cairn::planning
