// Cairn::perception: the cost volume and winner-take-all of a small random-texture pair whose right image is the
// left one shifted by 4 pixels; the consumer itself uses cv::Mat through Cairn::perception's interface.
#include <cmath>
#include <cstdio>

#include <opencv2/core.hpp>

#include <cairn/perception/stereo/compute_cost_volume.h>
#include <cairn/perception/stereo/disparity_volume.h>
#include <cairn/perception/stereo/winner_take_all.h>

int main() {
  using namespace cairn::perception;
  constexpr int kWidth = 96, kHeight = 48, kShift = 4;
  cv::Mat left(kHeight, kWidth, CV_8UC1);
  cv::RNG rng(12);
  rng.fill(left, cv::RNG::UNIFORM, 0, 256);
  cv::Mat right(kHeight, kWidth, CV_8UC1);
  rng.fill(right, cv::RNG::UNIFORM, 0, 256);
  // Left pixel x sees what right pixel x - d sees.
  left.colRange(kShift, kWidth).copyTo(right.colRange(0, kWidth - kShift));
  CostVolumeOptions options;
  options.window = 5;
  options.min_disparity = 0;
  options.max_disparity = 15;
  options.num_threads = 1;
  DisparityVolume costs;
  WtaResult wta;
  ComputeCostVolumeAndWinnerTakeAll(left, right, options, WtaOptions{}, &costs, &wta);
  int checked = 0, right_disparity = 0;
  for (int y = 8; y < kHeight - 8; ++y) {
    for (int x = options.max_disparity + 8; x < kWidth - 8; ++x) {
      ++checked;
      if (std::abs(wta.disparity.at<float>(y, x) - kShift) < 0.5f) ++right_disparity;
    }
  }
  std::printf("consumer perception: %d x %d x %d cost volume, disparity %d found at %d of %d pixels\n",
              costs.height(), costs.width(), costs.num_disparities(), kShift, right_disparity, checked);
  return checked > 0 && right_disparity == checked ? 0 : 1;
}
