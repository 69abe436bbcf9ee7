#include <cairn/planning/terrain/assemble_terrain.h>

#include <cmath>

#include <gtest/gtest.h>

#include <cairn/perception/friction/friction_quantile.h>
#include <cairn/planning/terrain/terrain_assembler.h>

#include "expect_throws.h"

namespace cairn::planning {
namespace {

using perception::FrictionPointCloud;
using perception::MaterialRegistry;
using perception::OccupancyGrid;

// 20 x 10 columns of 5 cm over x in [0, 1], y in [0, 0.5]; 16 layers from z = -0.1 to 0.7.
OccupancyGrid EmptyGrid() { return OccupancyGrid(Eigen::Vector3d(0.0, 0.0, -0.1), 0.05, Eigen::Vector3i(20, 10, 16)); }

// Raises a cell to about `p` (one Bayes update from the prior).
void Occupy(OccupancyGrid* grid, const Eigen::Vector3d& p_W, double p) {
  grid->Update(grid->Index(*grid->CellOf(p_W)), static_cast<float>(std::log(p / (1.0 - p))));
}

// Points on z = height(x, y) every 1 cm, all of material `label` where x < split and `other` beyond.
FrictionPointCloud Floor(const MaterialRegistry& registry, double split, const std::string& label,
                         const std::string& other, double tilt = 0.0) {
  FrictionPointCloud cloud;
  std::vector<Eigen::VectorXf> rows;
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 50; ++j) {
      const double x = 0.005 + 0.01 * i, y = 0.005 + 0.01 * j;
      cloud.points_W.emplace_back(x, y, tilt * x);
      Eigen::VectorXf w = Eigen::VectorXf::Zero(registry.size());
      w(registry.IndexOf(x < split ? label : other)) = 1.0f;
      rows.push_back(w);
      cloud.quantiles.push_back(0.0f);  // not read: the assembler recomputes the quantile of the fused mixture
    }
  }
  cloud.weights.resize(static_cast<Eigen::Index>(rows.size()), registry.size());
  for (std::size_t k = 0; k < rows.size(); ++k) cloud.weights.row(static_cast<Eigen::Index>(k)) = rows[k].transpose();
  return cloud;
}

double Quantile(const MaterialRegistry& registry, const std::vector<std::pair<std::string, double>>& mixture) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(registry.size());
  for (const auto& [label, weight] : mixture) w(registry.IndexOf(label)) = weight;
  return perception::FrictionQuantile(registry, w, 0.95, perception::QuantileMethod::kExact);
}

TEST(AssembleTerrainTest, GroundHeightFromTheSurfacePointsAndFrictionFromTheFusedMixture) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  OccupancyGrid grid = EmptyGrid();
  // The floor surface z = 0 lies in layer 2 ([0, 0.05)) of every column.
  for (int c = 0; c < 20; ++c) {
    for (int r = 0; r < 10; ++r) Occupy(&grid, Eigen::Vector3d(0.025 + 0.05 * c, 0.025 + 0.05 * r, 0.01), 0.8);
  }
  // Wood up to x = 0.52, ceramic beyond: column 10 (x in [0.5, 0.55)) holds 2 cm of wood and 3 cm of ceramic.
  const FrictionPointCloud cloud = Floor(registry, 0.52, "wood", "ceramic");
  const TerrainMap terrain = AssembleTerrain(grid, cloud, registry);
  ASSERT_EQ(terrain.cols(), 20);
  ASSERT_EQ(terrain.rows(), 10);
  EXPECT_DOUBLE_EQ(terrain.resolution(), 0.05);
  for (int c = 0; c < 20; ++c) {
    ASSERT_TRUE(terrain.has_ground(c, 4)) << c;
    EXPECT_NEAR(terrain.height(c, 4), 0.0, 1e-6);  // the points' height, not the cell's face at 0.05
    EXPECT_NEAR(terrain.normal(c, 4).z(), 1.0, 1e-9);
  }
  EXPECT_NEAR(terrain.friction(3, 4), Quantile(registry, {{"wood", 1.0}}), 1e-4);
  EXPECT_NEAR(terrain.friction(15, 4), Quantile(registry, {{"ceramic", 1.0}}), 1e-4);
  // The boundary cell: the quantile of the 40/60 mixture, below either material's own quantile... and below
  // the 40/60 average of the two quantiles, which a per-point average would have given.
  const double mixed = Quantile(registry, {{"wood", 0.4}, {"ceramic", 0.6}});
  EXPECT_NEAR(terrain.friction(10, 4), mixed, 1e-4);
  EXPECT_LT(mixed, 0.4 * terrain.friction(3, 4) + 0.6 * terrain.friction(15, 4));
  EXPECT_TRUE(terrain.occupied_voxels().empty());
}

