#pragma once

#include <limits>
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
#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/trajectory/configuration_chart.h>

namespace cairn::planning {

/// A fixed box of the environment (an obstacle, a bar, a step), full side lengths at pose X_WB.
struct EnvironmentBox {
  std::string name;                                   ///< unique among the environment's boxes
  Eigen::Vector3d size{Eigen::Vector3d::Zero()};      ///< full side lengths, m (each > 0)
  multibody::Pose X_WB;                               ///< pose of the box centre
  /// Probability that the box is there, in (0, 1]: 1 for a certain obstacle, an occupancy cell's probability for
  /// perceived space (EnvironmentFromTerrain). The penalty of a pair with this box is weighted by it, so the
  /// collision term is the expected hinge penalty under the occupancy grid's independent cells.
  double probability{1.0};
};

/// The hinge collision penalty of one configuration (thesis f_collision in eq. 2.9a, trajopt's discrete
/// collision cost): sum over pairs of w (m - d)_+^2, where d is the signed distance, w the environment box's
/// probability (1 between robot geometries and for certain boxes) and m the pair's margin:
/// d_safe between a robot geometry and an environment box, `self_margin` between two robot geometries that
/// CollisionWorld checks (not the same or adjacent bodies, and not two boxes: a box pair's distance has no
/// gradient where faces are parallel, which stalls the solver). Geometries of `contact_bodies` are not checked
/// against the environment (they touch it on purpose). Robot pairs already closer than self_margin in the
/// model's neutral configuration (e.g. a forearm and its hand across the wrist links) are excluded, as an SRDF's
/// "always close" list would: the penalty could not separate them, only distort the posture. The penalty is
/// C^1: its gradient -2 (m - d) grad d vanishes continuously at d = m (where d itself is smooth: parallel box
/// faces have no unique witness points).
///
/// The ground (a horizontal plane at `ground_height`, NaN for none) is handled in closed form rather than as a
/// box: each robot shape not in contact contributes (d_safe - d_p)_+^2 for each of its support points p (a
/// box's 8 corners, a sphere's centre, a capsule's two cap centres; meshes are skipped) with d_p its height
/// above the plane less its radius. A sole hovering parallel to the floor then has a smooth penalty, where the
/// box-to-box distance would switch between corners.
///
/// With a `ground_terrain` the ground follows the terrain instead: d_p is p's distance from the plane of the cell
/// under it (through the cell's ground point, with its normal; radius subtracted), so a swing foot keeps its
/// clearance from a slope or a stair tread and a sole tilted onto a slope is not pushed off it by a level floor.
/// The term is smooth within a cell and continuous across cells of one plane; at a step's edge it jumps (the
/// solver sees the edge through the samples between waypoints). Where the map has no cell or no ground under p,
/// the plane at ground_height applies (none if NaN).
///
/// The configuration is a waypoint q (inputs: nq) or, with `fraction` in (0, 1), the point between two waypoints
/// (inputs: [q_a; q_b], 2 nq): q = (1 - fraction) q_a + fraction q_b, the quaternion renormalised. Samples
/// between knots keep a swing foot from passing through an edge where no waypoint looks.
///
/// The Hessian is one of two (CollisionHessian): central differences of the analytic gradient (HessianByDifferences; across
/// the hinge's kink at d = m the one-sided curvature, as for any C^1 penalty) over the columns that move a body of
/// a term within its margin (none, and no work, when nothing is within its margin), or
/// the Gauss-Newton matrix 2 sum_p J_p' J_p over the pairs and ground points within their margin, J_p the
/// coordinate Jacobian of their distance: the penalty is a sum of squared hinges, so this drops only the
/// curvature of d itself (and of the quaternion chart), is positive semidefinite, and costs one gradient
/// evaluation instead of 2 nq.
///
/// Thread safety: the collision world is placed by every call, so calls hold a mutex; results do not depend on
/// the order of calls.
/// How CollisionPenalty forms its Hessian (see the class comment).
enum class CollisionHessian {
  kDifferences,  ///< central differences of the analytic gradient: the Hessian to about 1e-6 relative
  kGaussNewton,  ///< 2 sum_p J_p' J_p: the curvature of the distances dropped
};

class CollisionPenalty final : public optimization::Evaluator {
 public:
  /// self_margin = 0 disables robot-robot pairs. Throws std::invalid_argument for a non-positive or
  /// non-finite d_safe, a negative or non-finite self_margin, a fraction outside [0, 1), a box with a
  /// non-positive side, or an unknown contact body.
  CollisionPenalty(const std::string& name, std::shared_ptr<const multibody::Model> model,
                   const std::vector<EnvironmentBox>& environment, const std::vector<std::string>& contact_bodies,
                   double d_safe, double self_margin, double fraction = 0.0,
                   double ground_height = std::numeric_limits<double>::quiet_NaN(),
                   CollisionHessian hessian = CollisionHessian::kDifferences,
                   std::shared_ptr<const TerrainMap> ground_terrain = nullptr);
  ~CollisionPenalty() override;

