#include <cairn/multibody/model_builder.h>

#include <limits>
#include <string>

#include <cairn/multibody/data.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_models.h"

namespace cairn::multibody {
namespace {

Body MakeBody(const std::string& name, double mass = 1.0) {
  Body body;
  body.name = name;
  body.inertia =
      SpatialInertia::FromMassComInertia(mass, Eigen::Vector3d(0, 0, -0.5), 0.01 * Eigen::Matrix3d::Identity());
  return body;
}

Joint Revolute(const std::string& name, const Eigen::Vector3d& axis = Eigen::Vector3d::UnitY()) {
  Joint joint;
  joint.name = name;
  joint.type = JointType::kRevolute;
  joint.axis = axis;
  joint.lower_limit = -1.0;
  joint.upper_limit = 1.0;
  return joint;
}

TEST(ModelBuilderTest, BuildsADoublePendulumWithFramesAndLimits) {
  ModelBuilder builder("pendulum");
  const int upper = builder.AddBody(0, MakeBody("upper"), Revolute("shoulder"));
  Joint elbow = Revolute("elbow", Eigen::Vector3d(0, 2, 0));
  elbow.X_PJ = Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, -1));
  const int lower = builder.AddBody(upper, MakeBody("lower", 2.0), elbow);
  builder.AddFrame("tip", lower, Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, -1)));
  const Model model = builder.Build();
  EXPECT_EQ(model.nq(), 2);
  EXPECT_EQ(model.nv(), 2);
  EXPECT_EQ(model.num_bodies(), 3);
  EXPECT_EQ(model.num_frames(), 4);
  EXPECT_EQ(model.GetFrameIndex("tip"), 3);
  EXPECT_EQ(model.frame(model.GetFrameIndex("lower")).body, lower);
  EXPECT_DOUBLE_EQ(model.total_mass(), 3.0);
  EXPECT_TRUE(model.joint(lower).axis.isApprox(Eigen::Vector3d::UnitY()));  // normalized
  EXPECT_EQ(model.joint(lower).idx_q, 1);
  EXPECT_EQ(model.velocity_joint(1), lower);
  EXPECT_TRUE(model.IsAncestorOrSelf(upper, lower));
  EXPECT_FALSE(model.IsAncestorOrSelf(lower, upper));
  EXPECT_DOUBLE_EQ(model.lower_position_limits()[1], -1.0);
  EXPECT_TRUE(std::isinf(model.velocity_limits()[0]));
  EXPECT_EQ(model.joint_names(), (std::vector<std::string>{"shoulder", "elbow"}));
  const Model no_gravity = model.WithGravity(Eigen::Vector3d::Zero());
  EXPECT_TRUE(no_gravity.gravity().isZero());
  EXPECT_DOUBLE_EQ(model.gravity().z(), -9.81);
}

TEST(ModelBuilderTest, UnknownNamesListTheClosestOnes) {
  ModelBuilder builder("arm");
  builder.AddBody(0, MakeBody("l_foot"), Revolute("l_ankle"));
  builder.AddBody(1, MakeBody("r_foot"), Revolute("r_ankle"));
  const Model model = builder.Build();
  CAIRN_EXPECT_THROWS_WITH(model.GetBodyIndex("l_fot"), std::invalid_argument, "unknown body 'l_fot'", "'l_foot'",
                           "arm");
  CAIRN_EXPECT_THROWS_WITH(model.GetJointIndex("r_ankel"), std::invalid_argument, "unknown joint 'r_ankel'",
                           "'r_ankle'");
  CAIRN_EXPECT_THROWS_WITH(model.GetFrameIndex("wrld"), std::invalid_argument, "'world'");
}

TEST(ModelBuilderTest, RejectsBadBodiesAndJoints) {
  ModelBuilder builder("bad");
  builder.AddBody(0, MakeBody("a"), Revolute("ja"));
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, MakeBody("a"), Revolute("jb")), std::invalid_argument, "body name 'a'",
                           "unique");
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, MakeBody("b"), Revolute("ja")), std::invalid_argument, "joint name 'ja'",
                           "unique");
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(7, MakeBody("b"), Revolute("jb")), std::invalid_argument, "body index 7",
                           "out of range");
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, MakeBody("b"), Revolute("jb", Eigen::Vector3d::Zero())),
                           std::invalid_argument, "joint 'jb'", "axis (0 0 0)", "zero");
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, MakeBody("b", -2.0), Revolute("jb")), std::invalid_argument, "body 'b'",
                           "mass -2");
  Body flat = MakeBody("b");
  flat.inertia =
      SpatialInertia::FromMassComInertia(1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal());
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, flat, Revolute("jb")), std::invalid_argument, "body 'b'",
                           "not positive definite");
  Joint crossed = Revolute("jb");
  crossed.lower_limit = 2.0;
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, MakeBody("b"), crossed), std::invalid_argument, "joint 'jb'",
                           "lower limit 2", "swap");
  Geometry sphere;
  sphere.name = "ball";
  sphere.type = GeometryType::kSphere;
  sphere.radius = -1.0;
  CAIRN_EXPECT_THROWS_WITH(builder.AddCollisionGeometry(1, sphere), std::invalid_argument, "body 'a'", "sphere 'ball'",
                           "radius");
  builder.AddFrame("a", 1, Pose());
  CAIRN_EXPECT_THROWS_WITH(builder.Build(), std::invalid_argument, "frame name 'a'", "body name");
}

