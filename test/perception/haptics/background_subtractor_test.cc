#include "cairn/perception/haptics/background_subtractor.h"

#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(BackgroundSubtractorTest, ForegroundIsWhatTheReferenceLeftEmpty) {
  Eigen::Matrix3Xd reference(3, 3);
  reference << 0.005, 0.015, 0.025, 0.005, 0.005, 0.005, 1.005, 1.005, 1.005;
  const BackgroundSubtractor background(reference, 0.01);
  EXPECT_EQ(background.reference_cells(), 3);
  Eigen::Matrix3Xd scene(3, 5);
  scene << 0.006, 0.5, 0.016, 0.035, 0.024,  //
      0.004, 0.0, 0.006, 0.005, 0.004,       //
      1.004, 0.9, 1.006, 1.005, 1.001;
  const Eigen::Matrix3Xd foreground = background.Foreground(scene);
  ASSERT_EQ(foreground.cols(), 2);
  EXPECT_EQ(foreground(0, 0), 0.5);
  EXPECT_EQ(foreground(0, 1), 0.035);
}

TEST(BackgroundSubtractorTest, BadResolutionNamesTheValue) {
  CAIRN_EXPECT_THROWS_WITH(BackgroundSubtractor(Eigen::Matrix3Xd(3, 0), 0.0), std::invalid_argument,
                           "background resolution is 0 m");
}

}  // namespace
}  // namespace cairn::perception
