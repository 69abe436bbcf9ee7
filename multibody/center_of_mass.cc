#include <cairn/multibody/center_of_mass.h>

#include <stdexcept>

#include <cairn/multibody/joint_motion.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::multibody {

namespace internal {

void ComputeSubtreeMassesAndMotion(const Model& model, Data& data) {
  const int n = model.num_bodies();
  for (int i = 0; i < n; ++i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    const SpatialInertia& I = model.bodies()[ui].inertia;
    const Pose& X = data.X_world[ui];
    data.subtree_mass[ui] = I.mass();
    data.subtree_first_moment[ui] = X.rotation() * I.first_moment() + I.mass() * X.translation();
  }
  for (int i = n - 1; i > 0; --i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    const std::size_t up = static_cast<std::size_t>(model.parent(i));
    data.subtree_mass[up] += data.subtree_mass[ui];
    data.subtree_first_moment[up] += data.subtree_first_moment[ui];
    const Joint& joint = model.joints()[ui];
    for (int k = 0; k < joint.nv; ++k) {
      data.joint_motion_world.col(joint.idx_v + k) = data.X_world[ui].ActMotion(MotionSubspaceColumn(joint, k));
    }
  }
}

}  // namespace internal

const Eigen::Vector3d& CenterOfMass(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  ForwardKinematics(model, data, q);
  internal::ComputeSubtreeMassesAndMotion(model, data);
  if (!(data.subtree_mass[0] > 0.0)) {
    throw std::runtime_error("CenterOfMass: model '" + model.name() +
                             "' has zero total mass, so it has no centre of mass; give its links <inertial> data");
  }
  data.com = data.subtree_first_moment[0] / data.subtree_mass[0];
  return data.com;
}

const Eigen::Matrix<double, 3, Eigen::Dynamic>& CenterOfMassJacobian(const Model& model, Data& data,
                                                                     const Eigen::Ref<const Eigen::VectorXd>& q) {
  CenterOfMass(model, data, q);
  const double total = data.subtree_mass[0];
  for (int iv = 0; iv < model.nv(); ++iv) {
    const std::size_t body = static_cast<std::size_t>(model.velocity_joint(iv));
    const auto s = data.joint_motion_world.col(iv);
    // A joint motion moves its whole subtree rigidly; the subtree's first moment changes at
    // m v0 + ω x h (velocity of every point p is v0 + ω x p).
    data.com_jacobian.col(iv) =
        (data.subtree_mass[body] * s.tail<3>() + s.head<3>().cross(data.subtree_first_moment[body])) / total;
  }
  return data.com_jacobian;
}

}  // namespace cairn::multibody
