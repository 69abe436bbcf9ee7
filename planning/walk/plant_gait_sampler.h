#pragma once

#include <memory>
#include <string>

#include <cairn/multibody/model.h>
#include <cairn/multibody/plant/humanoid_plant_options.h>
#include <cairn/multibody/plant/joint_pd_controller.h>
#include <cairn/planning/locomotion/step_cost_model.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_objective.h>
#include <cairn/planning/stabilization/stabilizer_options.h>
#include <cairn/planning/trajectory/trajectory_optimizer_options.h>
#include <cairn/planning/walk/balance_feedback.h>
#include <cairn/planning/walk/periodic_gait.h>
#include <cairn/planning/walk/walk_diagram.h>

namespace cairn::planning {

/// How PlantGaitSampler walks and measures a gait.
struct PlantGaitOptions {
  /// Steps of each gait (thesis 2.3.3: 6); in [2 transient_steps + 1, kMaxPeriodicGaitSteps].
  int num_steps{6};
  /// Steps at each end left out of the measurement: the gait starts and stops at rest, which its middle steps do
  /// not. In [0, 10].
  int transient_steps{2};
  /// Coulomb friction of the plant's ground and the plan's mu_allowed (thesis: "ground of high friction"); (0, 10].
  double ground_friction{1.0};
  /// The soles must end within this horizontal distance of the plan's last stance for the gait to count as
  /// tracked, m; (0, 1].
  double tracking_tolerance{0.05};
  /// MeasurePlanned() only: the least distance of the stabilised ZMP inside its support polygon for a feasible gait,
  /// m; in [-0.1, 0.1] (negative tolerates the stabiliser's residual error).
  double min_support_margin{0.0};
  /// Standing simulated after the reference ends, so a fall after the last step counts, s; [0, 60].
  double settle_time{1.0};
  /// The chain from plan to plant, as `cairn walk` sets it by default.
  TrajectoryOptimizerOptions trajectory;
  StabilizerOptions stabilizer{WalkingStabilizerOptions("fft")};
  bool feedback{true};
  BalanceFeedbackOptions balance;
  /// Plant settings; stop_on_fall is forced on (a fall ends the sample). Empty drives: the walking model's motors
  /// (LoadJointDrives of its YAML), without which E_ele would stay 0.
  multibody::HumanoidPlantOptions plant;
};

/// What one gait did in the plant (PlantGaitSampler::Measure), or what the planning chain made of it
/// (MeasurePlanned). Energies and RCOF are over the measured steps (all but transient_steps at each end); NaN when
/// the gait was not walked (planned) that far, and the plant's quantities are NaN for MeasurePlanned.
struct GaitMeasurement {
  PeriodicGait gait;
  /// The analytic model's step for the same displacement and parameters (its Psi in `feasible`).
  TransitionCost predicted;
  /// The plant walked (false: no periodic gait exists for the displacement, or the trajectory optimiser or the
  /// stabiliser gave nothing; `reason` says which).
  bool simulated{false};
  /// Walked every step without falling and ended with both soles within tracking_tolerance of the plan's last
  /// stance (thesis 2.3.3's Psi: no fall, tracking within bounds).
  bool feasible{false};
  /// Why the gait is not feasible ("" when it is).
  std::string reason;
  int measured_steps{0};
  double com_work{0.0};           ///< mean E_COM (eq. 2.1) per measured step, J
  double electrical_energy{0.0};  ///< mean E_ele per measured step, J
  double heat{0.0};               ///< mean Joule heat of E_ele per measured step, J (the models' heat term)
  /// Largest net-force RCOF (eq. 2.2 of both soles' low-passed net force: what the models predict) over the
  /// measured steps' support stances.
  double rcof{0.0};
  /// Largest support-sole RCOF over the same stances without their first touchdown_time (the landing impact).
  double sole_rcof{0.0};
  /// Mean COM height above the mean height of the stance's footholds over the measured steps, m (the whole-body
  /// optimiser chooses the posture, so this is what the walk used, not gait.parameters.com_height).
  double com_height{0.0};
  /// Mean whole-body cost per measured step: the torque terms (thesis eqs. 2.10-2.11; torques divided by their
  /// effort limits, so dimensionless) of the step's waypoints, its start in double support and its mid-swing. The
  /// pipeline oracle's `torque` cost (thesis 2.5.1).
  double torque_cost{0.0};
  /// Smallest distance of the stabilised reference's ZMP inside its support polygon over the whole gait, m
  /// (negative: outside).
  double support_margin{0.0};
  int slips{0};                   ///< over the whole walk
  /// Larger of the two soles' horizontal distances from the plan's last stance at the end, m.
  double final_error{0.0};
  double duration{0.0};           ///< simulated time, s
  WalkSettleTimes seconds;        ///< wall time of the planning stages (not part of any result)
  double plant_seconds{0.0};      ///< wall time of the plant (not part of any result)
};

/// The physics measurement behind an oracle learned from simulation (thesis 2.3.3, issue 21's `plant` source):
/// a symmetric periodic gait (PeriodicGait) is turned into a footstep plan, optimised (TrajectoryOptimizer),
/// stabilised, and walked with the balance feedback in the physics plant on ground of high friction (a level floor,
/// or a staircase of treads when dz != 0), as the walk diagram with a fixed plan (WalkSetup::plan); E_COM, RCOF,
/// E_ele and feasibility are read over its middle steps.
///
/// Measure() builds its own diagram, so one sampler may measure from several threads at once; the same gait gives
/// the same measurement (the plant, the solvers and the ordering are deterministic).
class PlantGaitSampler {
 public:
  /// Throws std::invalid_argument naming the value for null models or controller, a robot without a floating base,
  /// or options out of range.
  PlantGaitSampler(std::shared_ptr<const WalkingModel> walking_model, std::shared_ptr<const multibody::Model> robot,
                   std::shared_ptr<const multibody::JointPdController> controller, WalkingObjective objective,
                   PlantGaitOptions options = PlantGaitOptions());

