#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/plant/slip_event.h>
#include <cairn/multibody/plant/stance_phase.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/stabilization/stabilized_trajectory.h>
#include <cairn/planning/trajectory/whole_body_trajectory.h>
#include <cairn/planning/walk/walk_diagram.h>

namespace cairn::planning {

/// How RunWalk() samples and ends the walk.
struct WalkRunOptions {
  /// s between recorded samples; in (0, 1].
  double log_period{0.01};
  /// s simulated after the reference ends (standing on its last sample), so a fall after the last step counts;
  /// in [0, 60].
  double settle_time{1.0};
  /// Settles the diagram's planners before the plant walks, given the diagram's simulator; null: InitializeWalk().
  /// The main diagram passes its own, which perceives first (InitializeMainDiagram).
  std::function<WalkStart(systems::Simulator*)> initialize;
};

/// One recorded sample of the plant.
struct WalkSample {
  double time{0.0};
  Eigen::VectorXd q;                        ///< the plant's configuration
  Eigen::Vector3d com{Eigen::Vector3d::Zero()};  ///< centre of mass of q, world
  Eigen::Vector3d zmp{Eigen::Vector3d::Zero()};  ///< measured from the foot contacts (NaN in the air)
  double left_force{0.0}, right_force{0.0};  ///< soles' normal forces, N
  double left_tangential{0.0}, right_tangential{0.0};  ///< magnitudes of the soles' tangential forces, N
  double com_energy{0.0};                   ///< E_COM so far, J
  double electrical_energy{0.0};            ///< E_ele so far, J
  double heat{0.0};                         ///< E_ele's Joule heat so far, J
};

/// Everything a walk produced: each stage's result, the plant's samples and verdicts.
struct WalkRecord {
  WalkStart start;                 ///< whether the chain settled (else nothing was simulated)
  FootstepPlan plan;
  WholeBodyTrajectory trajectory;
  StabilizedTrajectory reference;
  std::vector<WalkSample> samples;  ///< at t = 0 and every log_period (and at the end)
  std::vector<multibody::SlipEvent> slips;
  std::vector<multibody::StancePhase> stances;
  bool fell{false};
  std::string fall_reason;
  double duration{0.0};             ///< simulated time, s (shorter than planned when the robot fell)
  double plant_seconds{0.0};        ///< wall time of the plant's simulation (not part of any result)
};

/// Runs the walk diagram: InitializeWalk() (or options.initialize), then the Simulator until the reference's end plus
/// options.settle_time, recording a sample every options.log_period. A fall is a result (the plant's verdict); it
/// ends the run when the plant's stop_on_fall option is set. Throws std::invalid_argument for an empty diagram or
/// options out of range; std::runtime_error when an event handler fails.
WalkRecord RunWalk(const WalkDiagram& walk, const WalkRunOptions& options = WalkRunOptions());

}  // namespace cairn::planning
