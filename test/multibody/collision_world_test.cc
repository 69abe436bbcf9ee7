#include <cairn/multibody/collision_world.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/model_builder.h>

#include "expect_throws.h"
#include "test_models.h"

namespace cairn::multibody {
namespace {

class CollisionWorldTest : public ::testing::Test {
 protected:
  CollisionWorldTest() : model_(test::LoadRobot(test::HumanoidUrdf(), true)), data_(model_), world_(model_) {
    q_ = NeutralConfiguration(model_);
    q_[model_.joint(model_.GetJointIndex("root_joint")).idx_q + 2] = 0.87;  // soles 1 cm above the ground
    ground_ = world_.AddBox("ground", Eigen::Vector3d(4, 4, 0.1),
                            Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, -0.05)));
    Update(q_);
  }
  void Update(const Eigen::VectorXd& q) {
    ForwardKinematics(model_, data_, q);
    world_.UpdatePoses(model_, data_);
  }
  Model model_;
  Data data_;
  CollisionWorld world_;
  Eigen::VectorXd q_;
  int ground_ = -1;
};

TEST_F(CollisionWorldTest, StandingHumanoidIsCollisionFreeAndClosestToTheGround) {
  EXPECT_EQ(world_.num_geometries(), 20 + 1);
  const std::vector<CollisionPair> close = world_.PairsWithin(0.0);
  for (const CollisionPair& pair : close) {
    ADD_FAILURE() << world_.geometry_name(pair.geometry_a) << " - " << world_.geometry_name(pair.geometry_b) << ": "
                  << pair.result.distance;
  }
  const CollisionPair closest = world_.ClosestPair();
  EXPECT_EQ(world_.geometry_body(closest.geometry_b), -1);
  EXPECT_THAT(world_.geometry_name(closest.geometry_a), ::testing::HasSubstr("sole_box"));
  EXPECT_NEAR(closest.result.distance, 0.01, 1e-6);
  EXPECT_NEAR(closest.result.normal.z(), -1.0, 1e-6);  // from the sole towards the ground
  // Sorted, deterministic output.
  const std::vector<CollisionPair> pairs = world_.PairsWithin(0.05);
  ASSERT_GE(pairs.size(), 2u);
  for (std::size_t i = 1; i < pairs.size(); ++i) {
    EXPECT_LT(std::min(pairs[i - 1].geometry_a, pairs[i - 1].geometry_b),
              std::min(pairs[i].geometry_a, pairs[i].geometry_b) + 1);
  }
}

TEST_F(CollisionWorldTest, FiltersAdjacentAndExcludedPairs) {
  const int thigh = world_.GetGeometryIndex("capsule_l_thigh");
  const int shank = world_.GetGeometryIndex("capsule_l_shank");
  const int pelvis = world_.GetGeometryIndex("pelvis_box");
  EXPECT_FALSE(world_.IsPairChecked(thigh, shank));  // knee: parent and child
  EXPECT_TRUE(world_.IsPairChecked(pelvis, thigh));
  EXPECT_FALSE(world_.IsPairChecked(ground_, ground_));
  world_.ExcludeBodyPair("pelvis", "l_thigh");
  EXPECT_FALSE(world_.IsPairChecked(pelvis, thigh));
  const int sole = world_.GetGeometryIndex("l_sole_box");
  world_.ExcludeGeometryPair("l_sole_box", "ground");
  EXPECT_FALSE(world_.IsPairChecked(sole, ground_));
  for (const CollisionPair& pair : world_.PairsWithin(0.1)) {
    EXPECT_FALSE(pair.geometry_a == sole && pair.geometry_b == ground_);
  }
  CAIRN_EXPECT_THROWS_WITH(world_.ExcludeBodyPair("pelvis", "l_thig"), std::invalid_argument, "unknown body 'l_thig'",
                           "'l_thigh'");
  CAIRN_EXPECT_THROWS_WITH(world_.GetGeometryIndex("grund"), std::invalid_argument, "unknown geometry 'grund'",
                           "'ground'");
  CAIRN_EXPECT_THROWS_WITH(world_.AddSphere("ground", 1.0, Eigen::Vector3d::Zero()), std::invalid_argument, "'ground'",
                           "unique");
}