  /// The walk setup of a gait: its plan (PeriodicGaitPlan), the plant's ground (PeriodicGaitTerrain) and the
  /// options' stages; to build the diagram yourself (BuildWalkDiagram) and look at it. Throws
  /// std::invalid_argument as PeriodicGaitPlan and PeriodicGaitTerrain do.
  WalkSetup Setup(const PeriodicGait& gait) const;

  /// Walks `gait` (its num_steps is replaced by the options') and measures it. A gait that cannot be walked is a
  /// result (simulated or feasible false, with the reason); throws std::invalid_argument only for a gait outside the
  /// walking model's reach or parameter bounds.
  GaitMeasurement Measure(const PeriodicGait& gait) const;

  /// The planning chain alone, not walked (issue 21's `pipeline` source: what the whole-body optimiser and the
  /// stabiliser produce for a transition, thesis 2.5.1's oracle for the hierarchical planner): the walk diagram's
  /// chain is settled as for Measure() and read without simulating. torque_cost comes from the whole-body
  /// trajectory; com_work, rcof and com_height from the stabilised reference's centre of mass (its net external
  /// force m (a - g) by central differences: E_COM = integral of |v . F| dt as the plant measures it, RCOF = |F_xy| /
  /// F_z over the measured steps); electrical_energy, heat, sole_rcof and final_error are NaN and `simulated` is
  /// false. Feasible: the whole-body trajectory was found and the stabilised ZMP stays inside its support polygon
  /// by at least options().min_support_margin. (The stabiliser's joint-limit flag is not a criterion: its leg
  /// inverse kinematics grazes the knee and ankle limits on gaits the plant walks.) Throws as Measure() does.
  GaitMeasurement MeasurePlanned(const PeriodicGait& gait) const;

  const PlantGaitOptions& options() const { return options_; }
  const WalkingModel& walking_model() const { return *walking_model_; }
  WalkingObjective objective() const { return objective_; }

 private:
  std::shared_ptr<const WalkingModel> walking_model_;
  std::shared_ptr<const multibody::Model> robot_;
  std::shared_ptr<const multibody::JointPdController> controller_;
  WalkingObjective objective_;
  PlantGaitOptions options_;
};

}  // namespace cairn::planning
