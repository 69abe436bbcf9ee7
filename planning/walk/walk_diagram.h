#pragma once

#include <memory>
#include <string>
#include <vector>

#include <cairn/multibody/model.h>
#include <cairn/multibody/plant/humanoid_plant.h>
#include <cairn/multibody/plant/humanoid_plant_options.h>
#include <cairn/multibody/plant/joint_pd_controller.h>
#include <cairn/multibody/plant/terrain_box.h>
#include <cairn/planning/footstep/biped_geometry.h>
#include <cairn/planning/footstep/footstep_planner.h>
#include <cairn/planning/footstep/footstep_planner_options.h>
#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/locomotion/step_cost_model.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_objective.h>
#include <cairn/planning/scenarios/footstep_scenario.h>
#include <cairn/planning/stabilization/stabilized_reference_player.h>
#include <cairn/planning/stabilization/stabilizer.h>
#include <cairn/planning/stabilization/stabilizer_options.h>
#include <cairn/planning/trajectory/collision_penalty.h>
#include <cairn/planning/trajectory/trajectory_optimizer.h>
#include <cairn/planning/trajectory/trajectory_optimizer_options.h>
#include <cairn/planning/walk/balance_feedback.h>
#include <cairn/planning/walk/gravity_feedforward.h>
#include <cairn/systems/analysis/simulator.h>
#include <cairn/systems/framework/diagram.h>
#include <cairn/systems/framework/diagram_builder.h>

