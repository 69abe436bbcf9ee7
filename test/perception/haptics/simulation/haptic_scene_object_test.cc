#include "cairn/perception/haptics/simulation/haptic_scene_object.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

HapticPrimitive Sphere(const Eigen::Vector3d& c, double r, bool stiff) {
  return {HapticPrimitive::Shape::kSphere, c, Eigen::Vector3d::Zero(), r, stiff};
}

TEST(HapticSceneObjectTest, RaysHitEachShapeAtTheKnownDistance) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  const HapticSceneObject sphere("s", {Sphere({2, 0, 0}, 0.5, true)});
  EXPECT_NEAR(*sphere.CastRay(Eigen::Vector3d::Zero(), x, 10.0), 1.5, 1e-12);
  EXPECT_FALSE(sphere.CastRay(Eigen::Vector3d::Zero(), x, 1.0).has_value());  // beyond max_t
  EXPECT_FALSE(sphere.CastRay(Eigen::Vector3d::Zero(), -x, 10.0).has_value());
  const HapticSceneObject capsule(
      "c", {{HapticPrimitive::Shape::kCapsule, Eigen::Vector3d(2, 0, -1), Eigen::Vector3d(2, 0, 1), 0.1, false}});
  EXPECT_NEAR(*capsule.CastRay(Eigen::Vector3d(0, 0, 0.5), x, 10.0), 1.9, 1e-12);  // the side
  EXPECT_NEAR(*capsule.CastRay(Eigen::Vector3d(2, 0, 3), -Eigen::Vector3d::UnitZ(), 10.0), 1.9, 1e-12);  // a cap
  const HapticSceneObject box(
      "b", {{HapticPrimitive::Shape::kBox, Eigen::Vector3d(3, 0, 0), Eigen::Vector3d(0.5, 1, 1), 0.0, true}});
  EXPECT_NEAR(*box.CastRay(Eigen::Vector3d::Zero(), x, 10.0), 2.5, 1e-12);
  EXPECT_TRUE(box.CastRay(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0.3, 0).normalized(), 10.0).has_value());
}

TEST(HapticSceneObjectTest, StiffnessAndDistances) {
  const HapticSceneObject soft("leaves", {Sphere({0, 0, 1}, 0.1, false)});
  EXPECT_TRUE(soft.traversable());
  EXPECT_EQ(soft.StiffDistance(Eigen::Vector3d::Zero()), std::numeric_limits<double>::infinity());
  const HapticSceneObject mixed("plant", {Sphere({0, 0, 1}, 0.1, false), Sphere({1, 0, 0}, 0.25, true)});
  EXPECT_FALSE(mixed.traversable());
  EXPECT_NEAR(mixed.StiffDistance(Eigen::Vector3d::Zero()), 0.75, 1e-12);
  const HapticSceneObject box(
      "b", {{HapticPrimitive::Shape::kBox, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 0.0, true}});
  EXPECT_NEAR(box.StiffDistance(Eigen::Vector3d(3, 0, 0)), 2.0, 1e-12);
  EXPECT_NEAR(box.StiffDistance(Eigen::Vector3d(0.5, 0, 0)), -0.5, 1e-12);
  const HapticSceneObject moved = mixed.Translated({0, 0, 1});
  EXPECT_NEAR(moved.StiffDistance(Eigen::Vector3d(0, 0, 1)), 0.75, 1e-12);
}

TEST(HapticSceneObjectTest, BadPrimitiveNamesIt) {
  CAIRN_EXPECT_THROWS_WITH(HapticSceneObject("rock", {Sphere({0, 0, 0}, 0.1, true), Sphere({0, 0, 0}, 0.0, true)}),
                           std::invalid_argument, "primitive 1 of object 'rock'");
}

}  // namespace
}  // namespace cairn::perception
