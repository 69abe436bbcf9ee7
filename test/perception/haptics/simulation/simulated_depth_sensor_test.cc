#include "cairn/perception/haptics/simulation/simulated_depth_sensor.h"

#include <cmath>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// A wall facing the sensor at x = distance (its front face).
std::vector<HapticSceneObject> WallAt(double distance) {
  return {HapticSceneObject("wall", {{HapticPrimitive::Shape::kBox, Eigen::Vector3d(distance + 0.5, 0, 0.5),
                                      Eigen::Vector3d(0.5, 5, 5), 0.0, true}})};
}

TEST(SimulatedDepthSensorTest, PoseAxesFollowTheSensorConvention) {
  const Eigen::Isometry3d X = SimulatedDepthSensor::LookingAlong({1, 2, 0.3}, 0.0);
  EXPECT_TRUE(X.linear().col(2).isApprox(Eigen::Vector3d::UnitX()));   // z_C forward
  EXPECT_TRUE(X.linear().col(1).isApprox(-Eigen::Vector3d::UnitZ()));  // y_C down
  EXPECT_TRUE(X.linear().col(0).isApprox(-Eigen::Vector3d::UnitY()));  // x_C right
  EXPECT_NEAR(X.linear().determinant(), 1.0, 1e-12);
}

TEST(SimulatedDepthSensorTest, DepthNoiseGrowsWithTheSquareOfTheRange) {
  SimulatedDepthSensor::Options options;
  options.width = 80;
  options.height = 60;
  const SimulatedDepthSensor sensor(options);
  const Eigen::Isometry3d X_WC = SimulatedDepthSensor::LookingAlong({0, 0, 0.5}, 0.0);
  for (const double distance : {1.0, 3.0}) {
    const Eigen::Matrix3Xd points = sensor.Render(WallAt(distance), X_WC, 11);
    ASSERT_EQ(points.cols(), 80 * 60);
    const Eigen::ArrayXd z = points.row(2).transpose().array();
    const double mean = z.mean();
    const double sd = std::sqrt((z - mean).square().mean());
    EXPECT_NEAR(mean, distance, 5e-4 * distance * distance);
    const double expected = 1.425e-3 * distance * distance;
    EXPECT_NEAR(sd, expected, 0.1 * expected) << distance;
  }
  // Same seed, same frame; another seed, other noise.
  EXPECT_EQ(sensor.Render(WallAt(1.0), X_WC, 4), sensor.Render(WallAt(1.0), X_WC, 4));
  EXPECT_NE(sensor.Render(WallAt(1.0), X_WC, 4), sensor.Render(WallAt(1.0), X_WC, 5));
}

TEST(SimulatedDepthSensorTest, RangeLimitsAndGround) {
  SimulatedDepthSensor::Options options;
  options.width = 40;
  options.height = 30;
  const Eigen::Isometry3d X_WC = SimulatedDepthSensor::LookingAlong({0, 0, 0.5}, 0.0);
  EXPECT_EQ(SimulatedDepthSensor(options).Render(WallAt(0.2), X_WC, 1).cols(), 0);  // nearer than 0.4 m
  EXPECT_EQ(SimulatedDepthSensor(options).Render({}, X_WC, 1).cols(), 0);
  options.render_ground = true;
  const Eigen::Matrix3Xd ground = SimulatedDepthSensor(options).Render({}, X_WC, 1);
  EXPECT_GT(ground.cols(), 0);
  EXPECT_LT(ground.cols(), 40 * 15 + 1);  // only the lower half looks down
  EXPECT_TRUE((ground.row(1).array() > 0.0).all());  // below the sensor
}

TEST(SimulatedDepthSensorTest, BadOptionsNameTheValue) {
  SimulatedDepthSensor::Options options;
  options.width = 0;
  CAIRN_EXPECT_THROWS_WITH(SimulatedDepthSensor{options}, std::invalid_argument, "0 x 150");
  options = {};
  options.max_range = 0.1;
  CAIRN_EXPECT_THROWS_WITH(SimulatedDepthSensor{options}, std::invalid_argument, "range [0.4, 0.1]");
}

}  // namespace
}  // namespace cairn::perception
