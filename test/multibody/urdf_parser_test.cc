#include <cairn/multibody/urdf_parser.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

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
  CAIRN_EXPECT_THROWS_WITH(ParseArm(" \n\t"), std::runtime_error, "arm.urdf: the text is empty");
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

// A chain of `links` links joined by revolute joints, as a generator of test robots writes it.
std::string Chain(int links) {
  std::string xml = "<robot name=\"chain\">\n";
  for (int i = 0; i < links; ++i) {
    xml += "<link name=\"l" + std::to_string(i) +
           "\"><inertial><mass value=\"1\"/><inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" ixy=\"0\" ixz=\"0\" "
           "iyz=\"0\"/></inertial></link>\n";
  }
  for (int i = 1; i < links; ++i) {
    xml += "<joint name=\"j" + std::to_string(i) + "\" type=\"revolute\"><parent link=\"l" + std::to_string(i - 1) +
           "\"/><child link=\"l" + std::to_string(i) +
           "\"/><origin xyz=\"0 0 0.1\"/><axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" "
           "velocity=\"1\"/></joint>\n";
  }
  return xml + "</robot>\n";
}

TEST(UrdfParserTest, LoadsAFiveThousandLinkChain) {
  // Building the tree recursed once per link before and overflowed the stack on this chain.
  const Model model = ParseArm(Chain(5000));
  EXPECT_EQ(model.num_bodies(), 5001);
  EXPECT_EQ(model.nv(), 4999);
  for (int i = 2; i < model.num_bodies(); ++i) ASSERT_EQ(model.parent(i), i - 1);
  EXPECT_EQ(model.body(5000).name, "l4999");
  EXPECT_DOUBLE_EQ(model.total_mass(), 5000.0);
}

TEST(UrdfParserTest, BranchesAreAddedDepthFirstInJointNameOrder) {
  const std::string xml = R"(<robot name="y"><link name="root"/><link name="a"/><link name="a2"/><link name="b"/>
  <joint name="jb" type="fixed"><parent link="root"/><child link="b"/></joint>
  <joint name="ja" type="fixed"><parent link="root"/><child link="a"/></joint>
  <joint name="ja2" type="fixed"><parent link="a"/><child link="a2"/></joint></robot>)";
  const Model model = ParseArm(xml);
  EXPECT_EQ(model.body_names(), (std::vector<std::string>{"world", "root", "a", "a2", "b"}));
}

// `depth` elements nested inside a link (urdfdom ignores elements it does not know).
std::string Nested(int depth) {
  std::string xml = "<robot name=\"n\"><link name=\"a\">";
  for (int i = 0; i < depth; ++i) xml += "<x>";
  for (int i = 0; i < depth; ++i) xml += "</x>";
  return xml + "</link></robot>";
}

TEST(UrdfParserTest, RefusesNestingDeeperThanTheLimitBeforeParsing) {
  // 100,000 levels overflowed the stack inside TinyXML before.
  CAIRN_EXPECT_THROWS_WITH(ParseArm(Nested(100000)), std::runtime_error, "arm.urdf", "more than 100 levels",
                           "kMaxUrdfNestingDepth", "line 1");
  // robot and link are two levels.
  EXPECT_NO_THROW(ParseArm(Nested(kMaxUrdfNestingDepth - 2)));
  CAIRN_EXPECT_THROWS_WITH(ParseArm(Nested(kMaxUrdfNestingDepth - 1)), std::runtime_error, "more than 100 levels");
  // Markup that TinyXML does not nest does not count: comments, CDATA, declarations, self-closing elements.
  std::string flat = "<?xml version=\"1.0\"?><robot name=\"n\"><link name=\"a\">";
  for (int i = 0; i < 1000; ++i) flat += "<!-- <x> --><![CDATA[<x>]]><y a=\"<x>\"/>";
  EXPECT_NO_THROW(ParseArm(flat + "</link></robot>"));
  // A declaration ends at its first '>' in TinyXML, so elements after it count even before a later "?>".
  std::string after_declaration = "<?xml version=\"1.0\" ><robot name=\"n\">";
  for (int i = 0; i < 200; ++i) after_declaration += "<x>";
  CAIRN_EXPECT_THROWS_WITH(ParseArm(after_declaration + "?>"), std::runtime_error, "more than 100 levels");
}

