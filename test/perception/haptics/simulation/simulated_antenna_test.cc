#include "cairn/perception/haptics/simulation/simulated_antenna.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/multibody/data.h"
#include "cairn/multibody/kinematics.h"
#include "cairn/multibody/urdf_parser.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::perception {
namespace {

TEST(SimulatedAntennaTest, InverseKinematicsInvertsTheTipMap) {
  const SimulatedAntenna antenna;
  const Eigen::Vector3d q(0.4, -0.3, 0.7);
  const Eigen::Vector3d p = SimulatedAntenna::TipPosition(q);
  EXPECT_NEAR(p.norm(), 0.7, 1e-12);
  EXPECT_LT(p.y(), 0.0 + 1.0);  // tilt -0.3 (down) gives y > 0
  EXPECT_GT(p.y(), 0.0);
  const auto back = antenna.InverseKinematics(p);
  ASSERT_TRUE(back.has_value());
  EXPECT_TRUE(back->isApprox(q, 1e-12));
  EXPECT_FALSE(antenna.InverseKinematics({0.0, 0.0, 1.2}).has_value());   // beyond 1 m
  EXPECT_FALSE(antenna.InverseKinematics({0.0, 0.0, -0.5}).has_value());  // behind: pan beyond 90°
}

TEST(SimulatedAntennaTest, TheUrdfHasTheSameKinematics) {
  const multibody::Model model =
      multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_antenna.urdf");
  ASSERT_EQ(model.nq(), 3);
  multibody::Data data(model);
  const int tip = model.GetFrameIndex("tip");
  for (const Eigen::Vector3d& q : {Eigen::Vector3d(0.0, 0.0, 0.5), Eigen::Vector3d(0.4, -0.3, 0.7),
                                  Eigen::Vector3d(-1.2, 0.8, 0.2)}) {
    multibody::ForwardKinematics(model, data, q);
    EXPECT_TRUE(multibody::FramePose(model, data, tip).translation().isApprox(SimulatedAntenna::TipPosition(q), 1e-12))
        << q.transpose();
  }
}

TEST(SimulatedAntennaTest, StiffElementsBlockAndSoftOnesBend) {
  const SimulatedAntenna antenna;
  const std::vector<Eigen::Vector3d> targets{{0.1, 0.0, 0.6}, {-0.1, 0.0, 0.6}};
  // In A (= W here): a stiff ball on the way to the first target, or a soft one.
  for (const bool stiff : {true, false}) {
    const std::vector<HapticSceneObject> objects{HapticSceneObject(
        "ball", {{HapticPrimitive::Shape::kSphere, Eigen::Vector3d(0.1, 0.0, 0.55), Eigen::Vector3d::Zero(), 0.1,
                  stiff}})};
    const AntennaInteraction result = antenna.Probe(targets, objects, Eigen::Isometry3d::Identity());
    EXPECT_EQ(result.blocked, stiff);
    EXPECT_EQ(result.targets_reached, stiff ? 0 : 2);
    if (stiff) {
      EXPECT_LT(result.tip_W.z(), 0.46);  // stopped at the ball's surface, not beyond it
    }
  }
  const AntennaInteraction none = antenna.Probe({{0.0, 0.0, 2.0}}, {}, Eigen::Isometry3d::Identity());
  EXPECT_EQ(none.targets_unreachable, 1);
  EXPECT_FALSE(none.blocked);
}

TEST(SimulatedAntennaTest, BadOptionsNameTheValue) {
  SimulatedAntenna::Options options;
  options.max_extension = 0.01;
  CAIRN_EXPECT_THROWS_WITH(SimulatedAntenna{options}, std::invalid_argument, "extension range [0.05, 0.01]");
}

}  // namespace
}  // namespace cairn::perception
