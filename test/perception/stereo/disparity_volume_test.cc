#include "cairn/perception/stereo/disparity_volume.h"

#include <limits>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(DisparityVolumeTest, CurvesArePixelMajorAndContiguous) {
  DisparityVolume volume(2, 3, -1, 2);
  EXPECT_EQ(volume.num_disparities(), 4);
  EXPECT_EQ(volume.data().size(), 2u * 3u * 4u);
  volume.mutable_curve(1, 2)[3] = 7.0f;
  EXPECT_EQ(volume.at(1, 2, 3), 7.0f);
  EXPECT_EQ(volume.data().back(), 7.0f);
  EXPECT_EQ(volume.curve(0, 1) - volume.curve(0, 0), 4);
}

TEST(DisparityVolumeTest, RejectsBadShapes) {
  CAIRN_EXPECT_THROWS_WITH(DisparityVolume(0, 3, 0, 1), std::invalid_argument, "3x0");
  CAIRN_EXPECT_THROWS_WITH(DisparityVolume(2, 3, 5, 1), std::invalid_argument, "max_disparity 1", "swap");
  // The full int range of disparities overflowed int; a huge volume is named with its limit before allocating.
  CAIRN_EXPECT_THROWS_WITH(DisparityVolume(2, 3, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()),
                           std::invalid_argument, "4294967296 disparities", "more than the 1073741824");
  CAIRN_EXPECT_THROWS_WITH(DisparityVolume(8192, 8192, 0, 255), std::invalid_argument, "8192x8192",
                           "17179869184 values", "narrow the disparity range");
}

}  // namespace
}  // namespace cairn::perception
