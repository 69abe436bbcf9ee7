#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/optimization/mathematical_program.h>
#include <cairn/planning/trajectory/collision_penalty.h>
#include <cairn/planning/trajectory/configuration_chart.h>
#include <cairn/planning/trajectory/static_torque_residual.h>
#include <cairn/planning/trajectory/trajectory_optimizer_options.h>
#include <cairn/planning/trajectory/waypoint_spec.h>

namespace cairn::planning {

/// A violated group of rows of a TrajectoryProblem, for reports ("stance 3, l_sole position off by 0.21 m").
struct RowViolation {
  std::string label;    ///< e.g. "stance 3, l_sole position"
  double amount{0.0};   ///< norm of the group's row violations
  std::string unit;     ///< "m", "rad" or "" (normalised rows)
  /// The label with the amount, e.g. "stance 3, l_sole position off by 0.21 m".
  std::string ToString() const;
};

/// Problem (2.9) over a run of waypoints as one sparse MathematicalProgram (thesis 2.5.1b).
///
/// Variables: one block "q<t>" of nq coordinates per waypoint (t = the waypoint's index in the whole plan).
/// Costs: sum_t torque_weight |tau(q_t) / tau_max|^2 (StaticTorqueResidual as a least-squares cost) and
/// collision_weight times the hinge penalty (CollisionPenalty) at every waypoint and at samples_between points
/// between consecutive waypoints, plus the regularisers posture_weight |q_t|^2 and smoothness_weight
/// |q_{t+1} - q_t|^2 over the joint coordinates, and with base_rotation_smoothness_weight > 0 that weight times
/// |2 (quat_{t+1} - quat_t)|^2 over the floating base's quaternion (BaseRotationChange). Constraints per waypoint: the 6-D pose error of each contact (6 rows per
/// contact, = 0), the COM inside the support polygon (one row per edge, <= b - margin), the waist roll (= 0),
/// |quat|^2 = 1; between consecutive waypoints the joint speed limits |q_{t+1} - q_t| <= v_max (t_{t+1} - t_t)
/// (linear rows); joint limits are variable bounds. Every row block touches one waypoint's variables, or two for
/// speed limits and samples, so the Jacobian is block-banded; each evaluator declares its block's pattern once.
///
/// With `previous`, the problem starts from a fixed waypoint (the end of the previous window of a receding
/// horizon): its variables are bounded to its value, and only the speed limits and collision samples that link it
/// to the first free waypoint are added.
class TrajectoryProblem {
 public:
  /// A waypoint held fixed at the start of a window.
  struct FixedWaypoint {
    WaypointSpec spec;
    Eigen::VectorXd q;
  };

  /// `terrain` (may be null): the ground the collision terms keep links clear of, where it has a cell
  /// (CollisionPenalty's ground_terrain); elsewhere the plane at options.ground_height.
  ///
  /// Throws std::invalid_argument for a null model, no waypoints, options out of range, a model without the
  /// sole or waist frames, a non-increasing waypoint time, or a fixed waypoint of the wrong size.
  TrajectoryProblem(std::shared_ptr<const multibody::Model> model, std::vector<WaypointSpec> waypoints,
                    const std::vector<EnvironmentBox>& environment, const TrajectoryOptimizerOptions& options,
                    std::optional<FixedWaypoint> previous = std::nullopt,
                    std::shared_ptr<const TerrainMap> terrain = nullptr);

  /// The program.
  const optimization::MathematicalProgram& program() const { return prog_; }

  /// Number of free waypoints.
  int num_waypoints() const { return static_cast<int>(specs_.size()); }

  /// The spec of free waypoint i.
  const WaypointSpec& spec(int i) const { return specs_.at(static_cast<std::size_t>(i)); }

  /// The configuration of free waypoint i in the decision vector x (quaternion normalised).
  Eigen::VectorXd WaypointConfiguration(const Eigen::Ref<const Eigen::VectorXd>& x, int i) const;

  /// A decision vector from one configuration per free waypoint (the fixed waypoint, if any, is filled in).
  Eigen::VectorXd DecisionVector(const std::vector<Eigen::VectorXd>& configurations) const;

  /// Per-waypoint inverse kinematics (InverseKinematics): contacts on their targets, COM at the support
  /// polygon's centroid, zero waist roll, a bent-knee posture, the swing foot softly above the midpoint of its
  /// lift-off and landing poses. Configurations that IK cannot fully solve are still returned (the NLP decides).
  std::vector<Eigen::VectorXd> WarmStart() const;

  /// Every violated group of rows and bounds at x, largest first (those above `threshold`).
  std::vector<RowViolation> Violations(const Eigen::Ref<const Eigen::VectorXd>& x, double threshold) const;

  /// The smallest signed distance from a link not in contact to the environment at free waypoint i, with the
  /// pair's names.
  double MinimumClearance(const Eigen::Ref<const Eigen::VectorXd>& x, int i, std::string* which = nullptr) const;

  /// The same at the collision samples between waypoints (the smallest over all samples of the window).
  double MinimumSampleClearance(const Eigen::Ref<const Eigen::VectorXd>& x, std::string* which = nullptr) const;

  /// The unscaled static joint torques at free waypoint i (joint coordinate order of the chart).
  Eigen::VectorXd JointTorques(const Eigen::Ref<const Eigen::VectorXd>& x, int i) const;

  /// The torque term of free waypoint i at x: torque_weight |tau / tau_max|^2 (the cost of eq. 2.10 as weighted).
  double TorqueCost(const Eigen::Ref<const Eigen::VectorXd>& x, int i) const;

  /// Names of the q coordinates: "base_x", "base_y", "base_z", "base_qw".."base_qz", then the joints.
  const std::vector<std::string>& coordinate_names() const { return coordinate_names_; }

 private:
  struct LabeledConstraint {
    std::shared_ptr<optimization::Evaluator> function;
    optimization::DecisionVariables vars;
    Eigen::VectorXd lower;
    Eigen::VectorXd upper;
    std::vector<std::string> group;  // one label per row
    std::vector<std::string> unit;   // one unit per row
  };
  void AddLabeledConstraint(std::shared_ptr<optimization::Evaluator> function, const optimization::DecisionVariables& vars,
                            const Eigen::VectorXd& lower, const Eigen::VectorXd& upper, std::vector<std::string> group,
                            std::vector<std::string> unit);
  Eigen::VectorXd Gather(const Eigen::Ref<const Eigen::VectorXd>& x, const optimization::DecisionVariables& vars) const;

  std::shared_ptr<const multibody::Model> model_;
  ConfigurationChart chart_;
  std::vector<WaypointSpec> specs_;
  std::optional<FixedWaypoint> previous_;
  TrajectoryOptimizerOptions options_;
  optimization::MathematicalProgram prog_;
  optimization::DecisionVariables fixed_vars_;
  std::vector<optimization::DecisionVariables> vars_;
  std::vector<LabeledConstraint> constraints_;
  std::vector<std::shared_ptr<CollisionPenalty>> waypoint_collisions_;
  std::vector<std::pair<std::shared_ptr<CollisionPenalty>, optimization::DecisionVariables>> sample_collisions_;
  std::vector<std::shared_ptr<StaticTorqueResidual>> torques_;
  std::vector<std::string> coordinate_names_;
  std::vector<std::string> joint_names_;  // per joint coordinate of the chart
};

}  // namespace cairn::planning
