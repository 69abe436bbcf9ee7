#include "examples/probing/probing_example.h"

#include <cmath>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/perception/terrain/elevation_mapper.h"
#include "cairn/perception/terrain/probe_controller.h"
#include "cairn/perception/terrain/traversability_analyzer.h"
#include "cairn/planning/grid/grid_path_planner.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/primitives/constant_vector_source.h"
#include "examples/probing/path_follower.h"
#include "examples/probing/probe_arm.h"
#include "examples/probing/probe_supervisor.h"
#include "examples/probing/scenario_sensor.h"

namespace cairn::examples {

namespace {
constexpr double kPeriod = 0.1;
constexpr double kSamplePeriod = 0.005;
}  // namespace

std::unique_ptr<systems::Diagram> BuildProbingDiagram(const planning::TraverseScenario& s) {
  systems::DiagramBuilder builder;
  const Eigen::Vector2i size = (s.world_size / s.resolution).array().ceil().cast<int>();
  const perception::GridMap prototype(size, s.resolution, s.world_min + 0.5 * size.cast<double>() * s.resolution);
  perception::ElevationMapper::Options mapper_options;
  mapper_options.elevation.max_range = 2.0 * (s.sensor_range + s.sensor_height);
  auto* sensor = builder.AddNamedSystem<ScenarioSensor>("sensor", s);
  auto* mapper = builder.AddNamedSystem<perception::ElevationMapper>("mapper", prototype, kPeriod, mapper_options);
  auto* analyzer = builder.AddNamedSystem<perception::TraversabilityAnalyzer>("analyzer");
  planning::GridSearch::Options search;
  search.blocked_below = s.blocked_below;
  auto* planner = builder.AddNamedSystem<planning::GridPathPlanner>("planner", s.resolution, prototype.min_corner(),
                                                                    search, kPeriod);
  planning::ProbingPlanner::Options probing;
  probing.cluster_distance = 1.5 * s.resolution;
  probing.reach = s.reach;
  auto* supervisor = builder.AddNamedSystem<ProbeSupervisor>("supervisor", probing, 0.5, 2, kPeriod);
  auto* arm = builder.AddNamedSystem<ProbeArm>("arm", s);
  auto* probe = builder.AddNamedSystem<perception::ProbeController>(
      "probe_controller", perception::CollapsibilityEstimator::Options{s.hard_force, s.probe_samples}, kSamplePeriod);
  auto* walker = builder.AddNamedSystem<PathFollower>("walker", s.start, s.step, kPeriod);
  auto* goal = builder.AddNamedSystem<systems::ConstantVectorSource>("goal", Eigen::VectorXd(s.goal));
  builder.Connect(walker->get_position_output_port(), sensor->get_robot_input_port());
  builder.Connect(sensor->GetOutputPort("points_W"), mapper->get_points_input_port());
  builder.Connect(sensor->GetOutputPort("sensor_W"), mapper->get_sensor_input_port());
  builder.Connect(sensor->GetOutputPort("probabilities"), mapper->get_probabilities_input_port());
  builder.Connect(mapper->get_map_output_port(), analyzer->get_map_input_port());
  builder.Connect(supervisor->get_probes_output_port(), analyzer->get_probes_input_port());
  builder.Connect(analyzer->get_traversability_output_port(), planner->get_traversability_input_port());
  builder.Connect(walker->get_position_output_port(), planner->get_start_input_port());
  builder.Connect(goal->get_output_port(), planner->get_goal_input_port());
  builder.Connect(analyzer->get_map_output_port(), supervisor->get_map_input_port());
  builder.Connect(walker->get_position_output_port(), supervisor->get_robot_input_port());
  builder.Connect(probe->get_collapsibility_output_port(), supervisor->get_collapsibility_input_port());
  builder.Connect(supervisor->get_probe_command_output_port(), arm->get_command_input_port());
  builder.Connect(arm->GetOutputPort("force"), probe->get_force_input_port());
  builder.Connect(arm->GetOutputPort("probing"), probe->get_probing_input_port());
  builder.Connect(planner->get_path_output_port(), walker->get_path_input_port());
  builder.Connect(supervisor->get_pause_output_port(), walker->get_pause_input_port());
  auto diagram = builder.Build();
  diagram->set_name("probing");
  return diagram;
}

ProbingRun RunProbingExample(const planning::TraverseScenario& scenario, double max_time) {
  if (!(max_time > 0.0) || !std::isfinite(max_time)) {
    throw std::invalid_argument("RunProbingExample: max_time " + FormatShort(max_time) + " s must be positive");
  }
  auto diagram = BuildProbingDiagram(scenario);
  const auto& walker = static_cast<const PathFollower&>(diagram->GetSubsystemByName("walker"));
  const auto& supervisor = static_cast<const ProbeSupervisor&>(diagram->GetSubsystemByName("supervisor"));
  systems::Simulator simulator(*diagram);
  ProbingRun run;
  for (double t = kPeriod; t <= max_time + 1e-9; t += kPeriod) {
    simulator.AdvanceTo(t);
    const auto& wc = diagram->GetSubsystemContext(walker, simulator.get_context());
    run.final_position = walker.get_position_output_port().Eval<Eigen::VectorXd>(wc);
    run.trajectory.push_back(run.final_position);
    if ((run.final_position - scenario.goal).norm() <= scenario.resolution) {
      run.reached_goal = true;
      break;
    }
  }
  run.time = simulator.get_context().get_time();
  const auto& memory = supervisor.memory(diagram->GetSubsystemContext(supervisor, simulator.get_context()));
  run.probes_made = memory.probes_made;
  for (const auto& probe : memory.planner.probes()) run.collapsibilities.push_back(probe.collapsibility);
  return run;
}

}  // namespace cairn::examples
