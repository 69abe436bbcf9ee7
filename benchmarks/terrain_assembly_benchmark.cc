// TerrainAssembler's work per frame (issue 18's perception loop, last stage): an occupancy grid of 6.4 x 6.4 x 1.6 m
// at 5 cm (128 x 128 x 32 cells) holding a floor and a few obstacles, and the friction points of a 640 x 480 depth
// image (307,200 points, 14 registry labels, two materials) assembled into the planners' TerrainMap: ground
// heights, normals, the fused mixtures' Q_{1-eta} (exact) and the occupied voxels. One thread.

#include <cmath>

#include <benchmark/benchmark.h>

#include <cairn/planning/terrain/assemble_terrain.h>

namespace {

using namespace cairn;

void BM_AssembleTerrain(benchmark::State& state) {
  perception::OccupancyGrid grid(Eigen::Vector3d(0.0, -3.2, -0.1), 0.05, Eigen::Vector3i(128, 128, 32));
  for (int c = 0; c < 128; ++c) {
    for (int r = 0; r < 128; ++r) {
      grid.Update(grid.Index(Eigen::Vector3i(c, r, 2)), 1.5f);
      if ((c / 16 + r / 16) % 5 == 0) {
        for (int k = 3; k < 20; ++k) grid.Update(grid.Index(Eigen::Vector3i(c, r, k)), 1.0f);
      }
    }
  }
  const perception::MaterialRegistry registry = perception::MaterialRegistry::ThesisTable33();
  perception::FrictionPointCloud points;
  const int n = 640 * 480;
  points.weights = Eigen::MatrixXf::Zero(n, registry.size());
  for (int i = 0; i < n; ++i) {
    const double x = 0.5 + 5.5 * (i % 640) / 640.0, y = -3.0 + 6.0 * (i / 640) / 480.0;
    points.points_W.emplace_back(x, y, 0.01);
    points.quantiles.push_back(0.0f);
    points.weights(i, registry.IndexOf(x < 3.0 ? "wood" : "ceramic")) = 0.9f;
    points.weights(i, registry.IndexOf("cloth")) = 0.1f;
  }
  std::size_t voxels = 0;
  for (auto _ : state) {
    const planning::TerrainMap terrain = planning::AssembleTerrain(grid, points, registry);
    voxels = terrain.occupied_voxels().size();
    benchmark::DoNotOptimize(terrain.friction(10, 10));
  }
  state.counters["voxels"] = static_cast<double>(voxels);
  state.counters["points"] = n;
}
BENCHMARK(BM_AssembleTerrain)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
