// Cairn::planning_terrain: a floor seen by an occupancy grid and friction points of one material becomes a
// terrain whose cells carry the material's (1 - eta) friction quantile, and an occupied cell above the ground a
// voxel that lowers a body box's free probability.
#include <cmath>
#include <cstdio>

#include <cairn/perception/friction/friction_quantile.h>
#include <cairn/planning/terrain/assemble_terrain.h>

int main() {
  using namespace cairn;
  perception::OccupancyGrid grid(Eigen::Vector3d(0.0, 0.0, -0.1), 0.1, Eigen::Vector3i(4, 4, 10));
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) grid.Update(grid.Index(Eigen::Vector3i(c, r, 1)), 2.0f);
  }
  grid.Update(grid.Index(Eigen::Vector3i(2, 2, 8)), 2.0f);
  const perception::MaterialRegistry registry = perception::MaterialRegistry::ThesisTable33();
  perception::FrictionPointCloud points;
  points.points_W.emplace_back(0.15, 0.15, 0.02);
  points.quantiles.push_back(0.0f);
  points.weights = Eigen::MatrixXf::Zero(1, registry.size());
  points.weights(0, registry.IndexOf("wood")) = 1.0f;
  const planning::TerrainMap terrain = planning::AssembleTerrain(grid, points, registry);
  Eigen::VectorXd wood = Eigen::VectorXd::Zero(registry.size());
  wood(registry.IndexOf("wood")) = 1.0;
  const double expected = perception::FrictionQuantile(registry, wood, 0.95, perception::QuantileMethod::kExact);
  const double free = terrain.BoxFreeProbability(Eigen::Vector3d(0.25, 0.25, 0.75), Eigen::Vector3d(0.1, 0.1, 0.1), 0.0);
  std::printf("consumer planning_terrain: %d x %d cells, friction %.3f at (1, 1), %zu voxels, free probability %.3f\n",
              terrain.cols(), terrain.rows(), terrain.friction(1, 1), terrain.occupied_voxels().size(), free);
  const bool right = std::abs(terrain.friction(1, 1) - expected) < 1e-4 && std::abs(terrain.height(1, 1) - 0.02) < 1e-6 &&
                     !terrain.walkable(0, 0) && terrain.occupied_voxels().size() == 1 && free < 0.5;
  return right ? 0 : 1;
}