TEST(ModelBuilderTest, RefusesInertiasViolatingTheTriangleInequality) {
  ModelBuilder builder("bad");
  Body rod = MakeBody("rod");
  // Positive definite, but no mass distribution has Izz > Ixx + Iyy.
  rod.inertia =
      SpatialInertia::FromMassComInertia(1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.1, 0.1, 0.5).asDiagonal());
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, rod, Revolute("j")), std::invalid_argument, "body 'rod'",
                           "(0.1 0.1 0.5)", "triangle inequality", "0.1 + 0.1 < 0.5");
  // A thin plate sits on the boundary (Izz = Ixx + Iyy) and is accepted, as is rounding within the tolerance.
  Body plate = MakeBody("plate");
  plate.inertia = SpatialInertia::FromMassComInertia(1.0, Eigen::Vector3d::Zero(),
                                                     Eigen::Vector3d(0.05, 0.05, 0.10005).asDiagonal());
  EXPECT_NO_THROW(builder.AddBody(0, plate, Revolute("j")));
}

TEST(ModelBuilderTest, RefusesNegativeAndNanLimits) {
  ModelBuilder builder("bad");
  Joint effort = Revolute("j");
  effort.effort_limit = -5.0;
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, MakeBody("b"), effort), std::invalid_argument, "joint 'j'",
                           "effort limit -5", ">= 0");
  Joint velocity = Revolute("j");
  velocity.velocity_limit = -0.5;
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, MakeBody("b"), velocity), std::invalid_argument, "joint 'j'",
                           "velocity limit -0.5");
  Joint nan = Revolute("j");
  nan.upper_limit = std::numeric_limits<double>::quiet_NaN();
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(0, MakeBody("b"), nan), std::invalid_argument, "joint 'j'", "[-1, nan]",
                           "must be numbers");
  Geometry mesh;
  mesh.name = "m";
  mesh.type = GeometryType::kMesh;
  mesh.mesh_path = "/tmp/m.stl";
  mesh.scale = Eigen::Vector3d(1.0, std::numeric_limits<double>::infinity(), 1.0);
  CAIRN_EXPECT_THROWS_WITH(builder.AddVisualGeometry(0, mesh), std::invalid_argument, "mesh 'm'", "scale (1 inf 1)");
}

TEST(ModelBuilderTest, LongChainsBuildAndTheBodyCountIsBounded) {
  ModelBuilder builder("chain");
  // The names are checked through sets, so a chain as long as the limit builds in O(n log n).
  Body body;
  Joint joint;
  joint.type = JointType::kFixed;
  for (int i = 1; i <= kMaxModelBodies; ++i) {
    body.name = "l" + std::to_string(i);
    joint.name = "j" + std::to_string(i);
    ASSERT_EQ(builder.AddBody(i - 1, body, joint), i);
  }
  body.name = "one_too_many";
  joint.name = "one_too_many";
  CAIRN_EXPECT_THROWS_WITH(builder.AddBody(kMaxModelBodies, body, joint), std::invalid_argument, "'one_too_many'",
                           "100000 bodies", "kMaxModelBodies");
  const Model model = builder.Build();
  EXPECT_EQ(model.num_bodies(), kMaxModelBodies + 1);
  EXPECT_EQ(model.parent(kMaxModelBodies), kMaxModelBodies - 1);
}

TEST(DataTest, RefusesModelsWithMoreVelocitiesThanTheLimit) {
  ModelBuilder builder("wide");
  Body body;
  Joint joint = Revolute("j");
  for (int i = 1; i <= kMaxDataVelocities + 1; ++i) {
    body.name = "l" + std::to_string(i);
    joint.name = "j" + std::to_string(i);
    builder.AddBody(0, body, joint);
  }
  const Model model = builder.Build();
  ASSERT_EQ(model.nv(), kMaxDataVelocities + 1);
  CAIRN_EXPECT_THROWS_WITH(Data data(model), std::invalid_argument, "model 'wide'", "10001 velocity coordinates",
                           "at most 10000", "kMaxDataVelocities");
}

TEST(SpatialInertiaTest, TransformAndAddAgreeWithTheMatrixForm) {
  const Eigen::Matrix3d I_c = (Eigen::Matrix3d() << 0.3, 0.01, 0.02, 0.01, 0.2, 0.03, 0.02, 0.03, 0.1).finished();
  const SpatialInertia inertia = SpatialInertia::FromMassComInertia(2.5, Eigen::Vector3d(0.1, -0.2, 0.3), I_c);
  const Pose X(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
               Eigen::Vector3d(0.4, 0.5, -0.6));
  // Matrix form of the force transform and of the motion transform's inverse.
  Matrix6d force_transform, motion_inverse;
  for (int k = 0; k < 6; ++k) {
    force_transform.col(k) = X.ActForce(Vector6d::Unit(k));
    motion_inverse.col(k) = X.InverseActMotion(Vector6d::Unit(k));
  }
  const Matrix6d expected = force_transform * inertia.Matrix() * motion_inverse;
  EXPECT_TRUE(inertia.Transformed(X).Matrix().isApprox(expected, 1e-12));
  SpatialInertia sum = inertia;
  sum += inertia.Transformed(X);
  EXPECT_TRUE(sum.Matrix().isApprox(inertia.Matrix() + expected, 1e-12));
  EXPECT_TRUE(inertia.InertiaAboutCom().isApprox(I_c, 1e-12));
  EXPECT_TRUE(inertia.com().isApprox(Eigen::Vector3d(0.1, -0.2, 0.3)));
}

}  // namespace
}  // namespace cairn::multibody
