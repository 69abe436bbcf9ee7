#pragma once

/// @file
/// StereoMatcher: a rectified pair in; cost volume, winner-take-all disparity and whole-range confidence out.

#include <opencv2/core.hpp>

#include "cairn/perception/stereo/confidence_model.h"
#include "cairn/perception/stereo/cost_volume_options.h"
#include "cairn/perception/stereo/disparity_volume.h"
#include "cairn/perception/stereo/winner_take_all.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Matches a rectified pair with ComputeCostVolume(), ComputeWinnerTakeAll() and ComputeConfidence(). The
/// confidence model's parameter is either fixed, or fitted per pair by maximum likelihood from the costs at
/// left-right consistent WTA disparities (thesis eqs. 4.8-4.11), so no ground truth is needed.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `left` | cv::Mat (CV_8UC1) | rectified left image |
/// | input `right` | cv::Mat (CV_8UC1) | rectified right image, same size |
/// | output `cost_volume` | DisparityVolume | costs E_d of every left pixel over [min_disparity, max_disparity] |
/// | output `wta` | WtaResult | winner-take-all disparity, peak ratio and left-right check |
/// | output `confidence` | DisparityVolume | C(d) of every left pixel (sums to one per pixel) |
/// | output `model` | ConfidenceModel | the model used for this pair (with its fitted parameter) |
///
/// No state. Every output is cached and recomputed only when an input changes; the cost volume and the WTA
/// result are computed once per pair and shared.
class StereoMatcher final : public systems::LeafSystem {
 public:
  /// How to match.
  struct Options {
    /// Cost function, window, prefilter and disparity range.
    CostVolumeOptions cost_volume;
    /// Sub-pixel refinement and left-right tolerance.
    WtaOptions wta;
    /// The confidence model family.
    ConfidenceModelType model{ConfidenceModelType::kMerrell};
    /// The model's parameter; NaN (the default) fits it per pair by maximum likelihood.
    double parameter{std::numeric_limits<double>::quiet_NaN()};
  };

  /// Throws std::invalid_argument for bad cost-volume options (see CostVolumeOptions::Validate()), or a fixed
  /// parameter that is not positive, or a fixed-parameter histogram model (it needs training data: leave the
  /// parameter NaN to train it per pair).
  explicit StereoMatcher(const Options& options);

  const Options& options() const { return options_; }

  const systems::InputPort& get_left_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_right_input_port() const { return get_input_port(1); }
  const systems::OutputPort& get_cost_volume_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_wta_output_port() const { return get_output_port(1); }
  const systems::OutputPort& get_confidence_output_port() const { return get_output_port(2); }
  const systems::OutputPort& get_model_output_port() const { return get_output_port(3); }

 private:
  void CalcCostVolume(const systems::Context& context, DisparityVolume* costs) const;
  void CalcWta(const systems::Context& context, WtaResult* wta) const;
  void CalcModel(const systems::Context& context, ConfidenceModel* model) const;
  void CalcConfidence(const systems::Context& context, DisparityVolume* confidence) const;

  Options options_;
  int costs_cache_{};
  int wta_cache_{};
  int model_cache_{};
};

}  // namespace cairn::perception
