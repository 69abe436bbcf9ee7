#include <cairn/common/number_text.h>
#include <cairn/multibody/kinematics.h>

#include <stdexcept>
#include <string>

#include <cairn/multibody/joint_motion.h>

namespace cairn::multibody {

void CheckSizes(const Model& model, const Data& data, const char* caller, Eigen::Index q_size, Eigen::Index v_size,
                Eigen::Index a_size) {
  if (data.nq != model.nq() || data.nv != model.nv() || static_cast<int>(data.X_world.size()) != model.num_bodies()) {
    throw std::invalid_argument(std::string(caller) + ": the Data was made for another model (nq " +
                                cairn::FormatShort(data.nq) + ", nv " + cairn::FormatShort(data.nv) + ") than '" +
                                model.name() + "' (nq " + cairn::FormatShort(model.nq()) + ", nv " +
                                cairn::FormatShort(model.nv()) + "); create it with Data(model)");
  }
  if (q_size != model.nq()) {
    throw std::invalid_argument(std::string(caller) + ": q has size " + cairn::FormatShort(q_size) + " but model '" +
                                model.name() + "' has nq = " + cairn::FormatShort(model.nq()));
  }
  if (v_size >= 0 && v_size != model.nv()) {
    throw std::invalid_argument(std::string(caller) + ": v has size " + cairn::FormatShort(v_size) + " but model '" +
                                model.name() + "' has nv = " + cairn::FormatShort(model.nv()));
  }
  if (a_size >= 0 && a_size != model.nv()) {
    throw std::invalid_argument(std::string(caller) + ": the acceleration/torque vector has size " +
                                cairn::FormatShort(a_size) + " but model '" + model.name() +
                                "' has nv = " + cairn::FormatShort(model.nv()));
  }
}

void ForwardKinematics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  CheckSizes(model, data, "ForwardKinematics", q.size());
  const int n = model.num_bodies();
  data.X_world[0] = Pose();
  for (int i = 1; i < n; ++i) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(i)];
    const std::size_t ui = static_cast<std::size_t>(i);
    data.X_parent[ui] = internal::JointTransform(joint, q.data() + joint.idx_q);
    data.X_world[ui] = data.X_world[static_cast<std::size_t>(joint.parent)] * data.X_parent[ui];
  }
}

void ForwardKinematics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                       const Eigen::Ref<const Eigen::VectorXd>& v) {
  CheckSizes(model, data, "ForwardKinematics", q.size(), v.size());
  const int n = model.num_bodies();
  data.X_world[0] = Pose();
  data.v[0].setZero();
  for (int i = 1; i < n; ++i) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(i)];
    const std::size_t ui = static_cast<std::size_t>(i);
    const std::size_t up = static_cast<std::size_t>(joint.parent);
    data.X_parent[ui] = internal::JointTransform(joint, q.data() + joint.idx_q);
    data.X_world[ui] = data.X_world[up] * data.X_parent[ui];
    data.v[ui] =
        data.X_parent[ui].InverseActMotion(data.v[up]) + internal::ApplyMotionSubspace(joint, v.data() + joint.idx_v);
  }
}

void ForwardKinematics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                       const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& a) {
  CheckSizes(model, data, "ForwardKinematics", q.size(), v.size(), a.size());
  const int n = model.num_bodies();
  data.X_world[0] = Pose();
  data.v[0].setZero();
  data.a[0].setZero();
  for (int i = 1; i < n; ++i) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(i)];
    const std::size_t ui = static_cast<std::size_t>(i);
    const std::size_t up = static_cast<std::size_t>(joint.parent);
    data.X_parent[ui] = internal::JointTransform(joint, q.data() + joint.idx_q);
    data.X_world[ui] = data.X_world[up] * data.X_parent[ui];
    const Vector6d vj = internal::ApplyMotionSubspace(joint, v.data() + joint.idx_v);
    data.v[ui] = data.X_parent[ui].InverseActMotion(data.v[up]) + vj;
    data.a[ui] = data.X_parent[ui].InverseActMotion(data.a[up]) +
                 internal::ApplyMotionSubspace(joint, a.data() + joint.idx_v) + CrossMotion(data.v[ui], vj);
  }
}

Pose FramePose(const Model& model, const Data& data, int frame) {
  if (frame < 0 || frame >= model.num_frames()) {
    throw std::invalid_argument("FramePose: frame index " + cairn::FormatShort(frame) + " is out of range [0, " +
                                cairn::FormatShort(model.num_frames()) + "); look frames up with Model::GetFrameIndex");
  }
  const Frame& f = model.frames()[static_cast<std::size_t>(frame)];
  return data.X_world[static_cast<std::size_t>(f.body)] * f.X_BF;
}

Vector6d FrameVelocity(const Model& model, const Data& data, int frame) {
  if (frame < 0 || frame >= model.num_frames()) {
    throw std::invalid_argument("FrameVelocity: frame index " + cairn::FormatShort(frame) + " is out of range [0, " +
                                cairn::FormatShort(model.num_frames()) + "); look frames up with Model::GetFrameIndex");
  }
  const Frame& f = model.frames()[static_cast<std::size_t>(frame)];
  return f.X_BF.InverseActMotion(data.v[static_cast<std::size_t>(f.body)]);
}

}  // namespace cairn::multibody
