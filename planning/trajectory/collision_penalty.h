#pragma once

#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/collision_world.h>
#include <cairn/multibody/model.h>
#include <cairn/multibody/pose.h>
#include <cairn/optimization/evaluator.h>
#include <cairn/planning/trajectory/configuration_chart.h>

namespace cairn::planning {

/// A fixed box of the environment (an obstacle, a bar, a step), full side lengths at pose X_WB.
struct EnvironmentBox {
  std::string name;                                   ///< unique among the environment's boxes
  Eigen::Vector3d size{Eigen::Vector3d::Zero()};      ///< full side lengths, m (each > 0)
  multibody::Pose X_WB;                               ///< pose of the box centre
};

/// The hinge collision penalty of one configuration (thesis f_collision in eq. 2.9a, trajopt's discrete
/// collision cost): sum over pairs of (m - d)_+^2, where d is the signed distance and m the pair's margin:
/// d_safe between a robot geometry and an environment box, `self_margin` between two robot geometries that
/// CollisionWorld checks (not the same or adjacent bodies). Geometries of `contact_bodies` are not checked
/// against the environment (they touch it on purpose). Robot pairs already closer than self_margin in the
/// model's neutral configuration (e.g. a forearm and its hand across the wrist links) are excluded, as an SRDF's
/// "always close" list would: the penalty could not separate them, only distort the posture. The penalty is
/// C^1: its gradient -2 (m - d) grad d vanishes continuously at d = m (where d itself is smooth: parallel box
/// faces have no unique witness points).
///
/// The configuration is a waypoint q (inputs: nq) or, with `fraction` in (0, 1), the point between two waypoints
/// (inputs: [q_a; q_b], 2 nq): q = (1 - fraction) q_a + fraction q_b, the quaternion renormalised. Samples
/// between knots keep a swing foot from passing through an edge where no waypoint looks.
///
/// Thread safety: the collision world is placed by every call, so calls hold a mutex; results do not depend on
/// the order of calls.
class CollisionPenalty final : public optimization::Evaluator {
 public:
  /// self_margin = 0 disables robot-robot pairs. Throws std::invalid_argument for a non-positive or
  /// non-finite d_safe, a negative or non-finite self_margin, a fraction outside [0, 1), a box with a
  /// non-positive side, or an unknown contact body.
  CollisionPenalty(const std::string& name, std::shared_ptr<const multibody::Model> model,
                   const std::vector<EnvironmentBox>& environment, const std::vector<std::string>& contact_bodies,
                   double d_safe, double self_margin, double fraction = 0.0);
  ~CollisionPenalty() override;

  /// Every checked pair closer than its margin at x (a waypoint or a sample as the inputs), for reports.
  std::vector<multibody::CollisionPair> PairsWithinMargin(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// The smallest signed distance between the robot (less its contact bodies) and the environment at x, and the
  /// pair's geometry names in `which` (infinity and "" when nothing is within 10 * d_safe).
  double MinimumEnvironmentDistance(const Eigen::Ref<const Eigen::VectorXd>& x, std::string* which = nullptr) const;

  /// d_safe, m.
  double d_safe() const { return d_safe_; }

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;

  Eigen::VectorXd Configuration(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // Checked pairs closer than their margin (times `scale`), with that margin.
  std::vector<std::pair<multibody::CollisionPair, double>> Pairs(const Eigen::VectorXd& q, multibody::Data* data,
                                                                 double scale = 1.0) const;

  std::shared_ptr<const multibody::Model> model_;
  ConfigurationChart chart_;
  double d_safe_;
  double self_margin_;
  double fraction_;
  bool sample_;
  std::set<int> contact_bodies_;
  mutable std::mutex mutex_;
  mutable multibody::CollisionWorld world_;
};

}  // namespace cairn::planning
