#include "cairn/common/number_text.h"
#include "cairn/perception/evaluation/middlebury_pair.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cairn/common/number_text.h"
#include "cairn/perception/io/image_file.h"

namespace cairn::perception {
namespace {

// The disparity image of `path` as it is stored: one channel, 8- or 16-bit.
cv::Mat ReadDisparityValues(const std::string& path) {
  const cv::Mat raw = ReadImageFile(path, cv::IMREAD_UNCHANGED);
  if (raw.depth() != CV_8U && raw.depth() != CV_16U) {
    throw std::invalid_argument("ground truth '" + path + "' has OpenCV depth " + cairn::FormatShort(raw.depth()) +
                                "; disparity PNGs are 8-bit (Middlebury) or 16-bit (KITTI)");
  }
  if (raw.channels() == 1) return raw;
  // Middlebury stores grey in three channels; a colour-coded map (a visualisation) has no disparity values.
  std::vector<cv::Mat> planes;
  cv::split(raw, planes);
  for (int c = 1; c < std::min(raw.channels(), 3); ++c) {
    if (cv::countNonZero(planes[0] != planes[static_cast<std::size_t>(c)]) != 0) {
      throw std::invalid_argument("ground truth '" + path + "' has " + cairn::FormatShort(raw.channels()) +
                                  " channels that differ, so it is a colour visualisation, not disparity values; "
                                  "pass the grey disparity PNG of the data set");
    }
  }
  return planes[0];
}

}  // namespace

cv::Mat LoadGrayImage(const std::string& path) { return ReadImageFile(path, cv::IMREAD_GRAYSCALE); }

cv::Mat LoadDisparityImage(const std::string& path, double scale) {
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    throw std::invalid_argument("ground-truth scale " + cairn::FormatShort(scale) +
                                " must be positive and finite: the file value per pixel of disparity (Middlebury "
                                "2001: 8, tsukuba 16; KITTI 16-bit: 256)");
  }
  const cv::Mat raw = ReadDisparityValues(path);
  cv::Mat disparity;
  raw.convertTo(disparity, CV_32F, 1.0 / scale);
  return disparity;
}

cv::Mat LoadDisparityImage(const std::string& path) {
  const cv::Mat raw = ReadDisparityValues(path);
  if (raw.depth() != CV_16U) {
    throw std::invalid_argument("ground truth '" + path +
                                "' is 8-bit, whose scale differs per data set; give it (Middlebury 2001: 8, "
                                "tsukuba 16, 2003 quarter size 4, 2005-2006 third size 3)");
  }
  cv::Mat disparity;
  raw.convertTo(disparity, CV_32F, 1.0 / kKittiDisparityScale);
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
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) {
    throw std::invalid_argument("OcclusionFromGroundTruth: tolerance " + FormatShort(tolerance) +
                                " must be finite and >= 0 pixels (1 is usual)");
  }
  cv::Mat occluded(left_disparity.size(), CV_8UC1, cv::Scalar(0));
  for (int y = 0; y < left_disparity.rows; ++y) {
    const float* dl = left_disparity.ptr<float>(y);
    const float* dr = right_disparity.ptr<float>(y);
    for (int x = 0; x < left_disparity.cols; ++x) {
      if (!(dl[x] > 0.0f)) continue;
      const double match = std::round(x - static_cast<double>(dl[x]));  // infinite disparities fall outside
      const int xr = match >= 0.0 && match < left_disparity.cols ? static_cast<int>(match) : -1;
      if (xr < 0) {
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
