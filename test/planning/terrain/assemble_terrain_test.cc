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

// A floor over every column of EmptyGrid at z = 0 (layer 2) and its points: 1 cm apart, each of mixture `mixture`.
OccupancyGrid FlatGrid() {
  OccupancyGrid grid = EmptyGrid();
  for (int c = 0; c < 20; ++c) {
    for (int r = 0; r < 10; ++r) Occupy(&grid, Eigen::Vector3d(0.025 + 0.05 * c, 0.025 + 0.05 * r, 0.01), 0.8);
  }
  return grid;
}
// Columns 15..19 of FlatGrid() occupied up to z = 0.11 as well: a step 10 cm up.
void OccupyStep(OccupancyGrid* grid) {
  for (int c = 15; c < 20; ++c) {
    for (int r = 0; r < 10; ++r) Occupy(grid, Eigen::Vector3d(0.025 + 0.05 * c, 0.025 + 0.05 * r, 0.11), 0.8);
  }
}
void SetMixture(const MaterialRegistry& registry, FrictionPointCloud* cloud, int point,
                const std::vector<std::pair<std::string, float>>& mixture) {
  cloud->weights.row(point).setZero();
  for (const auto& [label, weight] : mixture) cloud->weights(point, registry.IndexOf(label)) = weight;
}

// A calibrated segmenter that is right about ceramic but leaves 6 % of each pixel on paper: averaged, the cell
// keeps 6 % at friction 0, and at eta = 0.95 its quantile is 0; fused as independent looks, agreeing points
// sharpen the mixture to ceramic. Points that disagree (a cell where wood meets ceramic) keep both labels.
TEST(AssembleTerrainTest, IndependentFusionSharpensAgreeingPointsAndKeepsDisagreement) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  FrictionPointCloud cloud = Floor(registry, 2.0, "wood", "wood");
  for (int i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d& p = cloud.points_W[static_cast<std::size_t>(i)];
    if (p.x() < 0.5) {
      SetMixture(registry, &cloud, i, {{"ceramic", 0.94f}, {"paper", 0.06f}});
    } else {
      // Column 12 (x in [0.6, 0.65)): wood and ceramic points alternate, each 90 % sure.
      const bool wood = static_cast<int>(std::lround(p.y() * 100.0 - 0.5)) % 2 == 0;
      SetMixture(registry, &cloud, i, {{wood ? "wood" : "ceramic", 0.9f}, {wood ? "ceramic" : "wood", 0.1f}});
    }
  }
  const TerrainMap averaged = AssembleTerrain(FlatGrid(), cloud, registry);
  EXPECT_EQ(averaged.friction(3, 4), 0.0);
  TerrainAssemblyOptions options;
  options.fusion = MaterialFusion::kIndependent;
  const TerrainMap fused = AssembleTerrain(FlatGrid(), cloud, registry, options);
  EXPECT_NEAR(fused.friction(3, 4), Quantile(registry, {{"ceramic", 1.0}}), 1e-4);
  // 25 points per cell, 13 or 12 of each kind: the product leaves about 90/10 between the two materials.
  const double both = fused.friction(12, 4);
  EXPECT_GT(both, Quantile(registry, {{"wood", 1.0}}) - 1e-4);
  EXPECT_LT(both, Quantile(registry, {{"ceramic", 1.0}}) - 0.05);
  // A label some point gives no mass at all is not vetoed by it.
  SetMixture(registry, &cloud, 0, {{"paper", 1.0f}});
  EXPECT_NEAR(AssembleTerrain(FlatGrid(), cloud, registry, options).friction(0, 0),
              Quantile(registry, {{"ceramic", 1.0}}), 1e-4);
}

