#include <cairn/planning/walk/walk_diagram.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/plant/joint_drive.h>
#include <cairn/planning/trajectory/environment_from_obstacles.h>
#include <cairn/planning/walk/scenario_terrain_boxes.h>
#include <cairn/systems/framework/diagram_builder.h>
#include <cairn/systems/primitives/constant_value_source.h>

namespace cairn::planning {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Eigen::VectorXd StandingAtStart(const multibody::Model& robot, const std::vector<std::string>& sole_bodies,
                                const Stance& start) {
  if (robot.num_bodies() < 2 || robot.joint(1).type != multibody::JointType::kFloating) {
    throw std::invalid_argument("StandingAtStart: model '" + robot.name() +
                                "' has no floating base; load the URDF with a floating base");
  }
  Eigen::VectorXd q = multibody::NeutralConfiguration(robot);
  const double yaw = 0.5 * (start.left.theta + start.right.theta);
  const Eigen::Quaterniond r(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  q.segment<4>(3) << r.w(), r.x(), r.y(), r.z();
  q[0] = 0.5 * (start.left.x + start.right.x);
  q[1] = 0.5 * (start.left.y + start.right.y);
  q[2] = 0.0;
  multibody::Data data(robot);
  multibody::ForwardKinematics(robot, data, q);
  double lowest = std::numeric_limits<double>::infinity();
  for (const std::string& sole : sole_bodies) {
    lowest = std::min(lowest, data.X_world[static_cast<std::size_t>(robot.GetBodyIndex(sole))].translation().z());
  }
  if (std::isfinite(lowest)) q[2] = std::max(start.left.z, start.right.z) - lowest;
  return q;
}

WalkSetup WalkSetupFromScenario(const FootstepScenario& scenario, std::shared_ptr<const StepCostModel> cost_model,
                                std::shared_ptr<const WalkingModel> walking_model, WalkingObjective objective,
                                std::shared_ptr<const multibody::Model> robot,
                                std::shared_ptr<const multibody::JointPdController> controller) {
  WalkSetup setup;
  setup.cost_model = std::move(cost_model);
  setup.objective = objective;
  if (walking_model != nullptr) {
    setup.geometry.foot_length = walking_model->foot_length();
    setup.geometry.foot_width = walking_model->foot_width();
    setup.geometry.body_half_extents = walking_model->body_half_extents();
    setup.geometry.body_bottom = walking_model->body_box_bottom();
  }
  setup.refine_model = std::move(walking_model);
  setup.planner = scenario.planner();
  setup.terrain = std::make_shared<const TerrainMap>(scenario.BuildTerrain());
  setup.start = scenario.start();
  setup.goal = scenario.goal();
  setup.environment = EnvironmentFromObstacles(scenario.obstacles());
  // The scenario's terrain is exact: the swing feet keep their clearance from its slopes and treads.
  setup.trajectory.ground_follows_terrain = true;
  setup.stabilizer = WalkingStabilizerOptions("fft");
  setup.robot = std::move(robot);
  setup.controller = std::move(controller);
  setup.plant_terrain = ScenarioTerrainBoxes(scenario);
  // Without the motors' drives the plant's E_ele and its Joule heat stay 0, and a step's measured energy would
  // silently leave out the heat its prediction includes.
  if (setup.robot != nullptr && setup.refine_model != nullptr) {
    setup.plant.drives = multibody::LoadJointDrives(*setup.robot, setup.refine_model->yaml_path());
  }
  return setup;
}

WalkDiagram AddWalkBlocks(const WalkSetup& setup, const systems::OutputPort* terrain_source,
                          systems::DiagramBuilder* builder) {
  const bool fixed_plan = setup.plan != nullptr;
  const bool external_terrain = terrain_source != nullptr;
  const systems::OutputPort* own_terrain = nullptr;  // the constant source of setup.terrain, once added
  if (fixed_plan) {
    if (!setup.plan->found) {
      throw std::invalid_argument("BuildWalkDiagram: the fixed plan has no steps to walk (" + setup.plan->reason +
                                  "); give a plan that was found, or none to plan one");
    }
    if (terrain_source != nullptr) {
      throw std::invalid_argument("BuildWalkDiagram: a terrain source was given with a fixed plan, which is never "
                                  "replanned; give one or the other");
    }
  } else {
    if (setup.cost_model == nullptr) throw std::invalid_argument("BuildWalkDiagram: the step cost model is null");
    if (terrain_source == nullptr && setup.terrain == nullptr) {
      throw std::invalid_argument("BuildWalkDiagram: the planner's terrain is null");
    }
  }
  if (setup.robot == nullptr) throw std::invalid_argument("BuildWalkDiagram: the robot model is null");
  if (setup.controller == nullptr) throw std::invalid_argument("BuildWalkDiagram: the PD controller is null");
  if (!(std::isfinite(setup.gravity_feedforward) && setup.gravity_feedforward >= 0.0 &&
        setup.gravity_feedforward <= 1.0)) {
    throw std::invalid_argument("BuildWalkDiagram: gravity_feedforward " + FormatShort(setup.gravity_feedforward) +
                                " must be in [0, 1] (0: none)");
  }
  WalkDiagram walk;
  if (fixed_plan) {
    walk.plan = &builder->AddNamedSystem<systems::ConstantValueSource<FootstepPlan>>("footsteps", *setup.plan)
                     ->GetOutputPort("y0");
  } else {
    auto* start = builder->AddNamedSystem<systems::ConstantValueSource<Stance>>("start", setup.start);
    auto* goal = builder->AddNamedSystem<systems::ConstantValueSource<StanceGoal>>("goal", setup.goal);
    if (terrain_source == nullptr) {
      terrain_source = &builder->AddNamedSystem<systems::ConstantValueSource<TerrainMap>>("terrain", *setup.terrain)
                            ->GetOutputPort("y0");
      own_terrain = terrain_source;
    }
    auto* footsteps = builder->AddNamedSystem<FootstepPlanner>("footsteps", setup.cost_model, setup.geometry,
                                                               setup.planner, setup.refine_model, setup.objective);
    builder->Connect(*terrain_source, footsteps->get_terrain_input_port());
    builder->Connect(start->GetOutputPort("y0"), footsteps->get_start_input_port());
    builder->Connect(goal->GetOutputPort("y0"), footsteps->get_goal_input_port());
    walk.footsteps = footsteps;
    walk.plan = &footsteps->get_plan_output_port();
  }
  auto* environment =
      builder->AddNamedSystem<systems::ConstantValueSource<std::vector<EnvironmentBox>>>("environment", setup.environment);
  auto* trajectory = builder->AddNamedSystem<TrajectoryOptimizer>("trajectory", setup.robot, setup.trajectory);
  auto* stabilizer = builder->AddNamedSystem<Stabilizer>("stabilizer", setup.robot, setup.stabilizer);
  auto* player = builder->AddNamedSystem<StabilizedReferencePlayer>("player", setup.robot);
  multibody::HumanoidPlantOptions plant_options = setup.plant;
  if (setup.gravity_feedforward > 0.0) plant_options.torque_input = true;
  auto* plant = builder->AddNamedSystem<multibody::HumanoidPlant>(
      "plant", *setup.robot, setup.plant_terrain, *setup.controller,
      StandingAtStart(*setup.robot, setup.plant.sole_bodies, fixed_plan ? setup.plan->start : setup.start),
      plant_options);
  if (setup.gravity_feedforward > 0.0) {
    auto* feedforward = builder->AddNamedSystem<GravityFeedforward>("feedforward", setup.robot,
                                                                    setup.plant.sole_bodies, setup.gravity_feedforward);
    builder->Connect(plant->GetOutputPort("state"), feedforward->get_state_input_port());
    builder->Connect(plant->GetOutputPort("contacts"), feedforward->get_contacts_input_port());
    builder->Connect(feedforward->get_torque_output_port(), plant->GetInputPort("torque"));
    walk.feedforward = feedforward;
  }
  builder->Connect(*walk.plan, trajectory->get_plan_input_port());
  builder->Connect(environment->GetOutputPort("y0"), trajectory->get_environment_input_port());
  // The whole-body optimiser lays the soles on the ground the walk knows (tilted on slopes): the planner's own
  // terrain. A perceived terrain (an external terrain_source) is not used for it: perceived footprints tilt the
  // soles where the true ground is level, and the cloth mock-up's walk then falls at 2.6 s (measured 2026-12-07;
  // docs/walk.md, "Slopes"). Without a known terrain the optimiser gets a map with no ground: level soles.
  const systems::OutputPort* sole_ground = own_terrain;
  if (sole_ground == nullptr) {
    sole_ground = &builder
                       ->AddNamedSystem<systems::ConstantValueSource<TerrainMap>>(
                           "sole_ground", external_terrain || setup.terrain == nullptr
                                              ? TerrainMap(Eigen::Vector2d::Zero(), 1, 1, 1.0)
                                              : *setup.terrain)
                       ->GetOutputPort("y0");
  }
  builder->Connect(*sole_ground, trajectory->get_terrain_input_port());
  builder->Connect(trajectory->get_trajectory_output_port(), stabilizer->get_trajectory_input_port());
  builder->Connect(stabilizer->get_reference_output_port(), player->get_reference_input_port());
  if (setup.feedback) {
    auto* balance = builder->AddNamedSystem<BalanceFeedback>("balance", setup.robot, setup.balance);
    builder->Connect(player->get_reference_output_port(), balance->get_reference_input_port());
    builder->Connect(plant->GetOutputPort("state"), balance->get_state_input_port());
    builder->Connect(plant->GetOutputPort("contacts"), balance->get_contacts_input_port());
    builder->Connect(balance->get_reference_output_port(), plant->GetInputPort("reference"));
    walk.balance = balance;
  } else {
    builder->Connect(player->get_reference_output_port(), plant->GetInputPort("reference"));
  }
  walk.trajectory = trajectory;
  walk.stabilizer = stabilizer;
  walk.player = player;
  walk.plant = plant;
  return walk;
}

WalkDiagram BuildWalkDiagram(const WalkSetup& setup) {
  systems::DiagramBuilder builder;
  WalkDiagram walk = AddWalkBlocks(setup, nullptr, &builder);
  walk.diagram = builder.Build();
  walk.diagram->set_name("walk");
  return walk;
}

WalkStart InitializeWalk(const WalkDiagram& walk, systems::Simulator* simulator) {
  if (simulator == nullptr || &simulator->get_system() != walk.diagram.get()) {
    throw std::invalid_argument("InitializeWalk: the simulator does not simulate this walk diagram");
  }
  const auto t0 = std::chrono::steady_clock::now();
  simulator->Initialize();
  const double initialize = SecondsSince(t0);
  WalkStart start = SettleWalk(walk, &simulator->get_mutable_context(), /*replan_footsteps=*/false);
  // The initialization pass solved the first stage that had its input: the footstep search, or with a fixed plan
  // the whole-body problem.
  (walk.footsteps != nullptr ? start.seconds.footsteps : start.seconds.trajectory) += initialize;
  return start;
}

WalkStart SettleWalk(const WalkDiagram& walk, systems::Context* root_context, bool replan_footsteps) {
  if (root_context == nullptr || walk.diagram == nullptr || walk.plan == nullptr) {
    throw std::invalid_argument("SettleWalk: give a built walk diagram and its root context");
  }
  WalkStart start;
  systems::Context& root = *root_context;
  auto t0 = std::chrono::steady_clock::now();
  if (replan_footsteps && walk.footsteps != nullptr) {
    walk.footsteps->ExecuteForcedEvents(&walk.diagram->GetMutableSubsystemContext(*walk.footsteps, &root));
    start.seconds.footsteps = SecondsSince(t0);
  }
  const auto& plan =
      walk.plan->Eval<FootstepPlan>(walk.diagram->GetSubsystemContext(walk.plan->get_system(), root));
  if (!plan.found) {
    start.reason = "no footstep plan: " + plan.reason;
    return start;
  }
  // With a fixed plan the trajectory optimizer saw its plan in the initialization pass and has solved it already.
  if (walk.footsteps != nullptr) {
    t0 = std::chrono::steady_clock::now();
    walk.trajectory->ExecuteForcedEvents(&walk.diagram->GetMutableSubsystemContext(*walk.trajectory, &root));
    start.seconds.trajectory = SecondsSince(t0);
  }
  const auto& trajectory = walk.trajectory->get_trajectory_output_port().Eval<WholeBodyTrajectory>(
      walk.diagram->GetSubsystemContext(*walk.trajectory, root));
  if (!trajectory.found) {
    start.reason = "no whole-body trajectory: " + trajectory.report.message;
    return start;
  }
  t0 = std::chrono::steady_clock::now();
  walk.stabilizer->ExecuteForcedEvents(&walk.diagram->GetMutableSubsystemContext(*walk.stabilizer, &root));
  start.seconds.stabilizer = SecondsSince(t0);
  const auto& reference = walk.stabilizer->get_reference_output_port().Eval<StabilizedTrajectory>(
      walk.diagram->GetSubsystemContext(*walk.stabilizer, root));
  if (!reference.report.success || reference.q.empty()) {
    start.reason = "no stabilised reference: " + reference.report.message;
    return start;
  }
  systems::Context& plant = walk.diagram->GetMutableSubsystemContext(*walk.plant, &root);
  const multibody::Model& robot = walk.plant->model();
  Eigen::VectorXd x(robot.nq() + robot.nv());
  x << reference.q.front(), reference.v.front();
  plant.SetDiscreteState(0, x);
  start.ready = true;
  return start;
}

}  // namespace cairn::planning
