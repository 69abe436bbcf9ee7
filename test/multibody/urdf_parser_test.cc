#include <cairn/multibody/urdf_parser.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_models.h"

namespace cairn::multibody {
namespace {

using ::testing::HasSubstr;

// A two-link arm; `link2_inertial`, `axis` and `extra` let each test break one thing.
std::string Arm(
    const std::string& link2_inertial =
        R"(<inertial><mass value="1.0"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>)",
    const std::string& axis = "0 0 1", const std::string& extra = "") {
  return R"(<?xml version="1.0"?>
<robot name="arm">
  <link name="base"><inertial><mass value="2.0"/><inertia ixx="0.2" iyy="0.2" izz="0.2" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="link1"><inertial><mass value="1.0"/><origin xyz="0 0 0.25"/><inertia ixx="0.1" iyy="0.1" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision name="capsule_upper"><origin xyz="0 0 0.25"/><geometry><cylinder radius="0.05" length="0.4"/></geometry></collision>
    <collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision>
  </link>
  <link name="link2">)" +
         link2_inertial + R"(<collision><geometry><sphere radius="0.07"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="link1"/><origin xyz="0 0 0.1"/>
    <axis xyz="0 1 0"/><limit lower="-1.5" upper="2.0" effort="50" velocity="3"/></joint>
  <joint name="elbow" type="continuous"><parent link="link1"/><child link="link2"/><origin xyz="0 0 0.5"/>
    <axis xyz=")" +
         axis + R"("/></joint>)" + extra + R"(
</robot>)";
}

Model ParseArm(const std::string& xml, bool floating = false) {
  UrdfOptions options;
  options.floating_base = floating;
  return ParseUrdfString(xml, "/tmp", options, "arm.urdf");
}