TEST_F(CollisionWorldTest, PointsAndSpheresUseClosedForms) {
  Eigen::Matrix3Xd points(3, 3);
  points << 0.5, 0.30, 2.0,  //
      0.0, 0.0, 0.0,         //
      1.2, 0.86, 1.0;
  const int cloud = world_.AddPoints("cloud", points, 0.01);
  const int pelvis = world_.GetGeometryIndex("pelvis_box");
  // Pelvis box: centre (0, 0, 0.87), half extents (0.09, 0.14, 0.07); the point (0.30, 0, 0.86) is 0.21 in front.
  EXPECT_NEAR(world_.ComputeDistance(pelvis, cloud).distance, 0.30 - 0.09 - 0.01, 1e-12);
  const int ball = world_.AddSphere("ball", 0.1, Eigen::Vector3d(0, 0, 1.87));
  const int head = world_.GetGeometryIndex("head_sphere");
  // Head centre at 0.87 + 0.1 + 0.34 + 0.04 + 0.06 = 1.41, radius 0.1.
  EXPECT_NEAR(world_.ComputeDistance(head, ball).distance, 1.87 - 1.41 - 0.2, 1e-12);
}

// d(distance)/dq from witness points and Jacobians against central differences, for every close pair at random
// configurations: self pairs, robot-box (FCL for box-box), robot-sphere and robot-points.
TEST_F(CollisionWorldTest, DistanceGradientsMatchFiniteDifferences) {
  Eigen::Matrix3Xd points(3, 4);
  points << 0.3, -0.3, 0.2, 0.0,  //
      0.2, -0.2, 0.3, 0.0,        //
      0.5, 0.9, 1.2, 1.6;
  world_.AddPoints("cloud", points, 0.02);
  world_.AddSphere("ball", 0.15, Eigen::Vector3d(0.35, 0.1, 1.0));
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> bump(0.0, 0.08);
  Eigen::MatrixXd heights(12, 12);
  for (Eigen::Index k = 0; k < heights.size(); ++k) heights.data()[k] = bump(rng);
  world_.AddHeightField("terrain", heights, 0.05, Eigen::Vector2d(-0.3, -0.3), -0.2);
  int checked = 0;
  for (int trial = 0; trial < 4; ++trial) {
    Eigen::VectorXd q = RandomConfiguration(model_, rng, 0.3);
    const Joint& root = model_.joint(model_.GetJointIndex("root_joint"));
    q.segment<7>(root.idx_q) << 0.0, 0.0, 0.86, 1.0, 0.0, 0.0, 0.0;
    Update(q);
    const std::vector<CollisionPair> pairs = world_.PairsWithin(0.3);
    Eigen::VectorXd gradient(model_.nv());
    const double h = 1e-6;
    for (const CollisionPair& pair : pairs) {
      world_.DistanceGradient(model_, data_, pair, gradient);
      for (int k = 0; k < model_.nv(); ++k) {
        const Eigen::VectorXd e = Eigen::VectorXd::Unit(model_.nv(), k);
        Update(Integrate(model_, q, e, h));
        const double plus = world_.ComputeDistance(pair.geometry_a, pair.geometry_b).distance;
        Update(Integrate(model_, q, e, -h));
        const double minus = world_.ComputeDistance(pair.geometry_a, pair.geometry_b).distance;
        EXPECT_NEAR(gradient[k], (plus - minus) / (2 * h), 1e-6)
            << world_.geometry_name(pair.geometry_a) << " - " << world_.geometry_name(pair.geometry_b) << " dof " << k;
      }
      Update(q);
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);
}

TEST_F(CollisionWorldTest, HeightFieldColumnsUnderTheFeet) {
  world_.ExcludeGeometryPair("l_sole_box", "ground");
  world_.ExcludeGeometryPair("r_sole_box", "ground");
  // Flat terrain at z = 0, 2 cm cells, under both feet; one cell under the left sole 5 cm high.
  Eigen::MatrixXd heights = Eigen::MatrixXd::Zero(30, 30);
  const Eigen::Vector2d origin(-0.3, -0.3);
  const int terrain = world_.AddHeightField("terrain", heights, 0.02, origin, -0.1);
  const int left = world_.GetGeometryIndex("l_sole_box");
  EXPECT_NEAR(world_.ComputeDistance(left, terrain).distance, 0.01, 1e-12);
  // The left sole centre is at (0.03, 0.08): cell (16, 19).
  heights(16, 19) = 0.05;
  CollisionWorld bumpy(model_);
  bumpy.UpdatePoses(model_, data_);
  const int bumpy_terrain = bumpy.AddHeightField("terrain", heights, 0.02, origin, -0.1);
  const ShapeDistance d = bumpy.ComputeDistance(bumpy.GetGeometryIndex("l_sole_box"), bumpy_terrain);
  EXPECT_NEAR(d.distance, -0.04, 1e-12);
  EXPECT_NEAR(bumpy.ComputeDistance(bumpy.GetGeometryIndex("r_sole_box"), bumpy_terrain).distance, 0.01, 1e-12);
  const std::vector<CollisionPair> hits = bumpy.PairsWithin(0.0);
  // The bump reaches into the sole plate and the ankle block of the left foot, nothing else.
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(bumpy.geometry_name(hits[0].geometry_a), "l_sole_box");
  EXPECT_EQ(bumpy.geometry_name(hits[1].geometry_a), "l_ankle_box");
  EXPECT_NEAR(hits[1].result.distance, 0.03 - 0.05, 1e-12);
  heights(0, 0) = -1.0;
  CAIRN_EXPECT_THROWS_WITH(bumpy.AddHeightField("bad", heights, 0.02, origin, -0.1), std::invalid_argument, "'bad'",
                           "below the bottom", "NaN");
}

TEST(CollisionWorldMeshTest, LoadsStlMeshesOfDrcHubo) {
  const Model model = test::LoadRobot(test::DrcHuboUrdf(), false);
  Data data(model);
  CollisionWorld world(model);
  ASSERT_GT(world.num_geometries(), 40);
  ForwardKinematics(model, data, Eigen::VectorXd::Zero(model.nq()));
  world.UpdatePoses(model, data);
  const int far = world.AddSphere("far_ball", 0.1, Eigen::Vector3d(5.0, 0.0, 0.0));
  const int torso = world.GetGeometryIndex("Body_Torso_collision_0");
  const double d = world.ComputeDistance(torso, far).distance;
  // The torso mesh lies within a metre of the origin.
  EXPECT_GT(d, 3.5);
  EXPECT_LT(d, 5.0);
  CAIRN_EXPECT_THROWS_WITH(world.AddPoints("empty", Eigen::Matrix3Xd(3, 0)), std::invalid_argument, "'empty'",
                           "at least one");
}

TEST_F(CollisionWorldTest, NanMarginsAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CAIRN_EXPECT_THROWS_WITH(world_.PairsWithin(nan), std::invalid_argument, "PairsWithin", "margin is NaN");
  CAIRN_EXPECT_THROWS_WITH(world_.ClosestPair(nan), std::invalid_argument, "ClosestPair", "max_distance is NaN");
}

// A one-link model whose collision shape is the mesh file `path` (not checked by the builder).
Model MeshModel(const std::string& path) {
  ModelBuilder builder("mesh");
  Body body;
  body.name = "b";
  Joint joint;
  joint.name = "j";
  const int index = builder.AddBody(0, body, joint);
  Geometry mesh;
  mesh.name = "m";
  mesh.type = GeometryType::kMesh;
  mesh.mesh_path = path;
  builder.AddCollisionGeometry(index, mesh);
  return builder.Build();
}

TEST(CollisionWorldMeshTest, CorruptHugeAndMisplacedMeshesAreRefused) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cairn_collision_world_test";
  std::filesystem::create_directories(dir);
  const std::string ascii = (dir / "nan.stl").string();
  std::ofstream(ascii) << "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex nan 1 0\n"
                          "endloop\nendfacet\nendsolid t\n";
  CAIRN_EXPECT_THROWS_WITH(CollisionWorld world(MeshModel(ascii)), std::invalid_argument, "nan.stl", "vertex 2",
                           "three numbers");
  // A binary STL with one triangle whose first vertex is infinite.
  std::string binary(84 + 50, '\0');
  binary[80] = 1;
  const float inf = std::numeric_limits<float>::infinity();
  std::memcpy(&binary[84 + 12], &inf, sizeof(inf));
  const std::string binary_path = (dir / "inf.stl").string();
  std::ofstream(binary_path, std::ios::binary) << binary;
  CAIRN_EXPECT_THROWS_WITH(CollisionWorld world(MeshModel(binary_path)), std::invalid_argument, "inf.stl",
                           "vertex 0 is not finite");
  const std::string huge = (dir / "huge.stl").string();
  { std::ofstream(huge) << "solid"; }
  std::filesystem::resize_file(huge, kMaxMeshBytes + 1);  // Sparse: costs no disk.
  CAIRN_EXPECT_THROWS_WITH(CollisionWorld world(MeshModel(huge)), std::invalid_argument, "huge.stl",
                           "larger than " + std::to_string(kMaxMeshBytes) + " bytes", "kMaxMeshBytes");
  CAIRN_EXPECT_THROWS_WITH(CollisionWorld world(MeshModel(dir.string())), std::invalid_argument,
                           "is a directory, expected an STL file");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cairn::multibody
