#include <cairn/multibody/plant/joint_pd_controller.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "cairn/common/internal/yaml_reader.h"
#include <cairn/common/number_text.h>

namespace cairn::multibody {
namespace {

void CheckVector(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Index size, const std::string& what) {
  if (x.size() != size) {
    throw std::invalid_argument("JointPdController: " + what + " has size " + FormatShort(x.size()) +
                                ", but the model needs " + FormatShort(size));
  }
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw std::invalid_argument("JointPdController: " + what + "[" + FormatShort(i) + "] is " + FormatShort(x[i]) +
                                  "; every entry must be finite");
    }
  }
}

}  // namespace

JointPdController::JointPdController(const Model& model, const Eigen::VectorXd& kp, const Eigen::VectorXd& kd)
    : nq_(model.nq()), nv_(model.nv()), kp_(kp), kd_(kd), effort_(Eigen::VectorXd::Zero(model.nv())),
      q_index_(static_cast<std::size_t>(model.nv()), -1) {
  CheckVector(kp, model.nv(), "kp");
  CheckVector(kd, model.nv(), "kd");
  for (int j = 1; j < model.num_bodies(); ++j) {
    const Joint& joint = model.joint(j);
    if (joint.type == JointType::kFloating) {
      kp_.segment(joint.idx_v, joint.nv).setZero();
      kd_.segment(joint.idx_v, joint.nv).setZero();
      continue;
    }
    for (int k = 0; k < joint.nv; ++k) {
      const int iv = joint.idx_v + k;
      if (kp_[iv] < 0.0 || kd_[iv] < 0.0) {
        throw std::invalid_argument("JointPdController: joint '" + joint.name + "' has kp " + FormatShort(kp_[iv]) +
                                    " and kd " + FormatShort(kd_[iv]) + "; gains must be >= 0");
      }
      effort_[iv] = joint.effort_limit;
      q_index_[static_cast<std::size_t>(iv)] = joint.idx_q + k;
    }
  }
}

JointPdController JointPdController::Load(const Model& model, const std::string& yaml_path) {
  const internal::YamlReader yaml(yaml_path);
  const YAML::Node gains = yaml.Require(yaml.root(), "gains", "the control file");
  if (!gains.IsMap()) yaml.Fail(gains, "'gains' must be a mapping of joint groups to {joints, kp, kd}");
  Eigen::VectorXd kp = Eigen::VectorXd::Zero(model.nv());
  Eigen::VectorXd kd = Eigen::VectorXd::Zero(model.nv());
  std::map<std::string, std::string> group_of_joint;
  for (const auto& entry : gains) {
    const std::string group = yaml.AsString(entry.first, "gains");
    const YAML::Node& node = entry.second;
    const std::string where = "gains." + group;
    yaml.CheckKeys(node, {"joints", "kp", "kd"}, where);
    const double group_kp = yaml.Number(node, "kp", where);
    const double group_kd = yaml.Number(node, "kd", where);
    if (group_kp < 0.0 || group_kd < 0.0) {
      yaml.Fail(node, where + " has kp " + FormatShort(group_kp) + " and kd " + FormatShort(group_kd) +
                          "; gains must be >= 0");
    }
    const YAML::Node joints = yaml.Require(node, "joints", where);
    for (const std::string& name : yaml.Strings(joints, where + ".joints")) {
      if (!model.HasJoint(name)) {
        yaml.Fail(joints, where + ".joints names '" + name + "', which is not a joint of '" + model.name() + "'");
      }
      const Joint& joint = model.joint(model.GetJointIndex(name));
      if (joint.nv == 0 || joint.type == JointType::kFloating) {
        yaml.Fail(joints, where + ".joints names '" + name + "', which is not an actuated (revolute or prismatic) joint");
      }
      const auto [it, inserted] = group_of_joint.emplace(name, group);
      if (!inserted) {
        yaml.Fail(joints, "joint '" + name + "' is in both gains." + it->second + " and " + where);
      }
      kp[joint.idx_v] = group_kp;
      kd[joint.idx_v] = group_kd;
    }
  }
  for (int j = 1; j < model.num_bodies(); ++j) {
    const Joint& joint = model.joint(j);
    if (joint.nv == 0 || joint.type == JointType::kFloating) continue;
    if (group_of_joint.count(joint.name) == 0) {
      yaml.Fail(gains, "joint '" + joint.name + "' of '" + model.name() + "' is in no group of 'gains'; every "
                       "actuated joint needs gains");
    }
  }
  return JointPdController(model, kp, kd);
}

Eigen::VectorXd JointPdController::Torques(const Eigen::Ref<const Eigen::VectorXd>& q,
                                           const Eigen::Ref<const Eigen::VectorXd>& v,
                                           const Eigen::Ref<const Eigen::VectorXd>& q_ref,
                                           const Eigen::Ref<const Eigen::VectorXd>& v_ref) const {
  return Torques(q, v, q_ref, v_ref, Eigen::VectorXd::Zero(nv_));
}

Eigen::VectorXd JointPdController::Torques(const Eigen::Ref<const Eigen::VectorXd>& q,
                                           const Eigen::Ref<const Eigen::VectorXd>& v,
                                           const Eigen::Ref<const Eigen::VectorXd>& q_ref,
                                           const Eigen::Ref<const Eigen::VectorXd>& v_ref,
                                           const Eigen::Ref<const Eigen::VectorXd>& feedforward) const {
  CheckVector(feedforward, nv_, "feedforward");
  CheckVector(q, nq_, "q");
  CheckVector(v, nv_, "v");
  CheckVector(q_ref, nq_, "q_ref");
  CheckVector(v_ref, nv_, "v_ref");
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(nv_);
  for (int iv = 0; iv < nv_; ++iv) {
    const int iq = q_index_[static_cast<std::size_t>(iv)];
    if (iq < 0) continue;
    const double t = kp_[iv] * (q_ref[iq] - q[iq]) + kd_[iv] * (v_ref[iv] - v[iv]) + feedforward[iv];
    tau[iv] = std::clamp(t, -effort_[iv], effort_[iv]);
  }
  return tau;
}

}  // namespace cairn::multibody