namespace cairn::planning {

/// Everything the walk diagram is built from: the planning problem, the three planners' settings and the plant.
struct WalkSetup {
  // Footstep planning.
  std::shared_ptr<const StepCostModel> cost_model;       ///< prices steps (a TransitionOracle); required
  std::shared_ptr<const WalkingModel> refine_model;      ///< refines each plan's steps (null: keep the table's)
  WalkingObjective objective{WalkingObjective::kComWorkPlusHeat};  ///< the cost model's objective
  BipedGeometry geometry;
  FootstepPlannerOptions planner;                        ///< give it an expansion budget for deterministic plans
  std::shared_ptr<const TerrainMap> terrain;             ///< the planner's view (friction already Q_{1-eta}); required
  Stance start;
  StanceGoal goal;
  /// A fixed plan to walk instead of planning one (a periodic gait, a plan saved earlier): a constant source named
  /// "footsteps" feeds it to the trajectory optimizer, the plant starts at the plan's start stance, and cost_model,
  /// terrain, start, goal and planner are not used. Null (the default): the FootstepPlanner plans.
  std::shared_ptr<const FootstepPlan> plan;
  // Whole-body trajectory and stabilisation.
  std::vector<EnvironmentBox> environment;               ///< obstacles for the collision penalty
  TrajectoryOptimizerOptions trajectory;
  StabilizerOptions stabilizer;
  /// Close the loop on the measured capture point (BalanceFeedback between the player and the plant); false plays
  /// the stabilised reference open loop.
  bool feedback{true};
  BalanceFeedbackOptions balance;
  /// Share of the gravity feedforward (GravityFeedforward: the static torques of every joint that carries no loaded
  /// sole) added to the PD drive, in [0, 1]; 0 adds none.
  double gravity_feedforward{0.0};
  // The physics plant.
  std::shared_ptr<const multibody::Model> robot;         ///< floating base; required
  std::shared_ptr<const multibody::JointPdController> controller;  ///< PD gains; required
  std::vector<multibody::TerrainBox> plant_terrain;      ///< the true world (ScenarioTerrainBoxes)
  multibody::HumanoidPlantOptions plant;
};

/// The robot of a floating-base `robot` standing at `start`: joints at their neutral values, the base above the
/// stance's midpoint with its mean heading, the lowest of `sole_bodies` on the higher foot's height (no sole bodies:
/// the base at z = 0). Where the walk diagram puts the plant before settling, and a picture of the robot at its start.
/// Throws std::invalid_argument for a robot without a floating base or a sole body `robot` does not have.
Eigen::VectorXd StandingAtStart(const multibody::Model& robot, const std::vector<std::string>& sole_bodies,
                                const Stance& start);

/// A WalkSetup for a footstep scenario: its terrain (FootstepScenario::BuildTerrain), start, goal and planner
/// settings, its obstacles as the trajectory's environment (EnvironmentFromObstacles) and as the plant's boxes with
/// its regions (ScenarioTerrainBoxes), the geometry of `walking_model`'s feet and body box, and `walking_model`
/// refining the plan's steps, and the plant driven by `walking_model`'s motors (LoadJointDrives of its YAML, so the
/// plant measures E_ele and its Joule heat; with a robot and a walking model). The stabiliser's options are
/// WalkingStabilizerOptions("fft") (the thesis' defaults do not walk in the plant); the other trajectory and plant
/// options are the defaults. The caller adjusts them. Throws as those functions do.
WalkSetup WalkSetupFromScenario(const FootstepScenario& scenario, std::shared_ptr<const StepCostModel> cost_model,
                                std::shared_ptr<const WalkingModel> walking_model, WalkingObjective objective,
                                std::shared_ptr<const multibody::Model> robot,
                                std::shared_ptr<const multibody::JointPdController> controller);

/// The walk as one diagram (thesis Fig. 5.1 from the footstep planner on), with its blocks:
///
///     start, goal, terrain ─► FootstepPlanner ─► TrajectoryOptimizer ─► Stabilizer ─► StabilizedReferencePlayer
///                                environment ─┘        ─► BalanceFeedback ─► HumanoidPlant (its state and contacts back)
///
/// Subsystem names: "start", "goal", "terrain", "environment" (constant sources), "footsteps", "trajectory",
/// "stabilizer", "player", "balance" (only with setup.feedback), "plant".
struct WalkDiagram {
  std::unique_ptr<systems::Diagram> diagram;
  const FootstepPlanner* footsteps{nullptr};  ///< null when the setup walks a fixed plan
  /// The plan the trajectory optimizer follows: the FootstepPlanner's output, or the fixed plan's source.
  const systems::OutputPort* plan{nullptr};
  const TrajectoryOptimizer* trajectory{nullptr};
  const Stabilizer* stabilizer{nullptr};
  const StabilizedReferencePlayer* player{nullptr};
  const BalanceFeedback* balance{nullptr};  ///< null without setup.feedback
  const GravityFeedforward* feedforward{nullptr};  ///< null with setup.gravity_feedforward 0
  const multibody::HumanoidPlant* plant{nullptr};
};

/// Builds the walk diagram. The plant starts standing at the start stance (joints at zero, the lower sole on the
/// start stance's height; with a fixed plan, its start); InitializeWalk() puts it on the reference's first sample.
/// Throws std::invalid_argument for a missing cost model or terrain (without a fixed plan), a fixed plan that was
/// not found, a missing robot or controller, and as the blocks' constructors do.
WalkDiagram BuildWalkDiagram(const WalkSetup& setup);

/// The walk's blocks added to a larger diagram under construction (the main diagram puts perception in front):
/// as BuildWalkDiagram, but the footstep planner's terrain comes from `terrain_source` (a TerrainMap output of a
/// system already in `builder`; null: a constant source of setup.terrain, which may then not be null; it must be
/// null with a fixed plan). The whole-body optimiser lays its soles on setup.terrain (tilted on slopes) when the
/// planner plans on it or the plan is fixed, and level on a `terrain_source` (perceived ground is not trusted for
/// that yet; docs/walk.md, "Slopes"). The
/// returned diagram pointer is empty: the caller builds and owns the diagram and stores it there.
WalkDiagram AddWalkBlocks(const WalkSetup& setup, const systems::OutputPort* terrain_source,
                          systems::DiagramBuilder* builder);

/// Wall time of each planning stage while InitializeWalk() settled the chain, s (not part of any result).
struct WalkSettleTimes {
  double footsteps{0.0};   ///< Simulator::Initialize(): the footstep search (the other blocks' initial events are trivial)
  double trajectory{0.0};  ///< the TrajectoryOptimizer's solve
  double stabilizer{0.0};  ///< the Stabilizer's interpolation and compensation
};

/// What InitializeWalk() left in the context.
struct WalkStart {
  /// The chain settled on a reference the plant can follow; false: `reason` names the stage that gave none.
  bool ready{false};
  std::string reason;
  WalkSettleTimes seconds;
};

/// Settles the planning chain before the plant takes a step, and puts the plant on the reference's first sample.
///
/// The three planners work in events: the Simulator's initialization runs every block's initialization event
/// from the state before any is applied, so at that instant the FootstepPlanner plans while the
/// TrajectoryOptimizer still sees "not planned yet" and the Stabilizer "not solved yet". So after
/// simulator->Initialize() this runs the TrajectoryOptimizer's forced event (it now sees the plan), then the
/// Stabilizer's (it sees the trajectory): each stage once, in the chain's order. (With a fixed plan the
/// TrajectoryOptimizer sees its plan in the initialization pass, so only the Stabilizer's event runs after it.) Then the plant's state (q, v) is
/// set to the reference's first sample (the plant resets its Bullet world to it), so the PD drive starts on its
/// reference instead of jumping to it. The Stabilizer's per-step check then finds its input unchanged and keeps
/// its reference. When a stage gives nothing (no footstep plan, no trajectory, no stabilised reference), the
/// plant is left as built and `ready` is false: simulating would fail at the player.
WalkStart InitializeWalk(const WalkDiagram& walk, systems::Simulator* simulator);

/// InitializeWalk()'s settling after Simulator::Initialize(), for diagrams whose terrain is only known once other
/// events ran (perception): with `replan_footsteps`, the FootstepPlanner's forced event plans again first (on the
/// terrain its input shows now; a fixed plan is never replanned, and its trajectory, solved in the initialization
/// pass, is not solved again). `root_context` is walk.diagram's context. Throws std::invalid_argument for a
/// null context or an unbuilt walk.
WalkStart SettleWalk(const WalkDiagram& walk, systems::Context* root_context, bool replan_footsteps);

}  // namespace cairn::planning
