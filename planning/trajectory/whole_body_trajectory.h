#pragma once

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cairn::planning {

/// One waypoint q_t of a whole-body trajectory.
struct WholeBodyWaypoint {
  double time{0.0};                 ///< s from the start of the plan
  int stance{0};                    ///< the plan's stance s_t (0: the start stance)
  bool single_support{false};       ///< mid-swing posture (one foot in contact) rather than a stance's start
  std::string label;                ///< e.g. "stance 3 start", "stance 3 mid-swing"
  Eigen::VectorXd q;                ///< configuration (floating base [x y z qw qx qy qz], then the joints)
  std::vector<std::string> contacts;  ///< contact frames, e.g. {"l_sole", "r_sole"}
  Eigen::Vector3d com{Eigen::Vector3d::Zero()};  ///< centre of mass in the world
  double min_clearance{0.0};        ///< smallest signed distance from a link not in contact to the environment, m
  /// The torque term of the cost at this waypoint (thesis eqs. 2.10-2.11): torque_weight times the squared static
  /// joint torques, each divided by its effort limit (dimensionless). The summand of TrajectorySolveReport::
  /// torque_cost, so a step's share of the whole-body cost can be read off.
  double torque_cost{0.0};
};

/// How a whole-body solve went: failures are results, with the most violated constraint rows by name.
struct TrajectorySolveReport {
  bool success{false};              ///< converged and every constraint within tolerance
  std::string status;               ///< the solver's status ("solved", "infeasible", ...), or the reason no solve ran
  std::string solver;               ///< solver name
  std::string message;              ///< one line: the status and, on failure, the worst rows
  /// The most violated rows (largest first, at most 5): "stance 3, l_sole position off by 0.21 m".
  std::vector<std::string> violations;
  double max_violation{0.0};        ///< largest constraint or bound violation (m, rad or normalised units)
  /// Smallest distance to the environment at the collision samples between waypoints, m (infinity if none),
  /// and the pair, e.g. "collision(stance 3 start -> stance 3 mid-swing): head_sphere - high bar".
  double min_sample_clearance{std::numeric_limits<double>::infinity()};
  std::string min_sample_pair;
  int iterations{0};                ///< solver iterations summed over windows
  int windows{0};                   ///< problems solved (1 for the whole plan)
  double seconds{0.0};              ///< wall time of the solves, s
  double objective{0.0};            ///< the program's objective at the solution (summed over windows): torque cost,
                                    ///< collision penalty and the regularisers
  double torque_cost{0.0};          ///< the torque term alone, summed over the returned waypoints
  int num_variables{0};             ///< of the largest problem solved
  int num_constraints{0};           ///< rows of the largest problem solved
  int jacobian_nonzeros{0};         ///< structural nonzeros of its constraint Jacobian
  /// Hessian entries declared by the largest problem's terms (before Ipopt merges duplicates; the least-squares
  /// terms' J'J adds more); 0 if a term has none.
  int hessian_nonzeros{0};
  std::string hessian;              ///< "exact" or "limited-memory" (Ipopt), else "solver's own"
};

/// The output of the whole-body optimiser (thesis 2.5.1b): waypoints from the footstep plan's stances.
struct WholeBodyTrajectory {
  bool found{false};                ///< true if the report is a success
  std::vector<std::string> coordinate_names;  ///< one per entry of q, e.g. "base_x", "base_qw", "l_knee"
  std::vector<WholeBodyWaypoint> waypoints;
  TrajectorySolveReport report;
};

}  // namespace cairn::planning
