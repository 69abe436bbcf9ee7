#include "cairn/planning/scenarios/traverse_simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/perception/terrain/collapsibility_estimator.h"
#include "cairn/perception/terrain/elevation_fusion.h"
#include "cairn/perception/terrain/hierarchical_traversability.h"
#include "cairn/perception/terrain/kalman_cell_update.h"
#include "cairn/perception/terrain/semantic_fusion.h"
#include "cairn/perception/terrain/slope_roughness_filter.h"
#include "cairn/planning/grid/grid_search.h"
#include "cairn/planning/grid/probing_planner.h"

namespace cairn::planning {
namespace {

using perception::GridMap;

// Sample rate of the simulated force sensor, Hz.
constexpr double kForceSensorRate = 200.0;

TraversabilityGrid ToGrid(const GridMap& map, int layer) {
  TraversabilityGrid grid;
  grid.resolution = map.resolution();
  grid.min_corner = map.min_corner();
  grid.values.resize(map.size().x(), map.size().y());
  for (int i = 0; i < map.size().x(); ++i) {
    for (int j = 0; j < map.size().y(); ++j) grid.values(i, j) = map.at(layer, i, j);
  }
  return grid;
}

}  // namespace

ProbeArmPlant TraverseSimulation::MakeProbeArm(const TraverseScenario& scenario, const std::string& urdf_path) {
  if (urdf_path.empty()) {
    throw std::invalid_argument(
        "TraverseSimulation: the scenario probes with the physics plant (probe model 'plant') but no probe arm URDF "
        "was given; pass data/robots/cairn_probe_arm.urdf, or set the probe model to 'spring'");
  }
  ProbeArmPlant::Options o;
  o.depth = scenario.probe_depth;
  o.samples = scenario.probe_samples;
  o.noise = scenario.force_noise;
  o.hold_time = std::max(o.hold_time, scenario.probe_samples / kForceSensorRate);
  ProbeArmPlant arm = ProbeArmPlant::Load(urdf_path, o);
  // In the probing diagram the robot's walker and the supervisor decide in the same period, so the robot may take
  // one more step before it stands still to probe: the target may then be a step further away.
  if (scenario.reach + scenario.step > arm.reach()) {
    throw std::invalid_argument("TraverseSimulation: the scenario's probe reach " + FormatShort(scenario.reach) +
                                " m plus one robot step of " + FormatShort(scenario.step) +
                                " m exceeds the arm's reach of " + FormatShort(arm.reach()) +
                                " m; lower 'probe: reach' or 'robot: step'");
  }
  return arm;
}

TraverseSimulation::TraverseSimulation(TraverseScenario scenario, const Options& options)
    : scenario_(std::move(scenario)), options_(options) {
  if (scenario_.probe_model == TraverseScenario::ProbeModel::kPlant && options_.probing) {
    arm_.emplace(MakeProbeArm(scenario_, options_.probe_arm_urdf));
  }
}

TraverseSimulation::Result TraverseSimulation::Run() const {
  const TraverseScenario& s = scenario_;
  const Eigen::Vector2i size = (s.world_size / s.resolution).array().ceil().cast<int>();
  Result result;
  result.map = GridMap(size, s.resolution, s.world_min + 0.5 * size.cast<double>() * s.resolution);
  GridMap& map = result.map;
  perception::ElevationFusion::Options eo;
  eo.num_threads = options_.num_threads;
  eo.max_range = std::max(eo.max_range, 2.0 * (s.sensor_range + s.sensor_height));
  perception::ElevationFusion elevation(eo);
  perception::ElevationFusion::AddLayers(&map);
  perception::SemanticFusion::Options so;
  so.num_threads = options_.num_threads;
  perception::SemanticFusion semantic(so);  // plants, water: ClassAt's order
  semantic.AddLayers(&map);
  const int collapsibility = map.AddLayer("collapsibility");
  const int collapsibility_variance = map.AddLayer("collapsibility_variance");
  perception::SlopeRoughnessFilter::Options fo;
  fo.num_threads = options_.num_threads;
  const perception::SlopeRoughnessFilter filter(fo);
  perception::HierarchicalTraversability::Options to;
  to.num_threads = options_.num_threads;
  const perception::HierarchicalTraversability traversability(to);
  GridSearch::Options go;
  go.blocked_below = s.blocked_below;
  const GridSearch search(go);
  ProbingPlanner::Options po;
  po.cluster_distance = 1.5 * s.resolution;  // diagonal neighbours connect
  po.reach = s.reach;
  ProbingPlanner prober(po);
  perception::CollapsibilityEstimator::Options co;
  co.hard_force = s.hard_force;
  co.window = s.probe_samples;
  perception::CollapsibilityEstimator estimator(co);

  std::mt19937 rng(static_cast<std::mt19937::result_type>(s.seed));
  std::normal_distribution<double> unit(0.0, 1.0);
  const int plants = map.LayerIndex(perception::SemanticFusion::LayerName("plants"));
  const int water = map.LayerIndex(perception::SemanticFusion::LayerName("water"));
  const int t_layer = [&] {
    traversability.Compute(&map);
    return map.LayerIndex("traversability");
  }();
  const double threshold = traversability.options().semantic_threshold;

  // The sensor's lattice, fixed in the world so that repeated scans sample the same points.
  const double spacing = s.point_spacing;
  const int span = static_cast<int>(std::ceil(s.sensor_range / spacing));
  Eigen::Matrix3Xd points;
  Eigen::MatrixXd probabilities;
  const auto sense = [&](const Eigen::Vector2d& robot) {
    const Eigen::Vector2d base = ((robot - s.world_min) / spacing).array().floor();
    std::vector<Eigen::Vector2d> xy;
    for (int a = -span; a <= span; ++a) {
      for (int b = -span; b <= span; ++b) {
        const Eigen::Vector2d p = s.world_min + (base + Eigen::Vector2d(a + 0.5, b + 0.5)) * spacing;
        if ((p - robot).norm() > s.sensor_range) continue;
        if ((p.array() < s.world_min.array()).any() || (p.array() >= (s.world_min + s.world_size).array()).any()) {
          continue;
        }
        xy.push_back(p);
      }
    }
    const Eigen::Vector3d sensor(robot.x(), robot.y(), s.sensor_height);
    points.resize(3, static_cast<Eigen::Index>(xy.size()));
    probabilities.resize(2, static_cast<Eigen::Index>(xy.size()));
    const double other = 0.5 * (1.0 - s.segmentation_confidence);
    for (std::size_t k = 0; k < xy.size(); ++k) {
      const Eigen::Vector3d truth(xy[k].x(), xy[k].y(), s.HeightAt(xy[k]));
      const double sigma = elevation.options().noise.StdDev((truth - sensor).norm());
      points.col(k) = truth + Eigen::Vector3d(0.0, 0.0, sigma * unit(rng));
      const int c = s.ClassAt(xy[k]);
      probabilities(0, k) = c == 0 ? s.segmentation_confidence : other;
      probabilities(1, k) = c == 1 ? s.segmentation_confidence : other;
    }
    elevation.Integrate(points, sensor, &map);
    semantic.Integrate(points, probabilities, &map);
    filter.Compute(&map);
    traversability.Compute(&map);
  };
  const auto assign = [&](const std::vector<int>& storage, double c) {
    for (int cell : storage) {
      // Probing touches the ground, so it is far more certain than a segmentation (seed 001 §4.2).
      perception::KalmanCellUpdate(c, traversability.options().probe_variance,
                                   &map.layer_data(collapsibility)[cell],
                                   &map.layer_data(collapsibility_variance)[cell]);
    }
  };

  Eigen::Vector2i goal_cell;
  map.CellOf(s.goal, &goal_cell);
  Eigen::Vector2d robot = s.start;
  result.trajectory.push_back(robot);
  std::vector<Eigen::Vector2i> path;  // what is left of the last plan, from the robot's cell
  const auto plan = [&]() -> bool {
    TraversabilityGrid grid = ToGrid(map, t_layer);
    Eigen::Vector2i start;
    map.CellOf(robot, &start);
    grid.values(start.x(), start.y()) = 1.0;  // the robot stands there already
    if (!path.empty() && std::isinf(search.PathCost(grid, path))) ++result.replans;
    const GridPath p = search.Plan(grid, start, goal_cell);
    if (!p.found) return false;
    path = p.cells;
    std::vector<Eigen::Vector2d> world;
    for (const auto& c : path) world.push_back(map.CellCenter(c));
    if (result.first_path.empty()) result.first_path = world;
    result.last_path = world;
    return true;
  };
  const auto crosses = [&](const std::set<int>& cells) {
    for (const auto& c : path) {
      if (cells.count(map.StorageIndex(c.x(), c.y())) > 0) return true;
    }
    return false;
  };

  for (result.ticks = 0; result.ticks < s.max_ticks; ++result.ticks) {
    Eigen::Vector2i here;
    map.CellOf(robot, &here);
    if (here == goal_cell) {
      result.reached_goal = true;
      return result;
    }
    sense(robot);
    bool probed = false;
    if (options_.probing) {
      std::vector<Eigen::Vector2d> xy;
      std::vector<int> labels, storage;
      for (int cell = 0; cell < static_cast<int>(map.num_cells()); ++cell) {
        if (!std::isnan(map.layer_data(collapsibility)[cell])) continue;
        const double pp = map.layer_data(plants)[cell];
        const double pw = map.layer_data(water)[cell];
        int label = -1;
        if (pp >= threshold && !(pw > pp)) label = 0;
        if (pw >= threshold && !(pp >= pw)) label = 1;
        if (label < 0) continue;
        xy.push_back(map.CellCenter(map.MapIndexOfStorage(cell)));
        labels.push_back(label);
        storage.push_back(cell);
      }
      Eigen::Matrix2Xd questionable(2, static_cast<Eigen::Index>(xy.size()));
      for (std::size_t k = 0; k < xy.size(); ++k) questionable.col(k) = xy[k];
      const auto clusters = prober.FindClusters(questionable, labels);
      const auto cells_of = [&](const ProbingPlanner::Cluster& c) {
        std::vector<int> cells;
        for (int m : c.members) cells.push_back(storage[m]);
        return cells;
      };
      bool inherited = false;
      for (const auto& cluster : clusters) {
        const int probe = prober.TouchingProbe(cluster, questionable);
        if (probe < 0) continue;
        assign(cells_of(cluster), prober.probes()[probe].collapsibility);
        ++result.inherited_clusters;
        inherited = true;
      }
      const auto decision = prober.Decide(clusters, questionable, robot);
      if (decision.action == ProbingPlanner::Decision::Action::kProbe) {
        const auto& cluster = clusters[decision.cluster];
        const std::vector<int> cells = cells_of(cluster);
        const std::set<int> cell_set(cells.begin(), cells.end());
        ProbeRecord record;
        record.tick = result.ticks;
        record.robot = robot;
        record.target = decision.target;
        record.cluster_class = cluster.label == 0 ? "plants" : "water";
        const auto* region = s.RegionAt(decision.target);
        record.region = region != nullptr ? region->name : "";
        record.cluster_cells = static_cast<int>(cells.size());
        record.path_crossed_cluster = crosses(cell_set);
        estimator.Reset();
        if (arm_) {
          ProbeArmPlant::Ground ground;
          ground.height = s.HeightAt(decision.target);
          ground.stiffness = s.StiffnessAt(decision.target);
          ground.damping = s.probe_damping;
          const ProbeArmPlant::Probe probe = arm_->Run(robot, decision.target, ground, &rng);
          for (double f : probe.forces) estimator.AddSample(f);
          record.simulated_time = probe.simulated_time;
        } else {
          const double force = s.StiffnessAt(decision.target) * s.probe_depth;
          for (int k = 0; k < s.probe_samples; ++k) estimator.AddSample(force + s.force_noise * unit(rng));
        }
        record.average_force = estimator.AverageForce();
        record.collapsibility = estimator.Collapsibility();
        assign(cells, record.collapsibility);
        prober.RecordProbe(cluster, questionable, decision.target, record.collapsibility);
        traversability.Compute(&map);
        if (!plan()) {
          result.probes.push_back(record);
          result.failure = "no path to the goal after probing at tick " + FormatShort(result.ticks);
          return result;
        }
        record.path_crosses_after = crosses(cell_set);
        result.probes.push_back(record);
        probed = true;
      } else if (inherited) {
        traversability.Compute(&map);
      }
    }
    if (probed) continue;  // the robot stood still to probe
    if (!plan()) {
      result.failure = "no path to the goal at tick " + FormatShort(result.ticks);
      return result;
    }
    // Walk `step` m along the path.
    double walked = 0.0;
    std::size_t k = 0;
    while (k + 1 < path.size() && walked < s.step - 1e-9) {
      walked += (path[k + 1] - path[k]).cast<double>().norm() * s.resolution;
      ++k;
      const Eigen::Vector2d p = map.CellCenter(path[k]);
      if (s.TrueCollapsibility(p) >= 0.5) ++result.collapsible_steps;
      if (const auto* region = s.RegionAt(p)) {
        if (std::find(result.regions_entered.begin(), result.regions_entered.end(), region->name) ==
            result.regions_entered.end()) {
          result.regions_entered.push_back(region->name);
        }
      }
    }
    result.distance_walked += (map.CellCenter(path[k]) - robot).norm();
    robot = map.CellCenter(path[k]);
    path.erase(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(k));
    result.trajectory.push_back(robot);
  }
  result.failure = "the goal was not reached within " + FormatShort(s.max_ticks) + " ticks";
  return result;
}

}  // namespace cairn::planning
