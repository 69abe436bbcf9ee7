#include <cairn/common/number_text.h>
#include <cairn/multibody/dynamics.h>

#include <stdexcept>
#include <string>

#include <cairn/multibody/joint_motion.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::multibody {

const Eigen::VectorXd& InverseDynamics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                                       const Eigen::Ref<const Eigen::VectorXd>& v,
                                       const Eigen::Ref<const Eigen::VectorXd>& a) {
  CheckSizes(model, data, "InverseDynamics", q.size(), v.size(), a.size());
  const int n = model.num_bodies();
  data.X_world[0] = Pose();
  data.v[0].setZero();
  // Gravity enters as an upward acceleration of the world (Featherstone's trick), so no body needs a
  // separate gravity force.
  data.a[0].head<3>().setZero();
  data.a[0].tail<3>() = -model.gravity();
  data.f[0].setZero();
  for (int i = 1; i < n; ++i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    const Joint& joint = model.joints()[ui];
    const std::size_t up = static_cast<std::size_t>(joint.parent);
    const Pose& X = data.X_parent[ui] = internal::JointTransform(joint, q.data() + joint.idx_q);
    data.X_world[ui] = data.X_world[up] * X;
    const Vector6d vj = internal::ApplyMotionSubspace(joint, v.data() + joint.idx_v);
    data.v[ui] = X.InverseActMotion(data.v[up]) + vj;
    data.a[ui] = X.InverseActMotion(data.a[up]) + internal::ApplyMotionSubspace(joint, a.data() + joint.idx_v) +
                 CrossMotion(data.v[ui], vj);
    const SpatialInertia& I = model.bodies()[ui].inertia;
    data.f[ui] = I.Apply(data.a[ui]) + CrossForce(data.v[ui], I.Apply(data.v[ui]));
  }
  for (int i = n - 1; i > 0; --i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    const Joint& joint = model.joints()[ui];
    internal::ApplyMotionSubspaceTranspose(joint, data.f[ui], data.tau.data() + joint.idx_v);
    data.f[static_cast<std::size_t>(joint.parent)] += data.X_parent[ui].ActForce(data.f[ui]);
  }
  return data.tau;
}

namespace {

// CRBA in the world frame (as Pinocchio does): with every inertia and motion subspace expressed in the world,
// composite inertias add without transforms and each entry M(r, c) is one 6-vector dot product. Needs
// data.X_world.
void MassMatrixFromPoses(const Model& model, Data& data) {
  const int n = model.num_bodies();
  data.composite_inertia[0] = SpatialInertia();
  for (int i = 1; i < n; ++i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    const Joint& joint = model.joints()[ui];
    const Pose& X = data.X_world[ui];
    data.composite_inertia[ui] = model.bodies()[ui].inertia.Transformed(X);
    for (int k = 0; k < joint.nv; ++k) {
      data.joint_motion_world.col(joint.idx_v + k) = X.ActMotion(internal::MotionSubspaceColumn(joint, k));
    }
  }
  for (int i = n - 1; i > 0; --i) {
    data.composite_inertia[static_cast<std::size_t>(model.parent(i))] +=
        data.composite_inertia[static_cast<std::size_t>(i)];
  }
  Eigen::MatrixXd& M = data.M;
  for (int c = 0; c < model.nv(); ++c) {
    const Vector6d F =
        data.composite_inertia[static_cast<std::size_t>(model.velocity_joint(c))].Apply(data.joint_motion_world.col(c));
    for (int r = c; r >= 0; r = model.velocity_parent(r)) {
      const double value = data.joint_motion_world.col(r).dot(F);
      M(r, c) = value;
      M(c, r) = value;
    }
  }
}

}  // namespace

const Eigen::MatrixXd& MassMatrix(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  CheckSizes(model, data, "MassMatrix", q.size());
  ForwardKinematics(model, data, q);
  MassMatrixFromPoses(model, data);
  return data.M;
}