  /// Every checked pair closer than its margin at x (a waypoint or a sample as the inputs), for reports.
  std::vector<multibody::CollisionPair> PairsWithinMargin(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// The smallest signed distance between the robot (less its contact bodies) and the environment (boxes and
  /// ground) at x, and the pair's geometry names in `which` (infinity and "" when nothing is within 10 * d_safe).
  double MinimumEnvironmentDistance(const Eigen::Ref<const Eigen::VectorXd>& x, std::string* which = nullptr) const;

  /// d_safe, m.
  double d_safe() const { return d_safe_; }

 private:
  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;

  Eigen::VectorXd Configuration(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // A checked pair closer than its margin, with that margin and its weight (the environment box's probability).
  struct WeightedPair {
    multibody::CollisionPair pair;
    double margin;
    double weight;
  };
  // Checked pairs closer than their margin (times `scale`).
  std::vector<WeightedPair> Pairs(const Eigen::VectorXd& q, multibody::Data* data, double scale = 1.0) const;

  // A support point of a robot shape for the ground term: body, position in the body, radius, geometry name.
  struct GroundPoint {
    int body;
    Eigen::Vector3d p_B;
    double radius;
    std::string name;
  };
  // Ground term at q (poses in data); adds its gradient (tangent) if gradient is not null.
  double GroundPenalty(const multibody::Data& data, Eigen::VectorXd* gradient) const;
  // The clearance of a support point at p_W with `radius` from the ground under it, and in *normal the ground's
  // normal there (the clearance's gradient with respect to p_W); infinity where there is no ground.
  double Clearance(const Eigen::Vector3d& p_W, double radius, Eigen::Vector3d* normal) const;
  // d(normal . p_W)/dv (tangent) for a point p_W fixed to `body`.
  void ClearanceGradient(const multibody::Data& data, int body, const Eigen::Vector3d& p_W,
                         const Eigen::Vector3d& normal, Eigen::Ref<Eigen::VectorXd> gradient) const;
  // The Gauss-Newton Hessian of the penalty with respect to the evaluator's raw configuration point q_raw (a
  // waypoint, or a sample's blended point), nq x nq.
  Eigen::MatrixXd GaussNewtonHessian(const Eigen::VectorXd& q_raw) const;
  double GroundDistance(const multibody::Data& data, std::string* which) const;
  // The q columns (sorted) that move a robot body of a pair or ground point within its margin at q (normalised).
  std::vector<int> ActiveColumns(const Eigen::VectorXd& q) const;

  std::shared_ptr<const multibody::Model> model_;
  ConfigurationChart chart_;
  double ground_height_;
  std::shared_ptr<const TerrainMap> ground_terrain_;
  std::vector<GroundPoint> ground_points_;
  double d_safe_;
  double self_margin_;
  double fraction_;
  bool sample_;
  CollisionHessian hessian_;
  std::set<int> contact_bodies_;
  std::set<std::pair<int, int>> self_box_pairs_;  // robot box-box pairs, left out (see the class comment)
  std::vector<double> geometry_weight_;           // per world geometry: 1 for the robot, the box's probability
  mutable std::mutex mutex_;
  mutable multibody::CollisionWorld world_;
};

}  // namespace cairn::planning