TEST(AssembleTerrainTest, UnseenGroundIsNotWalkableAndObstaclesBecomeVoxels) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  OccupancyGrid grid = EmptyGrid();
  for (int c = 0; c < 20; ++c) {
    for (int r = 0; r < 10; ++r) Occupy(&grid, Eigen::Vector3d(0.025 + 0.05 * c, 0.025 + 0.05 * r, 0.01), 0.8);
  }
  // A post in column (5, 5) from the floor to z = 0.6, seen with probability 0.7; the part above
  // max_ground_height (0.3) blocks bodies.
  for (double z = 0.075; z < 0.6; z += 0.05) Occupy(&grid, Eigen::Vector3d(0.275, 0.275, z), 0.7);
  FrictionPointCloud cloud = Floor(registry, 2.0, "wood", "wood");
  // No points beyond x = 0.8: the camera did not see that part of the floor; nor under the post, which hides it.
  FrictionPointCloud seen;
  std::vector<int> keep;
  for (int i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d& p = cloud.points_W[static_cast<std::size_t>(i)];
    const bool under_post = p.x() >= 0.25 && p.x() < 0.3 && p.y() >= 0.25 && p.y() < 0.3;
    if (p.x() < 0.8 && !under_post) keep.push_back(i);
  }
  seen.weights.resize(static_cast<Eigen::Index>(keep.size()), registry.size());
  for (std::size_t k = 0; k < keep.size(); ++k) {
    seen.points_W.push_back(cloud.points_W[static_cast<std::size_t>(keep[k])]);
    seen.quantiles.push_back(0.0f);
    seen.weights.row(static_cast<Eigen::Index>(k)) = cloud.weights.row(keep[k]);
  }
  TerrainMap terrain = AssembleTerrain(grid, seen, registry);
  EXPECT_TRUE(terrain.has_ground(18, 2));
  EXPECT_FALSE(terrain.walkable(18, 2));  // seen as ground, material unknown
  EXPECT_NEAR(terrain.height(18, 2), 0.05, 1e-9);  // the occupied cell's top face: no point to refine it
  TerrainAssemblyOptions trusting;
  trusting.unknown_friction = 0.5;
  EXPECT_DOUBLE_EQ(AssembleTerrain(grid, seen, registry, trusting).friction(18, 2), 0.5);
  // The post: no point confirms any of its cells, so its ground is its highest cell below 0.3 m, and the six cells
  // above are voxels of probability 0.7.
  EXPECT_NEAR(terrain.height(5, 5), 0.3, 1e-6);  // heights are stored as float
  ASSERT_EQ(terrain.occupied_voxels().size(), 6u);
  for (const TerrainMap::OccupiedVoxel& v : terrain.occupied_voxels()) {
    EXPECT_NEAR(v.probability, 0.7, 1e-6);
    EXPECT_NEAR(v.center.x(), 0.275, 1e-9);
    EXPECT_GT(v.center.z(), 0.3);
  }
  EXPECT_NEAR(terrain.BoxFreeProbability(Eigen::Vector3d(0.275, 0.275, 0.8), Eigen::Vector3d(0.15, 0.25, 0.35), 0.0),
              std::pow(0.3, 3), 1e-6);  // the body from z = 0.45 overlaps the voxels at 0.475, 0.525 and 0.575
}

TEST(AssembleTerrainTest, NormalsFollowATiltedFloor) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  OccupancyGrid grid = EmptyGrid();
  const double tilt = 0.2;  // z = 0.2 x
  for (int c = 0; c < 20; ++c) {
    for (int r = 0; r < 10; ++r) {
      const double x = 0.025 + 0.05 * c;
      Occupy(&grid, Eigen::Vector3d(x, 0.025 + 0.05 * r, tilt * x), 0.8);
    }
  }
  const TerrainMap terrain = AssembleTerrain(grid, Floor(registry, 2.0, "wood", "wood", tilt), registry);
  const Eigen::Vector3d expected = Eigen::Vector3d(-tilt, 0.0, 1.0).normalized();
  for (int c = 1; c < 19; ++c) {
    ASSERT_TRUE(terrain.has_ground(c, 5));
    EXPECT_LT((terrain.normal(c, 5) - expected).norm(), 0.02) << c;
  }
}

