#include "cairn/planning/scenarios/probing_diagram.h"

#include <cmath>
#include <algorithm>
#include <optional>
#include <set>
#include <utility>
#include <vector>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/perception/terrain/elevation_mapper.h"
#include "cairn/perception/terrain/probe_controller.h"
#include "cairn/perception/terrain/traversability_analyzer.h"
#include "cairn/planning/grid/grid_path_planner.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/primitives/constant_value_source.h"
#include "cairn/systems/primitives/constant_vector_source.h"
#include "cairn/perception/terrain/probed_region.h"
#include "cairn/planning/scenarios/path_follower.h"
#include "cairn/planning/scenarios/probe_arm.h"
#include "cairn/planning/scenarios/probe_supervisor.h"
#include "cairn/planning/scenarios/scenario_sensor.h"
#include "cairn/planning/scenarios/traverse_simulation.h"

namespace cairn::planning {

namespace {
constexpr double kPeriod = 0.1;
constexpr double kSamplePeriod = 0.005;
}  // namespace

std::unique_ptr<systems::Diagram> BuildProbingDiagram(const TraverseScenario& s, const std::string& probe_arm_urdf,
                                                      bool probing) {
  systems::DiagramBuilder builder;
  const Eigen::Vector2i size = (s.world_size / s.resolution).array().ceil().cast<int>();
  const perception::GridMap prototype(size, s.resolution, s.world_min + 0.5 * size.cast<double>() * s.resolution);
  perception::ElevationMapper::Options mapper_options;
  mapper_options.elevation.max_range = 2.0 * (s.sensor_range + s.sensor_height);
  auto* sensor = builder.AddNamedSystem<ScenarioSensor>("sensor", s);
  auto* mapper = builder.AddNamedSystem<perception::ElevationMapper>("mapper", prototype, kPeriod, mapper_options);
  auto* analyzer = builder.AddNamedSystem<perception::TraversabilityAnalyzer>("analyzer");
  GridSearch::Options search;
  search.blocked_below = s.blocked_below;
  auto* planner =
      builder.AddNamedSystem<GridPathPlanner>("planner", s.resolution, prototype.min_corner(), search, kPeriod);
  auto* walker = builder.AddNamedSystem<PathFollower>("walker", s.start, s.step, kPeriod);
  auto* goal = builder.AddNamedSystem<systems::ConstantVectorSource>("goal", Eigen::VectorXd(s.goal));
  builder.Connect(walker->get_position_output_port(), sensor->get_robot_input_port());
  builder.Connect(sensor->GetOutputPort("points_W"), mapper->get_points_input_port());
  builder.Connect(sensor->GetOutputPort("sensor_W"), mapper->get_sensor_input_port());
  builder.Connect(sensor->GetOutputPort("probabilities"), mapper->get_probabilities_input_port());
  builder.Connect(mapper->get_map_output_port(), analyzer->get_map_input_port());
  builder.Connect(analyzer->get_traversability_output_port(), planner->get_traversability_input_port());
  builder.Connect(walker->get_position_output_port(), planner->get_start_input_port());
  builder.Connect(goal->get_output_port(), planner->get_goal_input_port());
  builder.Connect(planner->get_path_output_port(), walker->get_path_input_port());
  if (probing) {
    ProbingPlanner::Options options;
    options.cluster_distance = 1.5 * s.resolution;  // diagonal neighbours connect
    options.reach = s.reach;
    // The arm plays its readings one sample period after the command, one every kSamplePeriod, and the
    // ProbeController takes the last one a sample period later: wait until the whole window is in.
    const int probe_periods =
        static_cast<int>(std::floor((s.probe_samples + 2) * kSamplePeriod / kPeriod + 1e-9)) + 1;
    auto* supervisor = builder.AddNamedSystem<ProbeSupervisor>("supervisor", options, 0.5, probe_periods, kPeriod);
    std::optional<ProbeArmPlant> plant;
    if (s.probe_model == TraverseScenario::ProbeModel::kPlant) {
      plant = TraverseSimulation::MakeProbeArm(s, probe_arm_urdf);
    }
    auto* arm = builder.AddNamedSystem<ProbeArm>("arm", s, plant, kSamplePeriod);
    auto* probe = builder.AddNamedSystem<perception::ProbeController>(
        "probe_controller", perception::CollapsibilityEstimator::Options{s.hard_force, s.probe_samples},
        kSamplePeriod);
    builder.Connect(supervisor->get_probes_output_port(), analyzer->get_probes_input_port());
    builder.Connect(analyzer->get_map_output_port(), supervisor->get_map_input_port());
    builder.Connect(walker->get_position_output_port(), supervisor->get_robot_input_port());
    builder.Connect(probe->get_collapsibility_output_port(), supervisor->get_collapsibility_input_port());
    builder.Connect(supervisor->get_probe_command_output_port(), arm->get_command_input_port());
    builder.Connect(walker->get_position_output_port(), arm->get_robot_input_port());
    builder.Connect(arm->get_force_output_port(), probe->get_force_input_port());
    builder.Connect(arm->get_probing_output_port(), probe->get_probing_input_port());
    builder.Connect(supervisor->get_pause_output_port(), walker->get_pause_input_port());
  } else {
    auto* none = builder.AddNamedSystem<systems::ConstantValueSource<std::vector<perception::ProbedRegion>>>(
        "no_probes", std::vector<perception::ProbedRegion>());
    auto* go = builder.AddNamedSystem<systems::ConstantVectorSource>("never_pause", Eigen::VectorXd::Zero(1));
    builder.Connect(none->get_output_port(0), analyzer->get_probes_input_port());
    builder.Connect(go->get_output_port(), walker->get_pause_input_port());
  }
  auto diagram = builder.Build();
  diagram->set_name("probing");
  return diagram;
}

namespace {

std::vector<Eigen::Vector2d> Columns(const Eigen::Matrix2Xd& m) {
  std::vector<Eigen::Vector2d> out;
  for (Eigen::Index k = 0; k < m.cols(); ++k) out.push_back(m.col(k));
  return out;
}

// Whether a path (cell centres) passes through one of `cells` (map cells, as storage-free index pairs).
bool Crosses(const Eigen::Matrix2Xd& path, const std::set<std::pair<int, int>>& cells, const TraverseScenario& s) {
  for (Eigen::Index k = 0; k < path.cols(); ++k) {
    const Eigen::Vector2d c = ((path.col(k) - s.world_min) / s.resolution).array().floor();
    if (cells.count({static_cast<int>(c.x()), static_cast<int>(c.y())}) > 0) return true;
  }
  return false;
}

}  // namespace

ProbingRun RunProbingDiagram(const TraverseScenario& scenario, const std::string& probe_arm_urdf, double max_time,
                             bool probing) {
  if (!(max_time > 0.0) || !std::isfinite(max_time) || max_time > kPeriod * TraverseScenario::kMaxTicks) {
    throw std::invalid_argument("RunProbingDiagram: max_time " + FormatShort(max_time) + " s must be in (0, " +
                                FormatShort(kPeriod * TraverseScenario::kMaxTicks) + "]");
  }
  const TraverseScenario& s = scenario;
  auto diagram = BuildProbingDiagram(scenario, probe_arm_urdf, probing);
  const auto& walker = static_cast<const PathFollower&>(diagram->GetSubsystemByName("walker"));
  const auto& planner = static_cast<const GridPathPlanner&>(diagram->GetSubsystemByName("planner"));
  const auto& analyzer =
      static_cast<const perception::TraversabilityAnalyzer&>(diagram->GetSubsystemByName("analyzer"));
  const ProbeSupervisor* supervisor =
      probing ? &static_cast<const ProbeSupervisor&>(diagram->GetSubsystemByName("supervisor")) : nullptr;
  const ProbeArm* arm = probing ? &static_cast<const ProbeArm&>(diagram->GetSubsystemByName("arm")) : nullptr;
  systems::Simulator simulator(*diagram);
  const systems::Context& root = simulator.get_context();
  ProbingRun run;
  run.final_position = s.start;
  run.trajectory.push_back(s.start);
  Eigen::Matrix2Xd path_before;
  const int max_ticks = static_cast<int>(std::floor(max_time / kPeriod + 1e-9));
  int open_probe = -1;  // the record of a probe whose path after is still to be seen
  double simulated_before = 0.0;
  int close_tick = -1;
  std::set<std::pair<int, int>> open_cells;
  for (run.ticks = 1; run.ticks <= max_ticks; ++run.ticks) {
    simulator.AdvanceTo(run.ticks * kPeriod);
    const systems::Context& planner_context = diagram->GetSubsystemContext(planner, root);
    const auto& path = planner.get_path_output_port().Eval<Eigen::Matrix2Xd>(planner_context);
    const Eigen::VectorXd& status =
        planner.get_status_output_port().Eval<Eigen::VectorXd>(planner_context);
    if (status[0] >= 0.5) {
      if (run.first_path.empty()) run.first_path = Columns(path);
      run.last_path = Columns(path);
    }
    run.replans = static_cast<int>(status[2]);
    if (supervisor != nullptr) {
      const auto& memory = supervisor->memory(diagram->GetSubsystemContext(*supervisor, root));
      if (open_probe >= 0 && close_tick < 0 && !memory.probing && memory.probes_made > open_probe) {
        // The supervisor holds the probe's C now; the planner's update of the next period is the first to plan on
        // a map that has it.
        close_tick = run.ticks + 1;
      }
      if (open_probe >= 0 && close_tick >= 0 && run.ticks >= close_tick) {
        close_tick = -1;
        TraverseSimulation::ProbeRecord& record = run.probes[static_cast<std::size_t>(open_probe)];
        record.collapsibility = memory.planner.probes()[static_cast<std::size_t>(open_probe)].collapsibility;
        const ProbeArm::Memory& readings = arm->memory(diagram->GetSubsystemContext(*arm, root));
        double sum = 0.0;
        for (double f : readings.readings) sum += f;
        record.average_force = readings.readings.empty() ? 0.0 : sum / static_cast<double>(readings.readings.size());
        record.simulated_time = readings.simulated_time - simulated_before;
        simulated_before = readings.simulated_time;
        record.path_crosses_after = status[0] >= 0.5 && Crosses(path, open_cells, s);
        run.collapsibilities.push_back(record.collapsibility);
        open_probe = -1;
      }
      if (memory.probing && static_cast<int>(run.probes.size()) == memory.probes_made) {
        TraverseSimulation::ProbeRecord record;
        record.tick = run.ticks;
        record.robot = run.final_position;
        record.target = memory.target;
        record.cluster_class = memory.cluster.label == 0 ? "plants" : "water";
        const auto* region = s.RegionAt(memory.target);
        record.region = region != nullptr ? region->name : "";
        record.cluster_cells = static_cast<int>(memory.cluster.members.size());
        // The cluster's cells, kept: the supervisor's cluster changes with the next probe or inheritance.
        open_cells.clear();
        for (int k : memory.cluster.members) {
          const Eigen::Vector2d c = ((memory.cluster_points.col(k) - s.world_min) / s.resolution).array().floor();
          open_cells.insert({static_cast<int>(c.x()), static_cast<int>(c.y())});
        }
        record.path_crossed_cluster = Crosses(path_before, open_cells, s);
        open_probe = static_cast<int>(run.probes.size());
        run.probes.push_back(record);
      }
      run.probes_made = memory.probes_made;
      run.inherited_clusters = static_cast<int>(memory.probes.size()) - memory.probes_made;
    }
    path_before = path;
    const Eigen::Vector2d p =
        walker.get_position_output_port().Eval<Eigen::VectorXd>(diagram->GetSubsystemContext(walker, root));
    if ((p - run.final_position).norm() > 1e-12) {
      run.distance_walked += (p - run.final_position).norm();
      run.trajectory.push_back(p);
      if (s.TrueCollapsibility(p) >= 0.5) ++run.collapsible_steps;
      if (const auto* region = s.RegionAt(p)) {
        if (std::find(run.regions_entered.begin(), run.regions_entered.end(), region->name) ==
            run.regions_entered.end()) {
          run.regions_entered.push_back(region->name);
        }
      }
    }
    run.final_position = p;
    if ((p - s.goal).norm() <= s.resolution) {
      run.reached_goal = true;
      break;
    }
    if (status[0] < 0.5 && (supervisor == nullptr ||
                            !supervisor->memory(diagram->GetSubsystemContext(*supervisor, root)).probing)) {
      run.failure = "no path to the goal at " + FormatShort(run.ticks * kPeriod) + " s";
      break;
    }
  }
  if (!run.reached_goal && run.failure.empty()) {
    run.failure = "the goal was not reached within " + FormatShort(max_time) + " s";
  }
  run.ticks = std::min(run.ticks, max_ticks);
  run.time = root.get_time();
  run.map = analyzer.get_map_output_port().Eval<perception::GridMap>(diagram->GetSubsystemContext(analyzer, root));
  if (arm != nullptr) run.probe_simulated_time = arm->memory(diagram->GetSubsystemContext(*arm, root)).simulated_time;
  return run;
}

}  // namespace cairn::planning
