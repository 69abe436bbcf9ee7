// Terrain (issue 19, seed 001): one update of a 10 m x 10 m global map at 5 cm (200 x 200 cells) from a 640 x 480
// point cloud — elevation fusion (eq. 1 with the D435 noise model), slope and roughness, hierarchical
// traversability (Algorithm 1) — on 1 and 2 threads; and the parts alone. The paper runs its pipeline at 5 Hz;
// elevation_mapping users report 0.5-3 s per update on comparable maps; the aim is at most 20 ms on 2 cores.
// Also: A* across the map (planning/grid), and one probe of the arm in the physics plant (planning/scenarios).

#include <cmath>
#include <random>
#include <string>

#include <benchmark/benchmark.h>

#include "cairn/perception/terrain/elevation_fusion.h"
#include "cairn/perception/terrain/hierarchical_traversability.h"
#include "cairn/perception/terrain/semantic_fusion.h"
#include "cairn/perception/terrain/slope_roughness_filter.h"
#include "cairn/planning/grid/grid_search.h"
#include "cairn/planning/scenarios/probe_arm_plant.h"

namespace {

using cairn::perception::ElevationFusion;
using cairn::perception::GridMap;
using cairn::perception::HierarchicalTraversability;
using cairn::perception::SlopeRoughnessFilter;

// A 640 x 480 depth camera 1.2 m above gently rolling ground, pitched down 35 degrees, seeing up to ~8 m ahead.
struct Cloud {
  Eigen::Matrix3Xd points;
  Eigen::Vector3d sensor{0.0, -4.5, 1.2};
  Cloud() : points(3, 640 * 480) {
    std::mt19937 rng(1);
    std::normal_distribution<double> noise(0.0, 0.01);
    const double pitch = 35.0 * M_PI / 180.0;
    const double fx = 380.0;
    int k = 0;
    for (int v = 0; v < 480; ++v) {
      for (int u = 0; u < 640; ++u, ++k) {
        // Ray in a camera looking along +y, pitched down; intersect with z = 0, then add relief.
        const Eigen::Vector3d ray_c((u - 320.0) / fx, 1.0, -(v - 240.0) / fx);
        const Eigen::Vector3d ray(ray_c.x(), ray_c.y() * std::cos(pitch) + ray_c.z() * std::sin(pitch),
                                  -ray_c.y() * std::sin(pitch) + ray_c.z() * std::cos(pitch));
        const double t = ray.z() < -1e-3 ? -sensor.z() / ray.z() : 100.0;
        Eigen::Vector3d p = sensor + t * ray;
        p.z() = 0.05 * std::sin(p.x()) * std::cos(0.7 * p.y()) + noise(rng);
        points.col(k) = p;
      }
    }
  }
};

const Cloud& SharedCloud() {
  static const Cloud cloud;
  return cloud;
}

GridMap MakeMap() {
  GridMap map(Eigen::Vector2i(200, 200), 0.05, Eigen::Vector2d::Zero());
  ElevationFusion::AddLayers(&map);
  return map;
}

void BM_TerrainUpdate(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  GridMap map = MakeMap();
  ElevationFusion::Options eo;
  eo.num_threads = threads;
  ElevationFusion elevation(eo);
  SlopeRoughnessFilter::Options fo;
  fo.num_threads = threads;
  const SlopeRoughnessFilter filter(fo);
  HierarchicalTraversability::Options to;
  to.num_threads = threads;
  const HierarchicalTraversability traversability(to);
  const Cloud& cloud = SharedCloud();
  for (auto _ : state) {
    elevation.Integrate(cloud.points, cloud.sensor, &map);
    filter.Compute(&map);
    traversability.Compute(&map);
    benchmark::DoNotOptimize(map.layer_data(0).data());
  }
  state.counters["points"] = static_cast<double>(cloud.points.cols());
  state.counters["fused"] = static_cast<double>(elevation.last_stats().fused);
}
BENCHMARK(BM_TerrainUpdate)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ElevationFusion(benchmark::State& state) {
  GridMap map = MakeMap();
  ElevationFusion::Options eo;
  eo.num_threads = static_cast<int>(state.range(0));
  ElevationFusion elevation(eo);
  const Cloud& cloud = SharedCloud();
  for (auto _ : state) elevation.Integrate(cloud.points, cloud.sensor, &map);
}
BENCHMARK(BM_ElevationFusion)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SlopeRoughness(benchmark::State& state) {
  GridMap map = MakeMap();
  ElevationFusion elevation;
  elevation.Integrate(SharedCloud().points, SharedCloud().sensor, &map);
  SlopeRoughnessFilter::Options fo;
  fo.num_threads = static_cast<int>(state.range(0));
  const SlopeRoughnessFilter filter(fo);
  for (auto _ : state) filter.Compute(&map);
}
BENCHMARK(BM_SlopeRoughness)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_GridAStar(benchmark::State& state) {
  cairn::planning::TraversabilityGrid grid;
  grid.resolution = 0.05;
  grid.values = Eigen::MatrixXd::Ones(200, 200);
  for (int i = 40; i < 160; ++i) grid.values(i, 100) = 0.0;  // a wall to go around
  const cairn::planning::GridSearch search;
  for (auto _ : state) {
    benchmark::DoNotOptimize(search.Plan(grid, Eigen::Vector2i(100, 5), Eigen::Vector2i(100, 195)).cost);
  }
}
BENCHMARK(BM_GridAStar)->Unit(benchmark::kMillisecond);

// One probe (ProbeArmPlant::Run: the arm reaches out, pushes its tip 2 cm into the ground and holds, 0.5 ms Bullet
// steps): argument 0 soft soil (750 N/m, as under the scenario's soft plants), 1 deep water (no support).
void BM_ProbeInThePlant(benchmark::State& state) {
  const cairn::planning::ProbeArmPlant arm = cairn::planning::ProbeArmPlant::Load(
      std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_probe_arm.urdf", cairn::planning::ProbeArmPlant::Options{});
  cairn::planning::ProbeArmPlant::Ground ground;
  ground.stiffness = state.range(0) == 0 ? 750.0 : 0.0;
  ground.damping = state.range(0) == 0 ? 50.0 : 0.0;
  std::mt19937 rng(1);
  double simulated = 0.0;
  for (auto _ : state) {
    const auto probe = arm.Run(Eigen::Vector2d::Zero(), Eigen::Vector2d(0.6, 0.2), ground, &rng);
    simulated = probe.simulated_time;
    benchmark::DoNotOptimize(probe.forces.data());
  }
  state.counters["simulated_s"] = simulated;
}
BENCHMARK(BM_ProbeInThePlant)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
