#include <cairn/multibody/gravity_torques.h>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::multibody {
namespace {

// For velocity coordinate iv (joint body j, world motion s = [w; v0] about the world origin): the rate of change
// of the first moment of j's subtree when the subtree moves with s.
Eigen::Vector3d SubtreeMomentRate(const Data& data, int body, const Eigen::Vector3d& w, const Eigen::Vector3d& v0) {
  const std::size_t ub = static_cast<std::size_t>(body);
  return data.subtree_mass[ub] * v0 + w.cross(data.subtree_first_moment[ub]);
}

}  // namespace

const Eigen::VectorXd& GravityTorques(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  ForwardKinematics(model, data, q);
  internal::ComputeSubtreeMassesAndMotion(model, data);
  const Eigen::Vector3d& g = model.gravity();
  for (int iv = 0; iv < model.nv(); ++iv) {
    const auto s = data.joint_motion_world.col(iv);
    // Power of the gravity wrench on the subtree along s; holding torque is its negative.
    data.gravity_torques[iv] = -g.dot(SubtreeMomentRate(data, model.velocity_joint(iv), s.head<3>(), s.tail<3>()));
  }
  return data.gravity_torques;
}

const Eigen::MatrixXd& GravityTorquesDerivative(const Model& model, Data& data,
                                                const Eigen::Ref<const Eigen::VectorXd>& q) {
  GravityTorques(model, data, q);
  const Eigen::Vector3d& g = model.gravity();
  const int nv = model.nv();
  Eigen::MatrixXd& D = data.gravity_torques_derivative;
  for (int k = 0; k < nv; ++k) {
    const int body_k = model.velocity_joint(k);
    const Eigen::Vector3d wk = data.joint_motion_world.col(k).head<3>();
    const Eigen::Vector3d vk = data.joint_motion_world.col(k).tail<3>();
    const Eigen::Vector3d moment_rate_k = SubtreeMomentRate(data, body_k, wk, vk);
    for (int l = 0; l < nv; ++l) {
      const int body_l = model.velocity_joint(l);
      const Eigen::Vector3d wl = data.joint_motion_world.col(l).head<3>();
      const Eigen::Vector3d vl = data.joint_motion_world.col(l).tail<3>();
      if (model.IsAncestorOrSelf(body_k, body_l)) {
        // Joint k carries joint l and l's whole subtree: both l's axis (s_k x s_l) and the subtree move.
        const Eigen::Vector3d dw = wk.cross(wl);
        const Eigen::Vector3d dv = wk.cross(vl) + vk.cross(wl);
        const std::size_t ul = static_cast<std::size_t>(body_l);
        const Eigen::Vector3d dh = SubtreeMomentRate(data, body_l, wk, vk);
        D(l, k) = -g.dot(data.subtree_mass[ul] * dv + dw.cross(data.subtree_first_moment[ul]) + wl.cross(dh));
      } else if (model.IsAncestorOrSelf(body_l, body_k)) {
        // Joint l's axis stays put; only the part of its subtree below joint k moves.
        D(l, k) = -g.dot(wl.cross(moment_rate_k));
      } else {
        D(l, k) = 0.0;
      }
    }
  }
  return D;
}

}  // namespace cairn::multibody