// A single frame's mismatch leaves a cell 5 cm above a level floor: with outlier_height it loses its ground,
// while the floor around it, a real 10 cm step of five cells and its edge, keep theirs.
TEST(AssembleTerrainTest, HeightOutliersLoseTheirGround) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  OccupancyGrid grid = FlatGrid();
  FrictionPointCloud cloud = Floor(registry, 2.0, "wood", "wood");
  for (std::size_t i = 0; i < cloud.points_W.size(); ++i) {
    Eigen::Vector3d& p = cloud.points_W[i];
    if (p.x() >= 0.25 && p.x() < 0.3 && p.y() >= 0.25 && p.y() < 0.3) p.z() = 0.05;  // column (5, 5)
    if (p.x() >= 0.75) p.z() = 0.1;  // columns 15..19: a step
  }
  Occupy(&grid, Eigen::Vector3d(0.275, 0.275, 0.06), 0.8);
  OccupyStep(&grid);
  EXPECT_NEAR(AssembleTerrain(grid, cloud, registry).height(5, 5), 0.05, 1e-6);
  TerrainAssemblyOptions options;
  options.outlier_height = 0.02;
  options.outlier_radius = 0.1;  // 5 x 5 cells
  const TerrainMap terrain = AssembleTerrain(grid, cloud, registry, options);
  EXPECT_FALSE(terrain.has_ground(5, 5));
  for (int c : {4, 6, 14, 15, 19}) {
    ASSERT_TRUE(terrain.has_ground(c, 5)) << c;
  }
  EXPECT_NEAR(terrain.height(15, 5), 0.1, 1e-6);
  EXPECT_NEAR(terrain.height(14, 5), 0.0, 1e-6);
  // What stood 5 cm above the floor, too narrow for the window, stays an obstacle, and is not bridged as floor.
  ASSERT_EQ(terrain.occupied_voxels().size(), 1u);
  EXPECT_TRUE(terrain.occupied_voxels()[0].center.isApprox(Eigen::Vector3d(0.275, 0.275, 0.075), 1e-9));
  options.max_gap = 0.1;
  EXPECT_FALSE(AssembleTerrain(grid, cloud, registry, options).has_ground(5, 5));
}

// A single frame's centimetre noise on a level floor: median_heights gives each cell its neighbourhood's median,
// which is level again, while the 10 cm step keeps its edge.
TEST(AssembleTerrainTest, MedianHeightsFlattenNoiseAndKeepAStep) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  OccupancyGrid grid = FlatGrid();
  FrictionPointCloud cloud = Floor(registry, 2.0, "wood", "wood");
  for (std::size_t i = 0; i < cloud.points_W.size(); ++i) {
    Eigen::Vector3d& p = cloud.points_W[i];
    const int c = static_cast<int>(p.x() / 0.05), r = static_cast<int>(p.y() / 0.05);
    // Columns 15..19: a step 10 cm up; every column off by up to 8 mm in a checkerboard-like pattern.
    p.z() = (c >= 15 ? 0.1 : 0.0) + 0.008 * (((c * 7 + r * 3) % 5) - 2) / 2.0;
  }
  OccupyStep(&grid);
  TerrainAssemblyOptions options;
  options.outlier_radius = 0.1;
  EXPECT_GT(std::abs(AssembleTerrain(grid, cloud, registry, options).height(3, 3)), 0.003);
  options.median_heights = true;
  const TerrainMap terrain = AssembleTerrain(grid, cloud, registry, options);
  for (int c = 2; c < 13; ++c) {
    for (int r = 2; r < 8; ++r) EXPECT_NEAR(terrain.height(c, r), 0.0, 0.0041) << c << ", " << r;
  }
  EXPECT_NEAR(terrain.height(14, 5), 0.0, 0.0081);
  EXPECT_NEAR(terrain.height(15, 5), 0.1, 0.0081);
}

