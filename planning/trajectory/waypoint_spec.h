#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/pose.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/trajectory/static_torque_residual.h>
#include <cairn/planning/trajectory/trajectory_optimizer_options.h>

namespace cairn::planning {

/// A foot in contact at a waypoint: its sole frame and where the plan puts it.
struct WaypointContact {
  std::string frame;     ///< sole frame, e.g. "l_sole"
  FootSide side{FootSide::kLeft};
  multibody::Pose X_WF;  ///< target pose of the sole frame (FootPose x, y, z and yaw, tilted to the ground)
};

/// What problem (2.9) asks of one waypoint q_t: the contacts of its stance, the support polygon of the contacts
/// that persist into the next waypoint (as half-planes), who carries the weight, and its time.
struct WaypointSpec {
  double time{0.0};             ///< s
  int stance{0};                ///< plan stance (0: start)
  bool single_support{false};   ///< mid-swing
  std::string label;            ///< "stance 3 start" or "stance 3 mid-swing"
  std::vector<WaypointContact> contacts;
  /// Support polygon as A p <= b (p the COM's horizontal projection), counter-clockwise edges, already shrunk by
  /// the COM margin.
  Eigen::MatrixXd polygon_A;
  Eigen::VectorXd polygon_b;
  /// The polygon's vertices (before the margin), counter-clockwise, for pictures and reports.
  std::vector<Eigen::Vector2d> polygon_vertices;
  std::vector<TorqueSupport> supports;
};

/// The waypoints of a footstep plan with M steps (stances S_0..S_M): for each stance S_j its start posture in
/// double support, and for each step j -> j+1 its mid-swing posture with only the stance foot in contact, so
/// T = 2M + 1 = 2N - 1 for N stances (the thesis' T = 2N counts the final stance's mid-stance posture, which
/// equals its start when nothing follows). Support polygons follow the thesis: the contacts that persist into
/// the next waypoint, i.e. the stance foot of the next step at a stance's start, the stance foot at mid-swing,
/// both feet at the final stance. Times: a stance starts when the previous step ends (t_ds + t_sw of each
/// step); mid-swing is at t_ds + t_sw / 2.
///
/// Sole targets: at the foot's x, y, z with its yaw, and, with a `terrain`, tilted onto the ground under the sole
/// (SoleTargetPose), so that a sole on a slope lies on it rather than standing on its toe or heel.
///
/// Throws std::invalid_argument if the plan was not found, has more than kMaxTrajectoryStances stances, or a
/// step has a non-positive or non-finite duration.
std::vector<WaypointSpec> MakeWaypointSpecs(const FootstepPlan& plan, const TrajectoryOptimizerOptions& options,
                                            const TerrainMap* terrain = nullptr);

/// The sole pose MakeWaypointSpecs targets for `foot`: its position and yaw, tilted by the smallest rotation that
/// takes the world's z axis to the normal of the plane fitted (least squares) to the ground heights of the map
/// cells whose centres lie under the sole (a sole_length x sole_width rectangle). The fit spans the whole footprint
/// because perceived cells' own normals are noisy; on a true plane it is exact. Level (z axis up) without a
/// terrain or where fewer than three cells under the sole have ground or they lie on one line.
multibody::Pose SoleTargetPose(const FootPose& foot, const TerrainMap* terrain, double sole_length = 0.24,
                               double sole_width = 0.14);

}  // namespace cairn::planning
