#include "cairn/perception/evaluation/material_segmentation_score.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// 1 x n image of 2-label probabilities: pixel i has P(label 0) = p0[i].
cv::Mat TwoLabel(const std::vector<float>& p0) {
  cv::Mat p(1, static_cast<int>(p0.size()), CV_32FC2);
  for (std::size_t i = 0; i < p0.size(); ++i) p.at<cv::Vec2f>(0, static_cast<int>(i)) = {p0[i], 1.0f - p0[i]};
  return p;
}

TEST(MaterialSegmentationScoreTest, AccuraciesAndCalibration) {
  MaterialSegmentationScore score(2);
  // Truth: three pixels of label 0, one of label 1, one ignored. Predictions: 0, 0, 1, 1, (ignored).
  const cv::Mat truth = (cv::Mat_<std::uint8_t>(1, 5) << 0, 0, 0, 1, 255);
  score.Add(TwoLabel({0.9f, 0.75f, 0.4f, 0.2f, 0.5f}), truth);
  EXPECT_EQ(score.num_pixels(), 4);
  EXPECT_DOUBLE_EQ(score.pixel_accuracy(), 0.75);
  EXPECT_DOUBLE_EQ(score.class_average_accuracy(), 0.5 * (2.0 / 3.0 + 1.0));
  EXPECT_EQ(score.confusion()(0, 1), 1);
  // Bins (10): 0.9 -> bin 9 (right), 0.75 -> bin 7 (right), 0.6 -> bin 6 (wrong), 0.8 -> bin 8 (right).
  const double expected_ece = 0.25 * (0.1 + 0.25 + 0.6 + 0.2);
  EXPECT_NEAR(score.expected_calibration_error(), expected_ece, 1e-6);
  const double nll = -(std::log(0.9) + std::log(0.75) + std::log(0.4) + std::log(0.8)) / 4.0;
  EXPECT_NEAR(score.mean_negative_log_likelihood(), nll, 1e-6);
}

TEST(MaterialSegmentationScoreTest, BadInputsAreNamed) {
  CAIRN_EXPECT_THROWS_WITH(MaterialSegmentationScore(0), std::invalid_argument, "num_labels", "got 0");
  CAIRN_EXPECT_THROWS_WITH(MaterialSegmentationScore(2, 0), std::invalid_argument, "num_bins", "got 0");
  MaterialSegmentationScore score(2);
  CAIRN_EXPECT_THROWS_WITH(score.Add(cv::Mat(1, 2, CV_32FC3), cv::Mat(1, 2, CV_8UC1)), std::invalid_argument,
                           "CV_32FC(2)", "3 channel(s)");
  CAIRN_EXPECT_THROWS_WITH(score.Add(TwoLabel({0.5f, 0.5f}), cv::Mat(1, 3, CV_8UC1)), std::invalid_argument,
                           "CV_8UC1", "3x1");
  const cv::Mat truth = (cv::Mat_<std::uint8_t>(1, 2) << 0, 7);
  CAIRN_EXPECT_THROWS_WITH(score.Add(TwoLabel({0.5f, 0.5f}), truth), std::invalid_argument, "(0, 1) holds 7");
}

}  // namespace
}  // namespace cairn::perception
