#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>

namespace cairn::multibody {

/// Joint-space PD position control, tau_i = kp_i (q_ref,i - q_i) + kd_i (v_ref,i - v_i), saturated at the
/// URDF's effort limit of each joint (+-effort_limit; unlimited joints are not clamped). Floating-base entries of
/// tau are zero: the base is not actuated. Gains come per joint group from the robot's control YAML
/// (data/robots/README.md, "cairn_humanoid_control.yaml").
class JointPdController {
 public:
  /// Gains per velocity coordinate (size nv; zero on the floating base). Throws std::invalid_argument when a size
  /// is wrong or a gain is negative or not finite.
  JointPdController(const Model& model, const Eigen::VectorXd& kp, const Eigen::VectorXd& kd);

  /// Reads the `gains` of a control YAML: a mapping of group name to {joints: [...], kp: N m/rad, kd: N m s/rad}
  /// that must cover every moving joint of `model` exactly once. Throws std::invalid_argument naming the file, the
  /// line and the key on a mistake (unknown or repeated joint, a joint in no group, a negative or non-finite gain).
  static JointPdController Load(const Model& model, const std::string& yaml_path);

  /// Proportional gains per velocity coordinate.
  const Eigen::VectorXd& kp() const { return kp_; }
  /// Derivative gains per velocity coordinate.
  const Eigen::VectorXd& kd() const { return kd_; }
  /// Effort limits per velocity coordinate (+inf where unlimited; 0 on the floating base).
  const Eigen::VectorXd& effort_limits() const { return effort_; }

  /// The saturated torques (size nv) for state (q, v) and reference (q_ref, v_ref); q and q_ref of size nq (the
  /// floating base part is ignored). Throws std::invalid_argument on a size mismatch or a non-finite entry.
  Eigen::VectorXd Torques(const Eigen::Ref<const Eigen::VectorXd>& q, const Eigen::Ref<const Eigen::VectorXd>& v,
                          const Eigen::Ref<const Eigen::VectorXd>& q_ref,
                          const Eigen::Ref<const Eigen::VectorXd>& v_ref) const;
  /// As above with a feedforward torque (size nv) added to the PD torque before saturation.
  Eigen::VectorXd Torques(const Eigen::Ref<const Eigen::VectorXd>& q, const Eigen::Ref<const Eigen::VectorXd>& v,
                          const Eigen::Ref<const Eigen::VectorXd>& q_ref, const Eigen::Ref<const Eigen::VectorXd>& v_ref,
                          const Eigen::Ref<const Eigen::VectorXd>& feedforward) const;

 private:
  int nq_ = 0;
  int nv_ = 0;
  Eigen::VectorXd kp_;
  Eigen::VectorXd kd_;
  Eigen::VectorXd effort_;
  // Configuration index of each velocity coordinate's joint angle (-1 for the floating base).
  std::vector<int> q_index_;
};

}  // namespace cairn::multibody
