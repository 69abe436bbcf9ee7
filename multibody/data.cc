#include <cairn/multibody/data.h>

#include <stdexcept>
#include <string>

namespace cairn::multibody {
namespace {

// Runs before any buffer is sized.
int CheckedNv(const Model& model) {
  if (model.nv() > kMaxDataVelocities) {
    throw std::invalid_argument("model '" + model.name() + "' has " + std::to_string(model.nv()) +
                                " velocity coordinates; a Data serves at most " + std::to_string(kMaxDataVelocities) +
                                " (kMaxDataVelocities), since it holds dense nv x nv matrices");
  }
  return model.nv();
}

}  // namespace

Data::Data(const Model& model)
    : nq((CheckedNv(model), model.nq())),
      nv(model.nv()),
      X_parent(static_cast<std::size_t>(model.num_bodies())),
      X_world(static_cast<std::size_t>(model.num_bodies())),
      v(static_cast<std::size_t>(model.num_bodies()), Vector6d::Zero()),
      a(static_cast<std::size_t>(model.num_bodies()), Vector6d::Zero()),
      f(static_cast<std::size_t>(model.num_bodies()), Vector6d::Zero()),
      composite_inertia(static_cast<std::size_t>(model.num_bodies())),
      subtree_mass(static_cast<std::size_t>(model.num_bodies()), 0.0),
      subtree_first_moment(static_cast<std::size_t>(model.num_bodies()), Eigen::Vector3d::Zero()),
      joint_motion_world(Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, model.nv())),
      tau(Eigen::VectorXd::Zero(model.nv())),
      gravity_torques(Eigen::VectorXd::Zero(model.nv())),
      gravity_torques_derivative(Eigen::MatrixXd::Zero(model.nv(), model.nv())),
      M(Eigen::MatrixXd::Zero(model.nv(), model.nv())),
      nonlinear_effects(Eigen::VectorXd::Zero(model.nv())),
      qdd(Eigen::VectorXd::Zero(model.nv())),
      mass_factor(Eigen::MatrixXd::Zero(model.nv(), model.nv())),
      body_path(static_cast<std::size_t>(model.num_bodies()), 0),
      com(Eigen::Vector3d::Zero()),
      com_jacobian(Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, model.nv())) {}

}  // namespace cairn::multibody