TEST(UrdfParserTest, ReadsBodiesJointsLimitsInertiasAndGeometry) {
  const Model model = ParseArm(Arm());
  EXPECT_EQ(model.name(), "arm");
  EXPECT_EQ(model.num_bodies(), 4);  // world, base, link1, link2
  EXPECT_EQ(model.nq(), 2);
  EXPECT_EQ(model.nv(), 2);
  EXPECT_DOUBLE_EQ(model.total_mass(), 4.0);
  const Joint& shoulder = model.joint(model.GetJointIndex("shoulder"));
  EXPECT_EQ(shoulder.type, JointType::kRevolute);
  EXPECT_DOUBLE_EQ(shoulder.lower_limit, -1.5);
  EXPECT_DOUBLE_EQ(shoulder.upper_limit, 2.0);
  EXPECT_DOUBLE_EQ(shoulder.velocity_limit, 3.0);
  EXPECT_DOUBLE_EQ(shoulder.effort_limit, 50.0);
  EXPECT_TRUE(shoulder.axis.isApprox(Eigen::Vector3d::UnitY()));
  const Joint& elbow = model.joint(model.GetJointIndex("elbow"));
  EXPECT_TRUE(elbow.continuous);
  EXPECT_TRUE(std::isinf(elbow.lower_limit));
  const Body& link1 = model.body(model.GetBodyIndex("link1"));
  EXPECT_TRUE(link1.inertia.com().isApprox(Eigen::Vector3d(0, 0, 0.25)));
  ASSERT_EQ(link1.collisions.size(), 2u);
  EXPECT_EQ(link1.collisions[0].type, GeometryType::kCapsule);
  EXPECT_DOUBLE_EQ(link1.collisions[0].radius, 0.05);
  EXPECT_DOUBLE_EQ(link1.collisions[0].length, 0.4);
  EXPECT_EQ(link1.collisions[1].type, GeometryType::kBox);
  EXPECT_EQ(link1.collisions[1].name, "link1_collision_1");
  EXPECT_TRUE(link1.collisions[1].size.isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  EXPECT_EQ(model.body(model.GetBodyIndex("link2")).collisions[0].type, GeometryType::kSphere);
  // Parents precede children.
  for (int i = 1; i < model.num_bodies(); ++i) EXPECT_LT(model.parent(i), i);
}

TEST(UrdfParserTest, FloatingBaseAddsAQuaternionJoint) {
  const Model model = ParseArm(Arm(), true);
  EXPECT_EQ(model.nq(), 9);
  EXPECT_EQ(model.nv(), 8);
  EXPECT_EQ(model.joint(model.GetJointIndex("root_joint")).type, JointType::kFloating);
}

TEST(UrdfParserTest, LoadsAtlasAndDrcHubo) {
  const Model atlas = test::LoadRobot(test::AtlasUrdf(), true);
  EXPECT_EQ(atlas.num_bodies(), 35);  // 34 links + world
  EXPECT_EQ(atlas.nv(), 27 + 6);
  EXPECT_EQ(atlas.nq(), 27 + 7);
  EXPECT_NEAR(atlas.total_mass(), 146.554, 1e-9);
  const Model hubo = test::LoadRobot(test::DrcHuboUrdf(), false);
  EXPECT_EQ(hubo.nv(), 51);
  EXPECT_NEAR(hubo.total_mass(), 43.98482846871159, 1e-9);
  // Meshes resolved through the package map.
  const Body& torso = hubo.body(hubo.GetBodyIndex("Body_Torso"));
  ASSERT_FALSE(torso.collisions.empty());
  EXPECT_EQ(torso.collisions[0].type, GeometryType::kMesh);
  EXPECT_TRUE(std::filesystem::exists(torso.collisions[0].mesh_path));
}

TEST(UrdfParserTest, PackageFoundFromEnclosingRosPackage) {
  // drchubo.urdf lives in a folder called drchubo with a package.xml.
  const Model hubo = ParseUrdfFile(test::DrcHuboUrdf());
  EXPECT_EQ(hubo.nv(), 51);
}

TEST(UrdfParserTest, AtlasV3NamesTheJointWithTheMissingLink) {
  CAIRN_EXPECT_THROWS_WITH(ParseUrdfFile(test::AtlasBrokenUrdf()), std::runtime_error, "atlas_v3.urdf", "head",
                           "neck_ry");
}

TEST(UrdfParserTest, MissingFileIsReported) {
  CAIRN_EXPECT_THROWS_WITH(ParseUrdfFile("/nonexistent/robot.urdf"), std::runtime_error, "/nonexistent/robot.urdf",
                           "cannot open");
}

TEST(UrdfParserTest, MalformedXmlIsReported) {
  CAIRN_EXPECT_THROWS_WITH(ParseArm("<robot name=\"arm\">\n<link name=\"a\"></robot>"), std::runtime_error, "arm.urdf",
                           "malformed XML at line 2");
  CAIRN_EXPECT_THROWS_WITH(ParseArm("<robt name=\"arm\"/>"), std::runtime_error, "arm.urdf", "<robot");
}

TEST(UrdfParserTest, NegativeMassIsReported) {
  CAIRN_EXPECT_THROWS_WITH(
      ParseArm(
          Arm(R"(<inertial><mass value="-1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>)")),
      std::runtime_error, "arm.urdf", "link 'link2'", "-1", "mass");
}

TEST(UrdfParserTest, NanMassIsReported) {
  CAIRN_EXPECT_THROWS_WITH(
      ParseArm(
          Arm(R"(<inertial><mass value="nan"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>)")),
      std::runtime_error, "arm.urdf", "link 'link2'", "nan", "mass");
}

TEST(UrdfParserTest, IndefiniteInertiaIsReported) {
  CAIRN_EXPECT_THROWS_WITH(
      ParseArm(
          Arm(R"(<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="-1" ixy="0" ixz="0" iyz="0"/></inertial>)")),
      std::runtime_error, "arm.urdf", "link2", "not positive definite");
}

TEST(UrdfParserTest, ZeroAxisIsReported) {
  CAIRN_EXPECT_THROWS_WITH(
      ParseArm(
          Arm(R"(<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>)",
              "0 0 0")),
      std::runtime_error, "arm.urdf", "joint 'elbow'", "zero");
}

TEST(UrdfParserTest, KinematicLoopIsReported) {
  const std::string loop = R"(<joint name="loop" type="fixed"><parent link="link2"/><child link="base"/></joint>)";
  CAIRN_EXPECT_THROWS_WITH(
      ParseArm(
          Arm(R"(<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>)",
              "0 0 1", loop)),
      std::runtime_error, "arm.urdf", "not a valid tree");
}

TEST(UrdfParserTest, MimicJointIsRejected) {
  const std::string xml = R"(<robot name="m">
  <link name="a"/><link name="b"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="c"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j1" type="continuous"><parent link="a"/><child link="b"/></joint>
  <joint name="j2" type="continuous"><parent link="b"/><child link="c"/><mimic joint="j1"/></joint>
</robot>)";
  CAIRN_EXPECT_THROWS_WITH(ParseArm(xml), std::runtime_error, "arm.urdf", "j2", "mimic", "j1");
}

TEST(UrdfParserTest, MissingMeshFileIsReported) {
  const std::string xml =
      R"(<robot name="m"><link name="a"><collision><geometry><mesh filename="no_such_mesh.stl"/></geometry></collision></link></robot>)";
  CAIRN_EXPECT_THROWS_WITH(ParseArm(xml), std::runtime_error, "arm.urdf", "link 'a'", "no_such_mesh.stl",
                           "does not exist");
  UrdfOptions options;
  options.check_mesh_files = false;
  const Model model = ParseUrdfString(xml, "/tmp", options);
  EXPECT_EQ(model.body(1).collisions[0].mesh_path, "/tmp/no_such_mesh.stl");
}

TEST(UrdfParserTest, UnknownPackageIsReported) {
  const std::string xml =
      R"(<robot name="m"><link name="a"><visual><geometry><mesh filename="package://nowhere/m.stl"/></geometry></visual></link></robot>)";
  CAIRN_EXPECT_THROWS_WITH(ParseArm(xml), std::runtime_error, "arm.urdf", "package 'nowhere'", "--package");
}

TEST(UrdfParserTest, WorldRootLinkIsTheWorld) {
  const std::string xml = R"(<robot name="w"><link name="world"/>
  <link name="b"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j" type="prismatic"><parent link="world"/><child link="b"/><axis xyz="1 0 0"/><limit lower="0" upper="1" effort="1" velocity="1"/></joint></robot>)";
  const Model model = ParseArm(xml);
  EXPECT_EQ(model.num_bodies(), 2);
  EXPECT_EQ(model.parent(1), 0);
  CAIRN_EXPECT_THROWS_WITH(ParseArm(xml, true), std::runtime_error, "world", "floating_base");
}

}  // namespace
}  // namespace cairn::multibody
