#include "cairn/common/number_text.h"
#include "cairn/perception/evaluation/middlebury_pair.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace cairn::perception {
namespace {

cv::Mat Read(const std::string& path, int flags) {
  if (!std::ifstream(path).good()) {
    throw std::runtime_error("cannot open image '" + path + "': no such readable file; check the path");
  }
  cv::Mat image = cv::imread(path, flags);
  if (image.empty()) {
    throw std::runtime_error("cannot decode image '" + path + "'; pass a PNG, JPEG or PGM file");
  }
  return image;
}

}  // namespace

cv::Mat LoadGrayImage(const std::string& path) { return Read(path, cv::IMREAD_GRAYSCALE); }

cv::Mat LoadDisparityImage(const std::string& path, double scale) {
  if (!(scale > 0.0)) {
    throw std::invalid_argument("ground-truth scale " + cairn::FormatShort(scale) +
                                " must be positive (Middlebury 2001: 8, tsukuba 16)");
  }
  const cv::Mat raw = Read(path, cv::IMREAD_GRAYSCALE);
  cv::Mat disparity;
  raw.convertTo(disparity, CV_32F, 1.0 / scale);
  return disparity;
}

cv::Mat OcclusionFromGroundTruth(const cv::Mat& left_disparity, const cv::Mat& right_disparity, double tolerance) {
  if (left_disparity.type() != CV_32FC1 || right_disparity.type() != CV_32FC1 ||
      left_disparity.size() != right_disparity.size()) {
    throw std::invalid_argument("OcclusionFromGroundTruth: both ground truths must be CV_32FC1 of one size, got " +
                                cairn::FormatShort(left_disparity.cols) + "x" + cairn::FormatShort(left_disparity.rows) +
                                " and " + cairn::FormatShort(right_disparity.cols) + "x" +
                                cairn::FormatShort(right_disparity.rows));
  }
  cv::Mat occluded(left_disparity.size(), CV_8UC1, cv::Scalar(0));
  for (int y = 0; y < left_disparity.rows; ++y) {
    const float* dl = left_disparity.ptr<float>(y);
    const float* dr = right_disparity.ptr<float>(y);
    for (int x = 0; x < left_disparity.cols; ++x) {
      if (!(dl[x] > 0.0f)) continue;
      const int xr = static_cast<int>(std::lround(x - dl[x]));
      if (xr < 0 || xr >= left_disparity.cols) {
        occluded.at<uint8_t>(y, x) = 255;
      } else if (dr[xr] > 0.0f && std::abs(dr[xr] - dl[x]) > tolerance) {
        occluded.at<uint8_t>(y, x) = 255;
      }
    }
  }
  return occluded;
}

MiddleburyPair MiddleburyPair::Load(const std::string& folder, double scale) {
  MiddleburyPair pair;
  pair.left = LoadGrayImage(folder + "/im2.png");
  pair.right = LoadGrayImage(folder + "/im6.png");
  pair.gt_left = LoadDisparityImage(folder + "/disp2.png", scale);
  if (std::ifstream(folder + "/disp6.png").good()) {
    pair.gt_right = LoadDisparityImage(folder + "/disp6.png", scale);
    pair.occluded = OcclusionFromGroundTruth(pair.gt_left, pair.gt_right);
  }
  return pair;
}

}  // namespace cairn::perception