TEST(UrdfParserTest, RefusesTextAndFilesLargerThanTheLimit) {
  CAIRN_EXPECT_THROWS_WITH(ParseArm(std::string(kMaxUrdfBytes + 1, ' ')), std::runtime_error, "arm.urdf",
                           std::to_string(kMaxUrdfBytes + 1) + " bytes", "kMaxUrdfBytes");
  const std::filesystem::path big = std::filesystem::temp_directory_path() / "cairn_urdf_parser_test_big.urdf";
  { std::ofstream(big.string()) << "<robot name=\"big\"/>"; }
  std::filesystem::resize_file(big, kMaxUrdfBytes + 1);  // Sparse: costs no disk.
  CAIRN_EXPECT_THROWS_WITH(ParseUrdfFile(big.string()), std::runtime_error, big.string(),
                           "larger than " + std::to_string(kMaxUrdfBytes) + " bytes", "kMaxUrdfBytes");
  std::filesystem::remove(big);
}

TEST(UrdfParserTest, ADirectoryIsNamedAsNotAFile) {
  const std::string folder = std::filesystem::temp_directory_path().string();
  CAIRN_EXPECT_THROWS_WITH(ParseUrdfFile(folder), std::runtime_error, folder + ": is a directory",
                           "expected a URDF file");
}

// Replaces the first occurrence of `from` in the arm with `to`.
std::string ArmWith(const std::string& from, const std::string& to) {
  std::string xml = Arm();
  const std::size_t at = xml.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? xml : xml.replace(at, from.size(), to);
}

