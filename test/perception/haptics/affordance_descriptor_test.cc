#include "cairn/perception/haptics/affordance_descriptor.h"

#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(AffordanceDescriptorTest, FourMetricsOfALineByHand) {
  Eigen::MatrixXi histogram(3, 8);
  histogram << 0, 2, 3, 0, 1, 0, 0, 4,  //
      0, 0, 0, 0, 0, 0, 0, 0,           //
      1, 1, 1, 1, 1, 1, 1, 1;
  const AffordanceDescriptor d = AffordanceDescriptor::FromHistogram(histogram);
  ASSERT_EQ(d.lines(), 3);
  ASSERT_EQ(d.values().size(), 12);
  // Clusters {2, 3}, {1}, {4}: n = 3, largest s = 2 bins, d = 10 points / 8 bins, m = 5 points.
  EXPECT_EQ(d.n(0), 3.0);
  EXPECT_EQ(d.s(0), 2.0);
  EXPECT_EQ(d.d(0), 1.25);
  EXPECT_EQ(d.m(0), 5.0);
  EXPECT_EQ(d.values().segment<4>(4), Eigen::Vector4d::Zero());
  EXPECT_EQ(d.values().segment<4>(8), Eigen::Vector4d(1.0, 8.0, 1.0, 8.0));
}

TEST(AffordanceDescriptorTest, LargestClusterByBinsAndByPointsDiffer) {
  Eigen::MatrixXi histogram(1, 6);
  histogram << 1, 1, 1, 0, 9, 0;
  const AffordanceDescriptor d = AffordanceDescriptor::FromHistogram(histogram);
  EXPECT_EQ(d.s(0), 3.0);  // the three-bin cluster
  EXPECT_EQ(d.m(0), 9.0);  // the one-bin cluster holds most points
}

TEST(AffordanceDescriptorTest, PaperDefaultsGive56ValuesAndBinTheBoundingBox) {
  const AffordanceDescriptor::Options options;
  EXPECT_EQ(options.columns, 16);
  EXPECT_EQ(options.lines, 14);
  // A 16 x 14 grid of points 2 cm apart spanning x in [0, 0.3], y in [0, 0.26]: one point per bin.
  Eigen::Matrix3Xd points(3, 16 * 14);
  for (int l = 0; l < 14; ++l) {
    for (int c = 0; c < 16; ++c) points.col(l * 16 + c) = Eigen::Vector3d(0.02 * c, 0.02 * l, 0.5);
  }
  const Eigen::MatrixXi histogram = AffordanceDescriptor::Histogram(points, options);
  EXPECT_EQ(histogram, Eigen::MatrixXi::Ones(14, 16));
  const AffordanceDescriptor d = AffordanceDescriptor::Compute(points, options);
  EXPECT_EQ(d.values().size(), 56);
  for (int l = 0; l < 14; ++l) {
    EXPECT_EQ(d.values().segment<4>(4 * l), Eigen::Vector4d(1.0, 16.0, 1.0, 16.0));
  }
}

TEST(AffordanceDescriptorTest, DownsamplingAndReachApplyBeforeBinning) {
  AffordanceDescriptor::Options options;
  options.columns = 2;
  options.lines = 1;
  Eigen::Matrix3Xd points(3, 4);
  points << 0.0, 0.004, 0.1, 0.1,  //
      0.0, 0.0, 0.0, 0.0,          //
      0.5, 0.5, 0.5, 5.0;          // the second is within 1 cm of the first, the last is out of reach
  const Eigen::MatrixXi histogram = AffordanceDescriptor::Histogram(points, options);
  EXPECT_EQ(histogram, (Eigen::MatrixXi(1, 2) << 1, 1).finished());
  // A fixed window ignores points outside it.
  options.window_C = Eigen::AlignedBox2d(Eigen::Vector2d(-0.05, -0.05), Eigen::Vector2d(0.05, 0.05));
  EXPECT_EQ(AffordanceDescriptor::Histogram(points, options), (Eigen::MatrixXi(1, 2) << 0, 1).finished());
  // No point in reach: an all-zero descriptor.
  options.reach_radius = 0.1;
  EXPECT_EQ(AffordanceDescriptor::Compute(points, options).values(), Eigen::VectorXd::Zero(4));
}

TEST(AffordanceDescriptorTest, BadInputNamesTheValue) {
  AffordanceDescriptor::Options options;
  options.columns = 0;
  CAIRN_EXPECT_THROWS_WITH(AffordanceDescriptor::Validate(options), std::invalid_argument, "columns is 0",
                           "between 1 and 1024");
  options = {};
  options.min_point_distance = -0.01;
  CAIRN_EXPECT_THROWS_WITH(AffordanceDescriptor::Validate(options), std::invalid_argument,
                           "min_point_distance is -0.01");
  options = {};
  options.window_C = Eigen::AlignedBox2d(Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, 1.0));
  CAIRN_EXPECT_THROWS_WITH(AffordanceDescriptor::Validate(options), std::invalid_argument, "window_C [1, 0]");
  CAIRN_EXPECT_THROWS_WITH(AffordanceDescriptor::FromValues(Eigen::VectorXd::Zero(6)), std::invalid_argument,
                           "got 6 values");
  Eigen::VectorXd values = Eigen::VectorXd::Zero(8);
  values[5] = -1.0;
  CAIRN_EXPECT_THROWS_WITH(AffordanceDescriptor::FromValues(values), std::invalid_argument,
                           "descriptor value 5 is -1");
  Eigen::MatrixXi histogram = Eigen::MatrixXi::Zero(2, 2);
  histogram(1, 1) = -3;
  CAIRN_EXPECT_THROWS_WITH(AffordanceDescriptor::FromHistogram(histogram), std::invalid_argument, "count -3");
  CAIRN_EXPECT_THROWS_WITH(AffordanceDescriptor::FromHistogram(Eigen::MatrixXi(0, 3)), std::invalid_argument,
                           "histogram lines is 0");
  CAIRN_EXPECT_THROWS_WITH(AffordanceDescriptor::FromHistogram(Eigen::MatrixXi::Zero(2, 5000)),
                           std::invalid_argument, "histogram columns is 5000", "between 1 and 1024");
}

}  // namespace
}  // namespace cairn::perception