TEST(AssembleTerrainTest, RejectsBadInput) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  FrictionPointCloud cloud;
  cloud.points_W.emplace_back(0.1, 0.1, 0.0);
  cloud.quantiles.push_back(0.5f);
  cloud.weights = Eigen::MatrixXf::Zero(1, 3);
  CAIRN_EXPECT_THROWS_WITH(AssembleTerrain(EmptyGrid(), cloud, registry), std::invalid_argument,
                           "1 x 3 weights; give one quantile and one row of 14 registry-order weights per point");
  TerrainAssemblyOptions options;
  options.eta = 1.0;
  CAIRN_EXPECT_THROWS_WITH(AssembleTerrain(EmptyGrid(), FrictionPointCloud{}, registry, options), std::invalid_argument,
                           "eta is 1; it must be in (0, 1)");
  options = TerrainAssemblyOptions();
  options.min_points = 0;
  CAIRN_EXPECT_THROWS_WITH(TerrainAssembler(registry, options), std::invalid_argument, "min_points is 0");
}

// The system gives AssembleTerrain's result and follows a registry swapped into its context.
TEST(TerrainAssemblerTest, AssemblesItsInputsAndReadsTheRegistryParameter) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  OccupancyGrid grid = EmptyGrid();
  for (int c = 0; c < 20; ++c) {
    for (int r = 0; r < 10; ++r) Occupy(&grid, Eigen::Vector3d(0.025 + 0.05 * c, 0.025 + 0.05 * r, 0.01), 0.8);
  }
  const FrictionPointCloud cloud = Floor(registry, 2.0, "wood", "wood");
  const TerrainAssembler assembler(registry);
  auto context = assembler.CreateDefaultContext();
  assembler.get_grid_input_port().FixValue(context.get(), grid);
  assembler.get_friction_points_input_port().FixValue(context.get(), cloud);
  const TerrainMap& terrain = assembler.get_terrain_output_port().Eval<TerrainMap>(*context);
  EXPECT_NEAR(terrain.friction(4, 4), Quantile(registry, {{"wood", 1.0}}), 1e-4);
  // Wet wood learned from contact: the registry parameter changes, and so does the terrain.
  std::vector<MaterialRegistry::Material> materials = registry.materials();
  materials[static_cast<std::size_t>(registry.IndexOf("wood"))].friction = perception::FrictionDistribution::Normal(0.2, 0.02);
  const MaterialRegistry learned(materials);
  context->get_mutable_abstract_parameter<MaterialRegistry>(assembler.registry_parameter()) = learned;
  const TerrainMap& relearned = assembler.get_terrain_output_port().Eval<TerrainMap>(*context);
  EXPECT_LT(relearned.friction(4, 4), 0.2);
  EXPECT_GT(relearned.friction(4, 4), 0.1);
}

// A single stereo frame leaves stray occupied cells above a floor, and a floor on a layer boundary spreads its
// points over two layers: the ground is the highest occupied cell the surface's points confirm, its friction
// comes from all the surface's points, and the stray cell becomes an obstacle voxel.
TEST(AssembleTerrainTest, TheSurfacePointsConfirmTheGroundCell) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  OccupancyGrid grid = EmptyGrid();
  // The floor z = 0 is the boundary of layers 1 ([-0.05, 0)) and 2; occupancy marked layer 2 only.
  for (int c = 0; c < 20; ++c) {
    for (int r = 0; r < 10; ++r) Occupy(&grid, Eigen::Vector3d(0.025 + 0.05 * c, 0.025 + 0.05 * r, 0.01), 0.8);
  }
  // A stray occupied cell in layer 4 ([0.1, 0.15)) of column (7, 3).
  Occupy(&grid, Eigen::Vector3d(0.375, 0.175, 0.125), 0.6);
  FrictionPointCloud cloud = Floor(registry, 2.0, "wood", "wood");
  // Half of the points 2 mm below the boundary (layer 1), half 2 mm above (layer 2).
  for (std::size_t i = 0; i < cloud.points_W.size(); ++i) cloud.points_W[i].z() = (i % 2 == 0) ? -0.002 : 0.002;
  const TerrainMap terrain = AssembleTerrain(grid, cloud, registry);
  for (int c : {3, 7}) {
    EXPECT_NEAR(terrain.height(c, 3), 0.0, 0.0021) << c;  // the points' median, not a face of a cell
    EXPECT_NEAR(terrain.friction(c, 3), Quantile(registry, {{"wood", 1.0}}), 1e-4) << c;
  }
  ASSERT_EQ(terrain.occupied_voxels().size(), 1u);
  EXPECT_TRUE(terrain.occupied_voxels()[0].center.isApprox(Eigen::Vector3d(0.375, 0.175, 0.125), 1e-9));
  EXPECT_NEAR(terrain.occupied_voxels()[0].probability, 0.6, 1e-6);
}

}  // namespace
}  // namespace cairn::planning
