#include "cairn/perception/stereo/stereo_source.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

class StereoSourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("cairn_stereo_source_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(folder_);
    for (int k = 0; k < 2; ++k) {
      cv::imwrite((folder_ / ("l" + std::to_string(k) + ".png")).string(), cv::Mat(6, 8, CV_8UC1, cv::Scalar(10 + k)));
      cv::imwrite((folder_ / ("r" + std::to_string(k) + ".png")).string(), cv::Mat(6, 8, CV_8UC1, cv::Scalar(20 + k)));
    }
    cv::imwrite((folder_ / "small.png").string(), cv::Mat(3, 4, CV_8UC1, cv::Scalar(0)));
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  std::string Write(const std::string& text) {
    const std::string path = (folder_ / "sequence.yaml").string();
    std::ofstream(path) << text;
    return path;
  }

  std::filesystem::path folder_;
};

constexpr const char* kCalibration = "calibration: {fx: 400, fy: 410, cx: 3.5, cy: 2.5, baseline: 0.12}\n";

TEST_F(StereoSourceTest, PlaysTheSequenceBackOneFramePerPeriod) {
  const std::string path = Write(std::string(kCalibration) +
                                 "frames:\n"
                                 "  - {left: l0.png, right: r0.png,\n"
                                 "     translation: [0, 0, 0], rotation_wxyz: [1, 0, 0, 0]}\n"
                                 "  - {left: l1.png, right: r1.png,\n"
                                 "     translation: [1, 2, 3], rotation_wxyz: [0, 0, 0, 2]}\n");
  StereoSource source(path, 0.5);
  EXPECT_EQ(source.num_frames(), 2);
  EXPECT_DOUBLE_EQ(source.calibration().fy, 410.0);
  EXPECT_DOUBLE_EQ(source.calibration().baseline, 0.12);
  auto context = source.CreateDefaultContext();
  EXPECT_EQ(source.get_left_output_port().Eval<cv::Mat>(*context).at<uint8_t>(0, 0), 10);
  context->SetTime(0.5);
  EXPECT_EQ(source.get_left_output_port().Eval<cv::Mat>(*context).at<uint8_t>(0, 0), 11);
  EXPECT_EQ(source.get_right_output_port().Eval<cv::Mat>(*context).at<uint8_t>(5, 7), 21);
  const auto& X_WC = source.get_pose_output_port().Eval<Eigen::Isometry3d>(*context);
  EXPECT_TRUE(X_WC.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
  // The quaternion (0, 0, 0, 2) normalises to a half turn about z.
  EXPECT_TRUE(X_WC.linear().isApprox(Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix()));
  context->SetTime(10.0);
  EXPECT_EQ(source.get_left_output_port().Eval<cv::Mat>(*context).at<uint8_t>(0, 0), 11);
}

TEST_F(StereoSourceTest, ReportsBadFilesClearly) {
  CAIRN_EXPECT_THROWS_WITH(StereoSource((folder_ / "none.yaml").string(), 0.1), std::invalid_argument, "none.yaml");
  CAIRN_EXPECT_THROWS_WITH(StereoSource(Write("frames: []\n"), 0.1), std::invalid_argument, "line 1",
                           "missing key 'calibration' in the stereo source");
  CAIRN_EXPECT_THROWS_WITH(StereoSource(Write(std::string(kCalibration) + "frames: []\n"), 0.1), std::invalid_argument,
                           "non-empty list");
  CAIRN_EXPECT_THROWS_WITH(
      StereoSource(Write(std::string(kCalibration) +
                         "frames:\n  - {left: missing.png, right: r0.png, translation: [0, 0, 0], "
                         "rotation_wxyz: [1, 0, 0, 0]}\n"),
                   0.1),
      std::invalid_argument, "line 3", "missing.png", "cannot be read");
  CAIRN_EXPECT_THROWS_WITH(
      StereoSource(Write(std::string(kCalibration) +
                         "frames:\n  - {left: l0.png, right: small.png, translation: [0, 0, 0], "
                         "rotation_wxyz: [1, 0, 0, 0]}\n"),
                   0.1),
      std::invalid_argument, "left 8x6 but right 4x3");
  CAIRN_EXPECT_THROWS_WITH(
      StereoSource(Write(std::string(kCalibration) + "frames:\n  - {left: l0.png, right: r0.png}\n"), 0.1),
      std::invalid_argument, "line 3", "missing key 'translation' in frame 0");
  CAIRN_EXPECT_THROWS_WITH(
      StereoSource(Write("calibration: {fx: 400, fy: 410, cx: 3.5, cy: 2.5, baseline: -1}\nframes:\n"
                         "  - {left: l0.png, right: r0.png, translation: [0, 0, 0], rotation_wxyz: [1, 0, 0, 0]}\n"),
                   0.1),
      std::invalid_argument, "baseline");
  CAIRN_EXPECT_THROWS_WITH(StereoSource(Write(std::string(kCalibration) + "frame: []\n"), 0.1), std::invalid_argument,
                           "line 2", "unknown key 'frame' in the stereo source", "Did you mean 'frames'?");
  CAIRN_EXPECT_THROWS_WITH(StereoSource(Write(kCalibration), -0.1), std::invalid_argument, "period");
}

TEST_F(StereoSourceTest, RefusesNonFinitePosesAndImagesTooLargeToDecode) {
  CAIRN_EXPECT_THROWS_WITH(
      StereoSource(Write(std::string(kCalibration) +
                         "frames:\n  - {left: l0.png, right: r0.png, translation: [0, .nan, 0], "
                         "rotation_wxyz: [1, 0, 0, 0]}\n"),
                   0.1),
      std::invalid_argument, "line 3", "'translation' must be a finite number, got '.nan'");
  // A PNG whose header claims 30000 x 30000 pixels is refused before it is decoded.
  std::vector<uchar> bytes;
  ASSERT_TRUE(cv::imencode(".png", cv::Mat(1, 1, CV_8UC1, cv::Scalar(0)), bytes));
  for (int offset : {16, 20}) {
    bytes[offset + 2] = 0x75;
    bytes[offset + 3] = 0x30;
  }
  std::ofstream((folder_ / "huge.png").string(), std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  CAIRN_EXPECT_THROWS_WITH(
      StereoSource(Write(std::string(kCalibration) +
                         "frames:\n  - {left: huge.png, right: r0.png, translation: [0, 0, 0], "
                         "rotation_wxyz: [1, 0, 0, 0]}\n"),
                   0.1),
      std::invalid_argument, "line 3", "frame 0 names image", "huge.png", "30000 x 30000", "limit of 67108864 pixels");
  CAIRN_EXPECT_THROWS_WITH(
      StereoSource(Write("calibration: {fx: 400, fy: 410, cx: .inf, cy: 2.5, baseline: 0.1}\nframes:\n"
                         "  - {left: l0.png, right: r0.png, translation: [0, 0, 0], rotation_wxyz: [1, 0, 0, 0]}\n"),
                   0.1),
      std::invalid_argument, "line 1", "'cx' must be a finite number, got '.inf'");
}

}  // namespace
}  // namespace cairn::perception
