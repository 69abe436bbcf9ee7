#include "cairn/perception/stereo/disparity_to_depth.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::perception {

DisparityToDepth::DisparityToDepth(const StereoCalibration& calibration, const Options& options)
    : calibration_(calibration), options_(options) {
  calibration.Validate();
  if (!(options.min_peak_ratio >= 1.0) || !std::isfinite(options.min_peak_ratio)) {
    throw std::invalid_argument("DisparityToDepth: min_peak_ratio must be a finite number >= 1 (1 keeps every pixel); got " +
                                cairn::FormatShort(options.min_peak_ratio));
  }
  DeclareAbstractInputPort("wta", systems::Value<WtaResult>(WtaResult()));
  DeclareAbstractOutputPort(
      "depth", systems::Value<cv::Mat>(cv::Mat()),
      [this](const systems::Context& context, systems::AbstractValue* value) {
        Convert(get_wta_input_port().Eval<WtaResult>(context), &value->get_mutable_value<cv::Mat>());
      },
      {input_port_ticket(0)});
}

void DisparityToDepth::Convert(const WtaResult& wta, cv::Mat* depth) const {
  const cv::Mat& disparity = wta.disparity;
  if (disparity.empty()) {
    depth->release();
    return;
  }
  if (disparity.type() != CV_32F) {
    throw std::invalid_argument("DisparityToDepth: the disparity image must be CV_32F (ComputeWinnerTakeAll's); got type " +
                                std::to_string(disparity.type()));
  }
  const bool check_lr = options_.require_left_right;
  const bool check_peak = options_.min_peak_ratio > 1.0;
  if (check_lr && (wta.lr_consistent.size() != disparity.size() || wta.lr_consistent.type() != CV_8U)) {
    throw std::invalid_argument("DisparityToDepth: lr_consistent must be a CV_8U image of the disparity's size; "
                                "give the full WtaResult or set require_left_right to false");
  }
  if (check_peak && (wta.peak_ratio.size() != disparity.size() || wta.peak_ratio.type() != CV_32F)) {
    throw std::invalid_argument("DisparityToDepth: peak_ratio must be a CV_32F image of the disparity's size; "
                                "give the full WtaResult or set min_peak_ratio to 1");
  }
  depth->create(disparity.size(), CV_32F);
  const double fb = calibration_.depth_times_disparity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int y = 0; y < disparity.rows; ++y) {
    const float* d = disparity.ptr<float>(y);
    const std::uint8_t* lr = check_lr ? wta.lr_consistent.ptr<std::uint8_t>(y) : nullptr;
    const float* peak = check_peak ? wta.peak_ratio.ptr<float>(y) : nullptr;
    float* z = depth->ptr<float>(y);
    for (int x = 0; x < disparity.cols; ++x) {
      const bool trusted = d[x] > 0.0f && std::isfinite(d[x]) && (lr == nullptr || lr[x] != 0) &&
                           (peak == nullptr || peak[x] >= options_.min_peak_ratio);
      z[x] = trusted ? static_cast<float>(fb / d[x]) : nan;
    }
  }
}

}  // namespace cairn::perception
