#include "cairn/common/number_text.h"
#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/io/image_file.h"

namespace cairn::perception {

SyntheticStereoRenderer::SyntheticStereoRenderer(const StereoCalibration& calibration, int width, int height,
                                                 double noise_variance, std::uint32_t seed)
    : calibration_(calibration), width_(width), height_(height), noise_variance_(noise_variance), seed_(seed) {
  calibration.Validate();
  if (width <= 0 || height <= 0 || static_cast<std::int64_t>(width) * height > kMaxImagePixels) {
    throw std::invalid_argument("SyntheticStereoRenderer: image size " + cairn::FormatShort(width) + "x" +
                                cairn::FormatShort(height) + " must be positive with at most " +
                                cairn::FormatShort(kMaxImagePixels) + " pixels");
  }
  if (!(noise_variance >= 0.0) || !std::isfinite(noise_variance)) {
    throw std::invalid_argument("SyntheticStereoRenderer: noise variance " + cairn::FormatShort(noise_variance) +
                                " must be finite and >= 0; use 0 for noise-free images");
  }
}

SyntheticStereoFrame SyntheticStereoRenderer::Render(const SyntheticStereoScene& scene, const Eigen::Isometry3d& X_WC,
                                                     int frame_index) const {
  if (frame_index < 0) {
    throw std::invalid_argument("SyntheticStereoRenderer::Render: frame index " + cairn::FormatShort(frame_index) +
                                " is negative; frames are numbered from 0 (it selects the noise realisation)");
  }
  SyntheticStereoFrame frame;
  frame.X_WC = X_WC;
  frame.depth.create(height_, width_, CV_32FC1);
  frame.labels.create(height_, width_, CV_32SC1);
  cv::Mat intensity[2] = {cv::Mat(height_, width_, CV_64FC1), cv::Mat(height_, width_, CV_64FC1)};
  const bool colour = scene.has_colour_textures();
  cv::Mat colours[2];
  for (cv::Mat& c : colours) {
    if (colour) c.create(height_, width_, CV_64FC3);
  }
  const Eigen::Matrix3d R_WC = X_WC.linear();
  const StereoCalibration& k = calibration_;
  ParallelFor(height_, 0, [&](int, int y0, int y1) {
    for (int view = 0; view < 2; ++view) {
      const Eigen::Vector3d origin = X_WC * Eigen::Vector3d(view == 0 ? 0.0 : k.baseline, 0.0, 0.0);
      for (int y = y0; y < y1; ++y) {
        for (int x = 0; x < width_; ++x) {
          double sum = 0.0;
          Eigen::Vector3d colour_sum = Eigen::Vector3d::Zero();
          for (int s = 0; s < 4; ++s) {
            const double u = x + (s % 2 == 0 ? -0.25 : 0.25);
            const double v = y + (s / 2 == 0 ? -0.25 : 0.25);
            const Eigen::Vector3d ray_C((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
            const Eigen::Vector3d ray_W = R_WC * ray_C;
            const auto hit = scene.Intersect(origin, ray_W);
            if (!colour) {
              sum += hit ? hit->intensity : kBackgroundIntensity;
              continue;
            }
            const Eigen::Vector3d bgr =
                hit ? scene.ColourOf(origin, ray_W, *hit) : Eigen::Vector3d::Constant(kBackgroundIntensity);
            colour_sum += bgr;
            sum += 0.114 * bgr[0] + 0.587 * bgr[1] + 0.299 * bgr[2];
          }
          intensity[view].at<double>(y, x) = sum / 4.0;
          if (colour) {
            cv::Vec3d& c = colours[view].at<cv::Vec3d>(y, x);
            for (int channel = 0; channel < 3; ++channel) c[channel] = colour_sum[channel] / 4.0;
          }
          if (view == 0) {
            const Eigen::Vector3d ray_C((x - k.cx) / k.fx, (y - k.cy) / k.fy, 1.0);
            const auto hit = scene.Intersect(origin, R_WC * ray_C);
            // With ray_C.z() = 1 the ray parameter is the depth.
            frame.depth.at<float>(y, x) = hit ? static_cast<float>(hit->t) : std::numeric_limits<float>::infinity();
            frame.labels.at<int32_t>(y, x) = hit ? hit->label : -1;
          }
        }
      }
    }
  });
  std::mt19937 rng(seed_ * 7919u + static_cast<std::uint32_t>(frame_index));
  std::normal_distribution<double> noise(0.0, std::sqrt(noise_variance_));
  cv::Mat* outputs[2] = {&frame.left, &frame.right};
  for (int view = 0; view < 2; ++view) {
    outputs[view]->create(height_, width_, CV_8UC1);
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        double value = intensity[view].at<double>(y, x);
        if (noise_variance_ > 0.0) value += noise(rng);
        outputs[view]->at<uint8_t>(y, x) = static_cast<uint8_t>(std::clamp(std::lround(value), 0L, 255L));
      }
    }
  }
  if (colour) {
    // A stream of its own, so the grey images' noise is the same with or without colour.
    std::mt19937 colour_rng(seed_ * 7919u + static_cast<std::uint32_t>(frame_index) + 0x9E3779B9u);
    cv::Mat* colour_outputs[2] = {&frame.left_colour, &frame.right_colour};
    for (int view = 0; view < 2; ++view) {
      colour_outputs[view]->create(height_, width_, CV_8UC3);
      for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
          const cv::Vec3d& c = colours[view].at<cv::Vec3d>(y, x);
          cv::Vec3b& out = colour_outputs[view]->at<cv::Vec3b>(y, x);
          for (int channel = 0; channel < 3; ++channel) {
            double value = c[channel];
            if (noise_variance_ > 0.0) value += noise(colour_rng);
            out[channel] = static_cast<uint8_t>(std::clamp(std::lround(value), 0L, 255L));
          }
        }
      }
    }
  }
  return frame;
}

}  // namespace cairn::perception