// Stereo leaves gaps where a surface has no texture: max_gap bridges those between level ground, with the lower
// friction of the two sides, and leaves wider gaps and gaps across a step as they are.
TEST(AssembleTerrainTest, BridgesNarrowGapsBetweenLevelGround) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  OccupancyGrid grid = EmptyGrid();
  FrictionPointCloud all = Floor(registry, 0.3, "wood", "ceramic");
  for (std::size_t i = 0; i < all.points_W.size(); ++i) {
    if (all.points_W[i].x() >= 0.8) all.points_W[i].z() = 0.05;  // columns 16..19 stand 5 cm higher
  }
  // Ground everywhere except: columns 6..7 of rows 2..3 (a hole 10 cm across, between wood in column 5 and
  // ceramic in 8), columns 10..13 of row 6 (20 cm long, 5 cm wide) and column 15 of row 8 (between the floor
  // and the higher columns).
  auto gap = [](int c, int r) {
    return ((r == 2 || r == 3) && (c == 6 || c == 7)) || (r == 6 && c >= 10 && c <= 13) || (r == 8 && c == 15);
  };
  std::vector<int> keep;
  for (int i = 0; i < all.size(); ++i) {
    const Eigen::Vector3d& p = all.points_W[static_cast<std::size_t>(i)];
    const int c = static_cast<int>(p.x() / 0.05), r = static_cast<int>(p.y() / 0.05);
    if (!gap(c, r)) keep.push_back(i);
  }
  FrictionPointCloud cloud;
  cloud.weights.resize(static_cast<Eigen::Index>(keep.size()), registry.size());
  for (std::size_t k = 0; k < keep.size(); ++k) {
    cloud.points_W.push_back(all.points_W[static_cast<std::size_t>(keep[k])]);
    cloud.quantiles.push_back(0.0f);
    cloud.weights.row(static_cast<Eigen::Index>(k)) = all.weights.row(keep[k]);
  }
  for (int c = 0; c < 20; ++c) {
    for (int r = 0; r < 10; ++r) {
      if (!gap(c, r)) Occupy(&grid, Eigen::Vector3d(0.025 + 0.05 * c, 0.025 + 0.05 * r, c >= 16 ? 0.06 : 0.01), 0.8);
    }
  }
  EXPECT_FALSE(AssembleTerrain(grid, cloud, registry).has_ground(6, 2));
  TerrainAssemblyOptions options;
  options.max_gap = 0.1;
  const TerrainMap terrain = AssembleTerrain(grid, cloud, registry, options);
  for (int c : {6, 7}) {
    ASSERT_TRUE(terrain.has_ground(c, 2)) << c;
    EXPECT_NEAR(terrain.height(c, 2), 0.0, 1e-6);
    EXPECT_NEAR(terrain.friction(c, 2), Quantile(registry, {{"wood", 1.0}}), 1e-4);
  }
  // Row 6's gap is 20 cm along x, but each of its cells has ground 5 cm away above and below (rows 5 and 7).
  EXPECT_TRUE(terrain.has_ground(11, 6));
  EXPECT_NEAR(terrain.friction(11, 6), Quantile(registry, {{"ceramic", 1.0}}), 1e-4);
  // Column 15 of row 8: the floor at 0 on one side and 5 cm higher on the other along x; rows 7 and 9 are level
  // with it, so it is bridged along y.
  EXPECT_NEAR(terrain.height(15, 8), 0.0, 1e-6);
  options.max_gap_step = 0.0;
  options.max_gap = 0.05;
  EXPECT_TRUE(AssembleTerrain(grid, cloud, registry, options).has_ground(11, 6));
  EXPECT_FALSE(AssembleTerrain(grid, cloud, registry, options).has_ground(6, 2));  // 10 cm wide: too wide
}

TEST(AssembleTerrainTest, RejectsBadGapAndOutlierOptions) {
  const MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  TerrainAssemblyOptions options;
  options.max_gap = -0.1;
  CAIRN_EXPECT_THROWS_WITH(TerrainAssembler(registry, options), std::invalid_argument,
                           "max_gap is -0.1; it must be in [0, 10] m (0: bridge no gap)");
  options = TerrainAssemblyOptions();
  options.outlier_radius = 0.0;
  CAIRN_EXPECT_THROWS_WITH(TerrainAssembler(registry, options), std::invalid_argument,
                           "outlier_radius is 0; it must be in (0, 1] m");
  options = TerrainAssemblyOptions();
  options.outlier_height = std::nan("");
  CAIRN_EXPECT_THROWS_WITH(TerrainAssembler(registry, options), std::invalid_argument, "outlier_height is nan");
}

}  // namespace
}  // namespace cairn::planning
