#include "cairn/common/number_text.h"
#include "cairn/perception/friction/friction_estimator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/text_suggestions.h"

namespace cairn::perception {

using systems::AbstractValue;
using systems::Context;
using systems::Value;

FrictionEstimator::FrictionEstimator(MaterialRegistry registry, std::shared_ptr<const MaterialSegmenter> segmenter,
                                     const Options& options)
    : segmenter_(std::move(segmenter)), options_(options), num_labels_(registry.size()) {
  if (segmenter_ == nullptr) throw std::invalid_argument("FrictionEstimator: the segmenter is null.");
  if (options.with_geometry) options.camera.Validate();
  for (const std::string& label : segmenter_->labels()) {
    const auto labels = registry.labels();
    if (std::find(labels.begin(), labels.end(), label) == labels.end()) {
      throw std::invalid_argument("The segmenter's label '" + label + "' is not in the material registry (" +
                                  QuotedList(labels) + "); add it to the registry with its friction distribution.");
    }
    registry_index_of_channel_.push_back(registry.IndexOf(label));
  }
  // Validates η and the search step now rather than at the first frame.
  FrictionQuantileImage(registry, {options.eta, options.method, options.search_step, options.num_threads});

  DeclareNumericParameter(Eigen::VectorXd::Constant(1, options.eta));
  DeclareAbstractParameter(Value<MaterialRegistry>(std::move(registry)));
  const auto& image = DeclareAbstractInputPort("image", Value<cv::Mat>());

  probabilities_cache_ = DeclareCacheEntry(
      "material_probabilities", Value<cv::Mat>(),
      [this](const Context& context, AbstractValue* value) { CalcProbabilities(context, &value->get_mutable_value<cv::Mat>()); },
      {image.ticket()});
  tables_cache_ = DeclareCacheEntry(
      "quantile_tables",
      Value<std::shared_ptr<const FrictionQuantileImage>>(),
      [this](const Context& context, AbstractValue* value) {
        const double eta = context.get_numeric_parameter(eta_parameter())[0];
        value->set_value(std::make_shared<const FrictionQuantileImage>(
            context.get_abstract_parameter<MaterialRegistry>(registry_parameter()),
            FrictionQuantileImage::Options{eta, options_.method, options_.search_step, options_.num_threads}));
      },
      {numeric_parameter_ticket(eta_parameter()), abstract_parameter_ticket(registry_parameter())});

  DeclareAbstractOutputPort(
      "material_probabilities", Value<cv::Mat>(),
      [this](const Context& context, AbstractValue* value) {
        value->set_value(EvalCacheEntry<cv::Mat>(context, probabilities_cache_));
      },
      {cache_entry_ticket(probabilities_cache_)});
  DeclareAbstractOutputPort(
      "friction_quantile", Value<cv::Mat>(),
      [this](const Context& context, AbstractValue* value) { CalcQuantiles(context, &value->get_mutable_value<cv::Mat>()); },
      {cache_entry_ticket(probabilities_cache_), cache_entry_ticket(tables_cache_)});
  if (options.with_geometry) {
    const auto& depth = DeclareAbstractInputPort("depth", Value<cv::Mat>());
    const auto& pose = DeclareAbstractInputPort("X_WC", Value<Eigen::Isometry3d>(Eigen::Isometry3d::Identity()));
    DeclareAbstractOutputPort(
        "friction_points", Value<FrictionPointCloud>(),
        [this](const Context& context, AbstractValue* value) {
          CalcPoints(context, &value->get_mutable_value<FrictionPointCloud>());
        },
        {cache_entry_ticket(probabilities_cache_), cache_entry_ticket(tables_cache_), depth.ticket(), pose.ticket()});
  }
}

void FrictionEstimator::SetEta(Context* context, double eta) const {
  ValidateContext(*context);
  if (!(eta > 0.0 && eta < 1.0)) {
    throw std::invalid_argument("eta must be in (0, 1); got " + cairn::FormatShort(eta) + ".");
  }
  context->get_mutable_numeric_parameter(eta_parameter())[0] = eta;
}

void FrictionEstimator::CalcProbabilities(const Context& context, cv::Mat* probabilities) const {
  const cv::Mat& image = GetInputPort("image").Eval<cv::Mat>(context);
  const cv::Mat channels = segmenter_->Segment(image);
  // Reorder the segmenter's channels into registry order; labels it does not know get probability 0.
  probabilities->create(image.rows, image.cols, CV_32FC(num_labels_));
  const int from = segmenter_->num_labels();
  for (int r = 0; r < image.rows; ++r) {
    const float* in = channels.ptr<float>(r);
    float* out = probabilities->ptr<float>(r);
    std::fill(out, out + static_cast<std::size_t>(image.cols) * num_labels_, 0.0f);
    for (int c = 0; c < image.cols; ++c) {
      for (int k = 0; k < from; ++k) out[c * num_labels_ + registry_index_of_channel_[k]] = in[c * from + k];
    }
  }
}

void FrictionEstimator::CalcQuantiles(const Context& context, cv::Mat* quantiles) const {
  const auto& tables = EvalCacheEntry<std::shared_ptr<const FrictionQuantileImage>>(context, tables_cache_);
  tables->Compute(EvalCacheEntry<cv::Mat>(context, probabilities_cache_), quantiles);
}

void FrictionEstimator::CalcPoints(const Context& context, FrictionPointCloud* cloud) const {
  const cv::Mat& probabilities = EvalCacheEntry<cv::Mat>(context, probabilities_cache_);
  const cv::Mat& quantiles = GetOutputPort("friction_quantile").Eval<cv::Mat>(context);
  const cv::Mat& depth = GetInputPort("depth").Eval<cv::Mat>(context);
  const auto& X_WC = GetInputPort("X_WC").Eval<Eigen::Isometry3d>(context);
  if (depth.type() != CV_32F || depth.rows != quantiles.rows || depth.cols != quantiles.cols) {
    throw std::invalid_argument("FrictionEstimator: the depth image must be CV_32F (metres) of the image's size " +
                                cairn::FormatShort(quantiles.cols) + "x" + cairn::FormatShort(quantiles.rows) + "; got " +
                                cairn::FormatShort(depth.cols) + "x" + cairn::FormatShort(depth.rows) + " of type " +
                                cairn::FormatShort(depth.type()) + ".");
  }
  const StereoCalibration& camera = options_.camera;
  cloud->points_W.clear();
  cloud->quantiles.clear();
  std::vector<int> pixels;
  for (int r = 0; r < depth.rows; ++r) {
    for (int c = 0; c < depth.cols; ++c) {
      const float d = depth.at<float>(r, c);
      if (!(d > 0.0f) || !std::isfinite(d)) continue;
      const Eigen::Vector3d p_C((c - camera.cx) * d / camera.fx, (r - camera.cy) * d / camera.fy, d);
      cloud->points_W.push_back(X_WC * p_C);
      cloud->quantiles.push_back(quantiles.at<float>(r, c));
      pixels.push_back(r * depth.cols + c);
    }
  }
  cloud->weights.resize(static_cast<Eigen::Index>(pixels.size()), num_labels_);
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    const float* p = probabilities.ptr<float>(0) + static_cast<std::size_t>(pixels[k]) * num_labels_;
    for (int i = 0; i < num_labels_; ++i) cloud->weights(static_cast<Eigen::Index>(k), i) = p[i];
  }
}

}  // namespace cairn::perception
