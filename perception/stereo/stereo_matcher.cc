#include "cairn/perception/stereo/stereo_matcher.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cairn/perception/stereo/compute_confidence.h"
#include "cairn/perception/stereo/compute_cost_volume.h"
#include "cairn/perception/stereo/cost_samples.h"

namespace cairn::perception {

using systems::Context;

StereoMatcher::StereoMatcher(const Options& options) : options_(options) {
  // The image width is only known per pair; ComputeCostVolume() checks the range against it.
  options.cost_volume.Validate(CostVolumeOptions::kUnknownImageSize, CostVolumeOptions::kUnknownImageSize);
  const bool fitted = std::isnan(options.parameter);
  if (!fitted) {
    // Throws for a non-positive parameter or a histogram model, naming the fix.
    ConfidenceModel::Parametric(options.model, options.cost_volume.cost, options.parameter);
  }
  DeclareAbstractInputPort("left", systems::Value<cv::Mat>(cv::Mat()));
  DeclareAbstractInputPort("right", systems::Value<cv::Mat>(cv::Mat()));
  const auto inputs = Prerequisites{input_port_ticket(0), input_port_ticket(1)};
  costs_cache_ = DeclareCacheEntry(
      "cost_volume", systems::Value<DisparityVolume>(DisparityVolume()),
      [this](const Context& c, systems::AbstractValue* v) {
        CalcCostVolume(c, &v->get_mutable_value<DisparityVolume>());
      },
      inputs);
  wta_cache_ = DeclareCacheEntry(
      "wta", systems::Value<WtaResult>(WtaResult()),
      [this](const Context& c, systems::AbstractValue* v) { CalcWta(c, &v->get_mutable_value<WtaResult>()); },
      {cache_entry_ticket(costs_cache_)});
  const ConfidenceModel model_value = ConfidenceModel::Merrell(options.cost_volume.cost, 1.0);
  model_cache_ = DeclareCacheEntry(
      "model", systems::Value<ConfidenceModel>(model_value),
      [this](const Context& c, systems::AbstractValue* v) { CalcModel(c, &v->get_mutable_value<ConfidenceModel>()); },
      {cache_entry_ticket(costs_cache_), cache_entry_ticket(wta_cache_)});
  DeclareAbstractOutputPort(
      "cost_volume", systems::Value<DisparityVolume>(DisparityVolume()),
      [this](const Context& c, systems::AbstractValue* v) {
        v->get_mutable_value<DisparityVolume>() = EvalCacheEntry<DisparityVolume>(c, costs_cache_);
      },
      {cache_entry_ticket(costs_cache_)});
  DeclareAbstractOutputPort(
      "wta", systems::Value<WtaResult>(WtaResult()),
      [this](const Context& c, systems::AbstractValue* v) {
        v->get_mutable_value<WtaResult>() = EvalCacheEntry<WtaResult>(c, wta_cache_);
      },
      {cache_entry_ticket(wta_cache_)});
  DeclareAbstractOutputPort("confidence", DisparityVolume(), &StereoMatcher::CalcConfidence,
                            {cache_entry_ticket(costs_cache_), cache_entry_ticket(model_cache_)});
  DeclareAbstractOutputPort(
      "model", systems::Value<ConfidenceModel>(model_value),
      [this](const Context& c, systems::AbstractValue* v) {
        v->get_mutable_value<ConfidenceModel>() = EvalCacheEntry<ConfidenceModel>(c, model_cache_);
      },
      {cache_entry_ticket(model_cache_)});
}

void StereoMatcher::CalcCostVolume(const Context& context, DisparityVolume* costs) const {
  const auto& left = get_left_input_port().Eval<cv::Mat>(context);
  const auto& right = get_right_input_port().Eval<cv::Mat>(context);
  if (left.empty() || right.empty()) {
    throw std::invalid_argument("StereoMatcher: the " + std::string(left.empty() ? "left" : "right") +
                                " image is empty; connect a stereo source or fix both inputs to 8-bit images");
  }
  ComputeCostVolume(left, right, options_.cost_volume, costs);
}

void StereoMatcher::CalcWta(const Context& context, WtaResult* wta) const {
  ComputeWinnerTakeAll(EvalCacheEntry<DisparityVolume>(context, costs_cache_), options_.wta, wta);
}

void StereoMatcher::CalcModel(const Context& context, ConfidenceModel* model) const {
  if (!std::isnan(options_.parameter)) {
    *model = ConfidenceModel::Parametric(options_.model, options_.cost_volume.cost, options_.parameter);
    return;
  }
  std::vector<float> samples;
  CollectConsistentWtaCosts(EvalCacheEntry<DisparityVolume>(context, costs_cache_),
                            EvalCacheEntry<WtaResult>(context, wta_cache_), &samples);
  *model = ConfidenceModel::FitMaximumLikelihood(options_.model, options_.cost_volume.cost, samples);
}

void StereoMatcher::CalcConfidence(const Context& context, DisparityVolume* confidence) const {
  ComputeConfidence(EvalCacheEntry<DisparityVolume>(context, costs_cache_),
                    EvalCacheEntry<ConfidenceModel>(context, model_cache_), confidence);
}

}  // namespace cairn::perception