const Eigen::VectorXd& ForwardDynamics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                                       const Eigen::Ref<const Eigen::VectorXd>& v,
                                       const Eigen::Ref<const Eigen::VectorXd>& tau) {
  CheckSizes(model, data, "ForwardDynamics", q.size(), v.size(), tau.size());
  data.qdd.setZero();
  data.nonlinear_effects = InverseDynamics(model, data, q, v, data.qdd);
  MassMatrixFromPoses(model, data);  // reuses the poses InverseDynamics just computed
  // Sparse L^T D L factorization along the tree (Featherstone, RBDA 6.5): M(k, i) is nonzero only when i is on
  // k's path to the root, so the cost is sum(depth^2) instead of nv^3 / 3, and there is no fill-in.
  Eigen::MatrixXd& H = data.mass_factor;
  H = data.M;
  const int nv = model.nv();
  for (int k = nv - 1; k >= 0; --k) {
    if (!(H(k, k) > 0.0)) {
      throw std::runtime_error("ForwardDynamics: the mass matrix of model '" + model.name() +
                               "' is not positive definite (velocity " + cairn::FormatShort(k) + ", joint '" +
                               model.joint(model.velocity_joint(k)).name +
                               "'); every moving joint must carry a body with mass");
    }
    for (int i = model.velocity_parent(k); i >= 0; i = model.velocity_parent(i)) {
      const double a = H(k, i) / H(k, k);
      for (int j = i; j >= 0; j = model.velocity_parent(j)) H(i, j) -= a * H(k, j);
      H(k, i) = a;
    }
  }
  Eigen::VectorXd& x = data.qdd;
  x = tau - data.nonlinear_effects;
  for (int i = nv - 1; i >= 0; --i) {
    for (int j = model.velocity_parent(i); j >= 0; j = model.velocity_parent(j)) x[j] -= H(i, j) * x[i];
  }
  for (int i = 0; i < nv; ++i) x[i] /= H(i, i);
  for (int i = 0; i < nv; ++i) {
    for (int j = model.velocity_parent(i); j >= 0; j = model.velocity_parent(j)) x[i] -= H(i, j) * x[j];
  }
  return x;
}

double KineticEnergy(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                     const Eigen::Ref<const Eigen::VectorXd>& v) {
  ForwardKinematics(model, data, q, v);
  double energy = 0.0;
  for (int i = 1; i < model.num_bodies(); ++i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    energy += 0.5 * data.v[ui].dot(model.bodies()[ui].inertia.Apply(data.v[ui]));
  }
  return energy;
}

double PotentialEnergy(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  ForwardKinematics(model, data, q);
  double energy = 0.0;
  for (int i = 1; i < model.num_bodies(); ++i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    const SpatialInertia& I = model.bodies()[ui].inertia;
    const Pose& X = data.X_world[ui];
    energy -= model.gravity().dot(X.rotation() * I.first_moment() + I.mass() * X.translation());
  }
  return energy;
}

Vector6d CentroidalMomentum(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& v) {
  ForwardKinematics(model, data, q, v);
  Vector6d h_O = Vector6d::Zero();
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  for (int i = 1; i < model.num_bodies(); ++i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    const SpatialInertia& I = model.bodies()[ui].inertia;
    const Pose& X = data.X_world[ui];
    h_O += X.ActForce(I.Apply(data.v[ui]));
    first_moment += X.rotation() * I.first_moment() + I.mass() * X.translation();
  }
  if (!(model.total_mass() > 0.0)) {
    throw std::runtime_error("CentroidalMomentum: model '" + model.name() + "' has zero total mass");
  }
  const Eigen::Vector3d com = first_moment / model.total_mass();
  Vector6d h_G;
  h_G.head<3>() = h_O.head<3>() - com.cross(h_O.tail<3>());
  h_G.tail<3>() = h_O.tail<3>();
  return h_G;
}

}  // namespace cairn::multibody
