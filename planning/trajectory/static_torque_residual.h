#pragma once

#include <memory>
#include <string>
#include <vector>

#include <cairn/planning/trajectory/waypoint_evaluator.h>

namespace cairn::planning {

/// A support of the robot at one waypoint: a contact frame and the share of the body weight it carries.
struct TorqueSupport {
  std::string frame;   ///< e.g. "l_sole"
  double share{1.0};   ///< in (0, 1]; the shares of one waypoint sum to 1
};

/// The static joint torques of thesis eqs. 2.10-2.11 for a floating-base robot standing on its feet, scaled
/// per joint: r_k = s_k tau_k for every revolute/prismatic joint k (1/2 |r|^2 is then the cost term).
///
/// Floating base and double support: eq. 2.11 sums J_i' m_i g over the links, which for a robot rooted at the
/// pelvis gives only the torques that hold each limb up from the pelvis, so a bent stance knee would look free.
/// Here the weight is carried by the supports: tau = g(q) - sum_c share_c J_c(q)' W(q), where g(q) are the
/// gravity torques of the pelvis-rooted tree (GravityTorques), J_c the spatial (world) Jacobian of support c and
/// W = [c(q) x f; f] the total gravity wrench (f = -M gravity through the centre of mass c). For a single
/// support this is exactly the torque of the chain from the supporting foot (the joint torques that hold the
/// rest of the robot up from the foot), and the six floating-base rows vanish identically, so only the joint
/// rows are kept. In double support the weight is split in fixed shares (the problem gives the whole weight to
/// the foot that carries the next single-support phase, and half to each foot in the final stance): every
/// convex split keeps the base rows at zero, i.e. it is a static equilibrium; the optimal split of the
/// thesis' trajopt implementation is not modelled.
///
/// Derivatives: dg/dq from GravityTorquesDerivative; d(S_k . W)/de_j = (S_j x S_k) . W + S_k,ang . (J_com,j x f)
/// for coordinates j that move joint k's axis (S are world motion subspaces).
class StaticTorqueResidual final : public WaypointEvaluator {
 public:
  /// `scale` has one entry per joint coordinate (ConfigurationChart::joint_coordinates order), typically
  /// 1 / effort limit. Throws std::invalid_argument for an unknown frame, a share outside (0, 1], shares that do
  /// not sum to 1 (within 1e-9), no supports, or a scale of the wrong size or with an entry that is not finite and positive.
  StaticTorqueResidual(std::shared_ptr<const multibody::Model> model, const std::vector<TorqueSupport>& supports,
                       const Eigen::VectorXd& scale);

  /// The unscaled joint torques tau at q (joint_coordinates order), for reports.
  Eigen::VectorXd JointTorques(const Eigen::Ref<const Eigen::VectorXd>& q) const;

 private:
  void EvalTangent(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> y, Eigen::MatrixXd* J_v) const override;

  std::vector<int> frames_;
  std::vector<double> shares_;
  // Per support, per velocity coordinate k: does joint k lie on the chain from the root to the support's body.
  std::vector<std::vector<char>> carries_support_;
  // (k, j): does coordinate j's joint move joint k's axis (is it an ancestor of, or, joint k).
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> moves_axis_;
  Eigen::VectorXd scale_;
};

}  // namespace cairn::planning