TEST(UrdfParserTest, EveryNumericAttributeIsReadStrictly) {
  // Each of these was read as 0, dropped with its element, or accepted before.
  const std::vector<std::pair<std::pair<std::string, std::string>, std::vector<std::string>>> cases = {
      {{"<box size=\"0.1 0.2 0.3\"/>", "<box size=\"nan 0.2 0.3\"/>"},
       {"link 'link1' (line 6)", "<box size=\"nan 0.2 0.3\">", "\"nan\" is not a finite number", "side lengths"}},
      {{"<box size=\"0.1 0.2 0.3\"/>", "<box size=\"abc 0.2 0.3\"/>"}, {"link 'link1'", "\"abc\" is not a finite"}},
      {{"<box size=\"0.1 0.2 0.3\"/>", "<box size=\"0.1 0.2\"/>"}, {"link 'link1'", "holds 2 numbers where 3"}},
      {{"<box size=\"0.1 0.2 0.3\"/>", "<box size=\"0.1 0.2 0.3 0.4\"/>"}, {"link 'link1'", "more than 3 numbers"}},
      {{"<box size=\"0.1 0.2 0.3\"/>", "<box size=\"-0.1 0.2 0.3\"/>"}, {"link 'link1'", "every side must be > 0"}},
      {{"<sphere radius=\"0.07\"/>", "<sphere radius=\"NaN\"/>"},
       {"link 'link2'", "<sphere radius=\"NaN\">", "not a finite number"}},
      {{"<sphere radius=\"0.07\"/>", "<sphere radius=\"0\"/>"}, {"link 'link2'", "<sphere radius=\"0\">", "> 0"}},
      {{"<cylinder radius=\"0.05\" length=\"0.4\"/>", "<cylinder radius=\"0.05\" length=\"inf\"/>"},
       {"link 'link1'", "<cylinder length=\"inf\">"}},
      {{"<cylinder radius=\"0.05\" length=\"0.4\"/>", "<cylinder radius=\"0.05\" length=\"-0.4\"/>"},
       {"link 'link1'", "<cylinder length=\"-0.4\">", ">= 0"}},
      {{"<origin xyz=\"0 0 0.25\"/>", "<origin xyz=\"0 0 1e400\"/>"}, {"link 'link1'", "\"1e400\" is not a finite"}},
      {{"<origin xyz=\"0 0 0.1\"/>", "<origin xyz=\"0 0 0.1\" rpy=\"0 0 x\"/>"},
       {"joint 'shoulder'", "<origin rpy=\"0 0 x\">", "roll pitch yaw"}},
      {{"ixx=\"0.2\"", "ixx=\"0.2kg\""}, {"link 'base'", "<inertia ixx=\"0.2kg\">", "\"0.2kg\""}},
      {{"<mass value=\"2.0\"/>", "<mass value=\"\"/>"}, {"link 'base'", "holds 0 numbers where 1 is expected"}},
      {{"<axis xyz=\"0 1 0\"/>", "<axis xyz=\"0 1 nan\"/>"}, {"joint 'shoulder'", "<axis xyz=\"0 1 nan\">"}},
      {{"effort=\"50\"", "effort=\"-50\""}, {"joint 'shoulder'", "<limit effort=\"-50\">", "must be >= 0"}},
      {{"velocity=\"3\"", "velocity=\"-3\""}, {"joint 'shoulder'", "<limit velocity=\"-3\">", "must be >= 0"}},
      {{"velocity=\"3\"", "velocity=\"fast\""}, {"joint 'shoulder'", "\"fast\" is not a finite number"}},
      {{"lower=\"-1.5\"", "lower=\"2.5\""}, {"joint 'shoulder'", "<limit lower=\"2.5\">", "exceeds upper=\"2\"", "swap"}},
      {{"upper=\"2.0\"", "upper=\"nan\""}, {"joint 'shoulder'", "<limit upper=\"nan\">"}},
      {{"<axis xyz=\"0 1 0\"/>", "<axis xyz=\"0 1 0\"/><dynamics damping=\"nan\"/>"},
       {"joint 'shoulder'", "<dynamics damping=\"nan\">"}},
  };
  for (const auto& [edit, fragments] : cases) {
    SCOPED_TRACE(edit.second);
    try {
      ParseArm(ArmWith(edit.first, edit.second));
      ADD_FAILURE() << "accepted " << edit.second;
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), HasSubstr("arm.urdf: "));
      for (const std::string& fragment : fragments) EXPECT_THAT(e.what(), HasSubstr(fragment));
    }
  }
  // Colours and leading '+' signs are numbers too; a long bad value is cut short in the message.
  EXPECT_NO_THROW(ParseArm(ArmWith("<origin xyz=\"0 0 0.1\"/>", "<origin xyz=\"+0 0 +0.1\"/>")));
  const std::string material = "<material name=\"red\"><color rgba=\"1 0 0 one\"/></material>";
  CAIRN_EXPECT_THROWS_WITH(ParseArm(ArmWith("<link name=\"base\">", material + "<link name=\"base\">")),
                           std::runtime_error, "material 'red'", "\"one\" is not a finite number", "r g b a");
  CAIRN_EXPECT_THROWS_WITH(ParseArm(ArmWith("<sphere radius=\"0.07\"/>", "<sphere radius=\"" +
                                                                             std::string(1000, '9') + "x\"/>")),
                           std::runtime_error, "(1001 characters)");
}

TEST(UrdfParserTest, InertiaViolatingTheTriangleInequalityIsReported) {
  CAIRN_EXPECT_THROWS_WITH(
      ParseArm(Arm(
          R"(<inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.5" ixy="0" ixz="0" iyz="0"/></inertial>)")),
      std::runtime_error, "arm.urdf", "body 'link2'", "triangle inequality", "0.1 + 0.1 < 0.5", "joint 'elbow'");
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
