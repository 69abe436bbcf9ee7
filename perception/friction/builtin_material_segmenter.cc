#include "cairn/perception/friction/builtin_material_segmenter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "cairn/common/atomic_file.h"
#include "cairn/common/internal/yaml_reader.h"
#include "cairn/common/number_text.h"

namespace cairn::perception {
namespace {

using cairn::internal::YamlReader;

constexpr const char* kFormat = "cairn_builtin_material_segmenter";
constexpr int kVersion = 1;

// Patch descriptors (one column per sample) and their labels.
struct Samples {
  Eigen::MatrixXf x;
  std::vector<int> y;
};

void ValidateTrainingSet(int num_labels, int window, const std::vector<cv::Mat>& images,
                         const std::vector<cv::Mat>& labels) {
  if (images.size() != labels.size()) {
    throw std::invalid_argument("BuiltinMaterialSegmenter::Train: " + cairn::FormatShort(images.size()) +
                                " images but " + cairn::FormatShort(labels.size()) +
                                " label images; pass one label image per image.");
  }
  if (images.size() < 2) {
    throw std::invalid_argument("BuiltinMaterialSegmenter::Train: needs at least 2 images (the last ones calibrate "
                                "the probabilities); got " + cairn::FormatShort(images.size()) + ".");
  }
  for (std::size_t i = 0; i < images.size(); ++i) {
    const cv::Mat& image = images[i];
    if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3)) {
      throw std::invalid_argument("BuiltinMaterialSegmenter::Train: image " + cairn::FormatShort(i) +
                                  " must be a non-empty 8-bit image with 1 or 3 channels; got depth " +
                                  cairn::FormatShort(image.depth()) + " with " + cairn::FormatShort(image.channels()) +
                                  " channel(s).");
    }
    if (image.cols < window || image.rows < window) {
      throw std::invalid_argument("BuiltinMaterialSegmenter::Train: image " + cairn::FormatShort(i) + " is " +
                                  cairn::FormatShort(image.cols) + "x" + cairn::FormatShort(image.rows) +
                                  " pixels, smaller than the " + cairn::FormatShort(window) + "x" +
                                  cairn::FormatShort(window) + " patch window; use larger images or a smaller window.");
    }
    const cv::Mat& label = labels[i];
    if (label.type() != CV_8UC1 || label.size() != image.size()) {
      throw std::invalid_argument("BuiltinMaterialSegmenter::Train: label image " + cairn::FormatShort(i) +
                                  " must be CV_8UC1 of its image's size " + cairn::FormatShort(image.cols) + "x" +
                                  cairn::FormatShort(image.rows) + "; got " + cairn::FormatShort(label.cols) + "x" +
                                  cairn::FormatShort(label.rows) + " of type " + cairn::FormatShort(label.type()) + ".");
    }
    for (int r = 0; r < label.rows; ++r) {
      const std::uint8_t* row = label.ptr<std::uint8_t>(r);
      for (int c = 0; c < label.cols; ++c) {
        if (row[c] >= num_labels && row[c] != 255) {
          throw std::invalid_argument("BuiltinMaterialSegmenter::Train: label image " + cairn::FormatShort(i) +
                                      " holds " + cairn::FormatShort(row[c]) + " at pixel (" + cairn::FormatShort(r) + ", " +
                                      cairn::FormatShort(c) + "); values must be label indices below " +
                                      cairn::FormatShort(num_labels) + " or 255 for unlabelled pixels.");
        }
      }
    }
  }
}

Samples CollectSamples(const MaterialFeatures& features, const std::vector<cv::Mat>& images,
                       const std::vector<cv::Mat>& labels, std::size_t begin, std::size_t end) {
  std::vector<float> values;
  Samples samples;
  for (std::size_t i = begin; i < end; ++i) {
    const cv::Mat descriptors = features.Compute(images[i]);
    const cv::Size grid = features.GridSize(images[i].size());
    for (int gr = 0; gr < grid.height; ++gr) {
      const std::uint8_t* row = labels[i].ptr<std::uint8_t>(features.CentreOf(gr, images[i].rows));
      for (int gc = 0; gc < grid.width; ++gc) {
        const std::uint8_t label = row[features.CentreOf(gc, images[i].cols)];
        if (label == 255) continue;
        const float* d = descriptors.ptr<float>(gr * grid.width + gc);
        values.insert(values.end(), d, d + MaterialFeatures::kDimension);
        samples.y.push_back(label);
      }
    }
  }
  samples.x = Eigen::Map<Eigen::MatrixXf>(values.data(), MaterialFeatures::kDimension,
                                          static_cast<Eigen::Index>(samples.y.size()));
  return samples;
}

// Keeps at most `cap` samples per label, chosen by a seeded shuffle, in their original order.
Samples CapPerLabel(const Samples& all, int num_labels, int cap, std::mt19937* rng) {
  std::vector<std::vector<int>> by_label(static_cast<std::size_t>(num_labels));
  for (int i = 0; i < static_cast<int>(all.y.size()); ++i) by_label[static_cast<std::size_t>(all.y[i])].push_back(i);
  std::vector<int> keep;
  for (auto& indices : by_label) {
    if (static_cast<int>(indices.size()) > cap) {
      std::shuffle(indices.begin(), indices.end(), *rng);
      indices.resize(static_cast<std::size_t>(cap));
    }
    keep.insert(keep.end(), indices.begin(), indices.end());
  }
  std::sort(keep.begin(), keep.end());
  Samples kept;
  kept.x.resize(all.x.rows(), static_cast<Eigen::Index>(keep.size()));
  for (std::size_t k = 0; k < keep.size(); ++k) {
    kept.x.col(static_cast<Eigen::Index>(k)) = all.x.col(keep[k]);
    kept.y.push_back(all.y[static_cast<std::size_t>(keep[k])]);
  }
  return kept;
}

// Row-wise softmax of logits / temperature (one column per sample), in place.
void SoftmaxColumns(double temperature, Eigen::MatrixXf* logits) {
  const float inv = static_cast<float>(1.0 / temperature);
  for (Eigen::Index j = 0; j < logits->cols(); ++j) {
    auto col = logits->col(j);
    col *= inv;
    col.array() -= col.maxCoeff();
    col = col.array().exp();
    col /= col.sum();
  }
}

// Mean negative log-likelihood and 10-bin expected calibration error of softmax(logits / temperature).
std::pair<double, double> NllAndEce(const Eigen::MatrixXf& logits, const std::vector<int>& y, double temperature) {
  Eigen::MatrixXf p = logits;
  SoftmaxColumns(temperature, &p);
  constexpr int kBins = 10;
  double nll = 0.0;
  std::vector<double> count(kBins, 0.0), correct(kBins, 0.0), confidence(kBins, 0.0);
  for (Eigen::Index j = 0; j < p.cols(); ++j) {
    Eigen::Index best = 0;
    const double top = p.col(j).maxCoeff(&best);
    nll -= std::log(std::max(static_cast<double>(p(y[static_cast<std::size_t>(j)], j)), 1e-12));
    const auto bin = static_cast<std::size_t>(std::clamp(static_cast<int>(top * kBins), 0, kBins - 1));
    count[bin] += 1.0;
    correct[bin] += best == y[static_cast<std::size_t>(j)] ? 1.0 : 0.0;
    confidence[bin] += top;
  }
  const double n = std::max<double>(1.0, static_cast<double>(p.cols()));
  double ece = 0.0;
  for (int b = 0; b < kBins; ++b) {
    if (count[b] > 0.0) ece += std::abs(correct[b] - confidence[b]) / n;
  }
  return {nll / n, ece};
}

double Accuracy(const Eigen::MatrixXf& logits, const std::vector<int>& y) {
  if (y.empty()) return 0.0;
  int right = 0;
  for (Eigen::Index j = 0; j < logits.cols(); ++j) {
    Eigen::Index best = 0;
    logits.col(j).maxCoeff(&best);
    right += best == y[static_cast<std::size_t>(j)] ? 1 : 0;
  }
  return static_cast<double>(right) / static_cast<double>(y.size());
}

struct Network {
  Eigen::MatrixXf w1;
  Eigen::VectorXf b1;
  Eigen::MatrixXf w2;
  Eigen::VectorXf b2;

  Eigen::MatrixXf Logits(const Eigen::MatrixXf& x) const {
    const Eigen::MatrixXf hidden = ((w1 * x).colwise() + b1).cwiseMax(0.0f);
    return (w2 * hidden).colwise() + b2;
  }
};

// Adam on the class-balanced cross-entropy with an L2 penalty; mini-batches of 128 in a seeded order.
void Fit(const Samples& data, int num_labels, const BuiltinMaterialSegmenter::TrainingOptions& options,
         std::mt19937* rng, Network* net) {
  const int d = static_cast<int>(data.x.rows());
  const int h = options.hidden_units;
  std::normal_distribution<float> normal(0.0f, 1.0f);
  net->w1 = Eigen::MatrixXf::NullaryExpr(h, d, [&] { return normal(*rng) * std::sqrt(2.0f / d); });
  net->b1 = Eigen::VectorXf::Zero(h);
  net->w2 = Eigen::MatrixXf::NullaryExpr(num_labels, h, [&] { return normal(*rng) * std::sqrt(1.0f / h); });
  net->b2 = Eigen::VectorXf::Zero(num_labels);
  // Class weights: every label present contributes equally, whatever its sample count.
  std::vector<double> counts(static_cast<std::size_t>(num_labels), 0.0);
  for (int label : data.y) counts[static_cast<std::size_t>(label)] += 1.0;
  const double present = static_cast<double>(std::count_if(counts.begin(), counts.end(), [](double c) { return c > 0; }));
  Eigen::VectorXf class_weight(num_labels);
  for (int k = 0; k < num_labels; ++k) {
    class_weight[k] = counts[static_cast<std::size_t>(k)] > 0
                          ? static_cast<float>(static_cast<double>(data.y.size()) / (present * counts[static_cast<std::size_t>(k)]))
                          : 0.0f;
  }

  struct Moments {
    Eigen::MatrixXf m, v;
  };
  auto zeros = [](const auto& like) { return Moments{Eigen::MatrixXf::Zero(like.rows(), like.cols()),
                                                     Eigen::MatrixXf::Zero(like.rows(), like.cols())}; };
  Moments mw1 = zeros(net->w1), mb1 = zeros(net->b1), mw2 = zeros(net->w2), mb2 = zeros(net->b2);
  const float beta1 = 0.9f, beta2 = 0.999f, epsilon = 1e-8f;
  const auto lr = static_cast<float>(options.learning_rate);
  const auto decay = static_cast<float>(options.weight_decay);
  int step = 0;
  auto adam = [&](Eigen::Ref<Eigen::MatrixXf> param, const Eigen::MatrixXf& grad, Moments* mom) {
    mom->m = beta1 * mom->m + (1.0f - beta1) * grad;
    mom->v = beta2 * mom->v + (1.0f - beta2) * grad.cwiseProduct(grad);
    const float c1 = 1.0f - std::pow(beta1, static_cast<float>(step));
    const float c2 = 1.0f - std::pow(beta2, static_cast<float>(step));
    param.array() -= lr * (mom->m.array() / c1) / ((mom->v.array() / c2).sqrt() + epsilon);
  };

  const int n = static_cast<int>(data.y.size());
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  constexpr int kBatch = 128;
  Eigen::MatrixXf xb(d, kBatch);
  for (int epoch = 0; epoch < options.epochs; ++epoch) {
    std::shuffle(order.begin(), order.end(), *rng);
    for (int start = 0; start < n; start += kBatch) {
      const int b = std::min(kBatch, n - start);
      xb.resize(d, b);
      Eigen::VectorXf weight(b);
      for (int j = 0; j < b; ++j) {
        const int i = order[static_cast<std::size_t>(start + j)];
        xb.col(j) = data.x.col(i);
        weight[j] = class_weight[data.y[static_cast<std::size_t>(i)]];
      }
      const Eigen::MatrixXf pre = (net->w1 * xb).colwise() + net->b1;
      const Eigen::MatrixXf hidden = pre.cwiseMax(0.0f);
      Eigen::MatrixXf p = (net->w2 * hidden).colwise() + net->b2;
      SoftmaxColumns(1.0, &p);
      // d(loss)/d(logits) = weight * (p - onehot) / batch.
      for (int j = 0; j < b; ++j) {
        p(data.y[static_cast<std::size_t>(order[static_cast<std::size_t>(start + j)])], j) -= 1.0f;
        p.col(j) *= weight[j] / static_cast<float>(b);
      }
      const Eigen::MatrixXf gw2 = p * hidden.transpose() + decay * net->w2;
      const Eigen::VectorXf gb2 = p.rowwise().sum();
      Eigen::MatrixXf dh = net->w2.transpose() * p;
      dh.array() *= (pre.array() > 0.0f).cast<float>();
      const Eigen::MatrixXf gw1 = dh * xb.transpose() + decay * net->w1;
      const Eigen::VectorXf gb1 = dh.rowwise().sum();
      ++step;
      adam(net->w1, gw1, &mw1);
      adam(net->b1, gb1, &mb1);
      adam(net->w2, gw2, &mw2);
      adam(net->b2, gb2, &mb2);
    }
  }
}

// The temperature minimising the calibration samples' NLL: golden-section search on log T in [log 0.05, log 20]
// (the NLL is unimodal in T for fixed logits).
double FitTemperature(const Eigen::MatrixXf& logits, const std::vector<int>& y) {
  double lo = std::log(0.05);
  double hi = std::log(20.0);
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = hi - ratio * (hi - lo);
  double b = lo + ratio * (hi - lo);
  double fa = NllAndEce(logits, y, std::exp(a)).first;
  double fb = NllAndEce(logits, y, std::exp(b)).first;
  for (int i = 0; i < 40; ++i) {
    if (fa < fb) {
      hi = b;
      b = a;
      fb = fa;
      a = hi - ratio * (hi - lo);
      fa = NllAndEce(logits, y, std::exp(a)).first;
    } else {
      lo = a;
      a = b;
      fa = fb;
      b = lo + ratio * (hi - lo);
      fb = NllAndEce(logits, y, std::exp(b)).first;
    }
  }
  return std::exp(0.5 * (lo + hi));
}

void EmitMatrix(YAML::Emitter& out, const char* key, const Eigen::MatrixXf& m) {
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "rows" << YAML::Value << m.rows() << YAML::Key << "cols" << YAML::Value << m.cols();
  out << YAML::Key << "data" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  // Row-major, as a reader would expect.
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    for (Eigen::Index c = 0; c < m.cols(); ++c) out << m(r, c);
  }
  out << YAML::EndSeq << YAML::EndMap;
}

Eigen::MatrixXf ReadMatrix(const YamlReader& yaml, const char* key, Eigen::Index rows, Eigen::Index cols) {
  const std::string where = std::string("'") + key + "'";
  const YAML::Node node = yaml.Require(yaml.root(), key, "the model");
  constexpr long long kMaxIndex = std::numeric_limits<int>::max();
  const long long r = yaml.Integer(node, "rows", where, 0, kMaxIndex, -1);
  const long long c = yaml.Integer(node, "cols", where, 0, kMaxIndex, -1);
  const YAML::Node data = YamlReader::Has(node, "data") ? node["data"] : YAML::Node();
  if (r != rows || c != cols || !data.IsSequence() || static_cast<Eigen::Index>(data.size()) != rows * cols) {
    yaml.Fail(node, std::string("the model has a malformed '") + key + "': expected " + cairn::FormatShort(rows) + "x" +
                        cairn::FormatShort(cols) + " with " + cairn::FormatShort(rows * cols) + " values, got rows " +
                        cairn::FormatShort(r) + ", cols " + cairn::FormatShort(c) + " and " +
                        cairn::FormatShort(data.IsSequence() ? data.size() : 0) + " values.");
  }
  Eigen::MatrixXf m(rows, cols);
  for (Eigen::Index i = 0; i < rows * cols; ++i) {
    const YAML::Node value = data[static_cast<std::size_t>(i)];
    const float v = static_cast<float>(yaml.AsNumber(value, key));
    if (!std::isfinite(v)) yaml.Fail(value, std::string("'") + key + "' has a value outside the range of float.");
    m(i / cols, i % cols) = v;
  }
  return m;
}

}  // namespace

BuiltinMaterialSegmenter::BuiltinMaterialSegmenter(std::vector<std::string> labels, MaterialFeatures features,
                                                   Eigen::VectorXf mean, Eigen::VectorXf inverse_scale,
                                                   Eigen::MatrixXf w1, Eigen::VectorXf b1, Eigen::MatrixXf w2,
                                                   Eigen::VectorXf b2, double temperature)
    : MaterialSegmenter(std::move(labels)),
      features_(features),
      mean_(std::move(mean)),
      inverse_scale_(std::move(inverse_scale)),
      w1_(std::move(w1)),
      b1_(std::move(b1)),
      w2_(std::move(w2)),
      b2_(std::move(b2)),
      temperature_(temperature) {}

BuiltinMaterialSegmenter BuiltinMaterialSegmenter::Train(const std::vector<std::string>& labels,
                                                         const std::vector<cv::Mat>& images,
                                                         const std::vector<cv::Mat>& label_images,
                                                         const TrainingOptions& options, TrainingReport* report) {
  if (labels.empty() || labels.size() > 255) {
    throw std::invalid_argument("BuiltinMaterialSegmenter::Train: needs 1 to 255 labels; got " +
                                cairn::FormatShort(labels.size()) + ".");
  }
  if (options.hidden_units < 1 || options.epochs < 1 || options.max_samples_per_label < 1) {
    throw std::invalid_argument("BuiltinMaterialSegmenter::Train: hidden_units, epochs and max_samples_per_label "
                                "must be >= 1; got " + cairn::FormatShort(options.hidden_units) + ", " +
                                cairn::FormatShort(options.epochs) + ", " + cairn::FormatShort(options.max_samples_per_label) +
                                ".");
  }
  if (options.hidden_units > kMaxHiddenUnits) {
    throw std::invalid_argument("BuiltinMaterialSegmenter::Train: hidden_units " +
                                cairn::FormatShort(options.hidden_units) + " is more than the " +
                                cairn::FormatShort(kMaxHiddenUnits) + " a model may have; try 48.");
  }
  if (!(options.learning_rate > 0.0) || !(options.weight_decay >= 0.0) || !std::isfinite(options.learning_rate) ||
      !std::isfinite(options.weight_decay)) {
    throw std::invalid_argument("BuiltinMaterialSegmenter::Train: learning_rate must be finite and > 0 and "
                                "weight_decay finite and >= 0; got " + FormatShort(options.learning_rate) + " and " +
                                FormatShort(options.weight_decay) + ".");
  }
  if (!(options.calibration_fraction > 0.0 && options.calibration_fraction < 1.0)) {
    throw std::invalid_argument("BuiltinMaterialSegmenter::Train: calibration_fraction must be in (0, 1); got " +
                                FormatShort(options.calibration_fraction) + ". Try 0.25.");
  }
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (std::find(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(i), labels[i]) !=
        labels.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw std::invalid_argument("BuiltinMaterialSegmenter::Train: the label '" + labels[i] +
                                  "' appears twice; labels must be distinct.");
    }
  }
  const int num_labels = static_cast<int>(labels.size());
  const MaterialFeatures features(options.window, options.stride);
  ValidateTrainingSet(num_labels, options.window, images, label_images);
  const std::size_t num_calibration = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::lround(options.calibration_fraction * static_cast<double>(images.size()))), 1,
      images.size() - 1);
  const std::size_t split = images.size() - num_calibration;

  std::mt19937 rng(options.seed);
  const Samples all = CollectSamples(features, images, label_images, 0, split);
  if (all.y.empty()) {
    throw std::invalid_argument("BuiltinMaterialSegmenter::Train: the training images (the first " +
                                cairn::FormatShort(split) + ") have no labelled patch centre; label some pixels.");
  }
  Samples train = CapPerLabel(all, num_labels, options.max_samples_per_label, &rng);
  Samples calibration = CollectSamples(features, images, label_images, split, images.size());
  if (calibration.y.empty()) {
    throw std::invalid_argument("BuiltinMaterialSegmenter::Train: the calibration images (the last " +
                                cairn::FormatShort(num_calibration) + ") have no labelled patch centre.");
  }

  const Eigen::VectorXf mean = train.x.rowwise().mean();
  const Eigen::VectorXf stddev =
      ((train.x.colwise() - mean).array().square().rowwise().mean()).sqrt().matrix();
  const Eigen::VectorXf inverse_scale = stddev.unaryExpr([](float s) { return s > 1e-6f ? 1.0f / s : 1.0f; });
  train.x = (train.x.colwise() - mean).array().colwise() * inverse_scale.array();
  calibration.x = (calibration.x.colwise() - mean).array().colwise() * inverse_scale.array();

  Network net;
  Fit(train, num_labels, options, &rng, &net);
  const Eigen::MatrixXf calibration_logits = net.Logits(calibration.x);
  const double temperature = FitTemperature(calibration_logits, calibration.y);
  if (report != nullptr) {
    report->num_training_samples = static_cast<int>(train.y.size());
    report->num_calibration_samples = static_cast<int>(calibration.y.size());
    report->training_accuracy = Accuracy(net.Logits(train.x), train.y);
    report->calibration_accuracy = Accuracy(calibration_logits, calibration.y);
    report->temperature = temperature;
    std::tie(report->nll_before, report->ece_before) = NllAndEce(calibration_logits, calibration.y, 1.0);
    std::tie(report->nll_after, report->ece_after) = NllAndEce(calibration_logits, calibration.y, temperature);
  }
  return BuiltinMaterialSegmenter(labels, features, mean, inverse_scale, net.w1, net.b1, net.w2, net.b2,
                                  temperature);
}

cv::Mat BuiltinMaterialSegmenter::SegmentGrid(const cv::Mat& image) const {
  const cv::Mat descriptors = features_.Compute(image);
  const cv::Size grid = features_.GridSize(image.size());
  const int n = num_labels();
  Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> rows(
      descriptors.ptr<float>(), descriptors.rows, descriptors.cols);
  const Eigen::MatrixXf x = (rows.transpose().colwise() - mean_).array().colwise() * inverse_scale_.array();
  Eigen::MatrixXf p = (w2_ * ((w1_ * x).colwise() + b1_).cwiseMax(0.0f)).colwise() + b2_;
  SoftmaxColumns(temperature_, &p);
  cv::Mat out(grid, CV_32FC(n));
  // p is column-major with one column per grid cell: exactly the interleaved layout of a continuous Mat.
  std::copy(p.data(), p.data() + p.size(), out.ptr<float>());
  return out;
}

cv::Mat BuiltinMaterialSegmenter::DoSegment(const cv::Mat& image) const {
  const cv::Mat grid = SegmentGrid(image);
  const int stride = features_.stride();
  // Resizing the grid to stride x its size puts cell centres on their pixels; then crop to the image.
  thread_local cv::Mat up;  // reused from frame to frame (MaterialFeatures keeps its maps likewise)
  cv::resize(grid, up, cv::Size(grid.cols * stride, grid.rows * stride), 0.0, 0.0, cv::INTER_LINEAR);
  return up(cv::Rect(0, 0, image.cols, image.rows)).clone();
}

void BuiltinMaterialSegmenter::Save(const std::string& path) const {
  YAML::Emitter out;
  out.SetFloatPrecision(9);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << kFormat;
  out << YAML::Key << "version" << YAML::Value << kVersion;
  out << YAML::Key << "labels" << YAML::Value << YAML::Flow << labels();
  out << YAML::Key << "window" << YAML::Value << features_.window();
  out << YAML::Key << "stride" << YAML::Value << features_.stride();
  out << YAML::Key << "temperature" << YAML::Value << temperature_;
  EmitMatrix(out, "feature_mean", mean_.transpose());
  EmitMatrix(out, "feature_inverse_scale", inverse_scale_.transpose());
  EmitMatrix(out, "w1", w1_);
  EmitMatrix(out, "b1", b1_.transpose());
  EmitMatrix(out, "w2", w2_);
  EmitMatrix(out, "b2", b2_.transpose());
  out << YAML::EndMap;
  WriteFileAtomically(path, std::string(out.c_str()) + "\n");
}

BuiltinMaterialSegmenter BuiltinMaterialSegmenter::Load(const std::string& path) {
  // Every problem is a file that Save() did not write (or that was edited): say how to make a good one.
  const std::string remedy = " Re-create it with `cairn friction-train --out " + path + "`.";
  try {
    const YamlReader yaml(path);
    const YAML::Node& root = yaml.root();
    if (yaml.String(root, "format", "the model", "") != kFormat) {
      yaml.Fail(root, std::string("the file is not a built-in material segmenter model (no 'format: ") + kFormat +
                          "').");
    }
    constexpr long long kMaxInt = std::numeric_limits<int>::max();
    const long long version = yaml.Integer(root, "version", "the model", -kMaxInt, kMaxInt);
    if (version != kVersion) {
      yaml.Fail(root["version"], "the file has version " + cairn::FormatShort(version) + "; this build reads version " +
                                     cairn::FormatShort(kVersion) + ".");
    }
    const std::vector<std::string> labels = yaml.Strings(yaml.Require(root, "labels", "the model"), "labels");
    if (labels.empty() || labels.size() > 255) {
      yaml.Fail(root["labels"], "the model has " + cairn::FormatShort(labels.size()) + " labels; a model has 1 to 255.");
    }
    const int window = static_cast<int>(yaml.Integer(root, "window", "the model", -kMaxInt, kMaxInt));
    const int stride = static_cast<int>(yaml.Integer(root, "stride", "the model", -kMaxInt, kMaxInt));
    const double temperature = yaml.Number(root, "temperature", "the model");
    if (!(temperature > 0.0)) {
      yaml.Fail(root["temperature"],
                "the file has temperature " + FormatShort(temperature) + "; it must be positive.");
    }
    const Eigen::Index d = MaterialFeatures::kDimension;
    const Eigen::Index n = static_cast<Eigen::Index>(labels.size());
    const YAML::Node b1_node = yaml.Require(root, "b1", "the model");
    const Eigen::Index h = yaml.Integer(b1_node, "cols", "'b1'", 0, kMaxInt, 0);
    if (h < 1 || h > kMaxHiddenUnits) {
      yaml.Fail(b1_node, "the model has a malformed 'b1': " + cairn::FormatShort(h) + " hidden units, outside [1, " +
                             cairn::FormatShort(kMaxHiddenUnits) + "].");
    }
    const Eigen::VectorXf mean = ReadMatrix(yaml, "feature_mean", 1, d).transpose();
    const Eigen::VectorXf inverse_scale = ReadMatrix(yaml, "feature_inverse_scale", 1, d).transpose();
    Eigen::MatrixXf w1 = ReadMatrix(yaml, "w1", h, d);
    const Eigen::VectorXf b1 = ReadMatrix(yaml, "b1", 1, h).transpose();
    Eigen::MatrixXf w2 = ReadMatrix(yaml, "w2", n, h);
    const Eigen::VectorXf b2 = ReadMatrix(yaml, "b2", 1, n).transpose();
    try {
      return BuiltinMaterialSegmenter(labels, MaterialFeatures(window, stride), mean, inverse_scale, std::move(w1),
                                      b1, std::move(w2), b2, temperature);
    } catch (const std::invalid_argument& error) {
      yaml.Fail(YAML::Node(), std::string("the model is inconsistent: ") + error.what());
    }
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(error.what() + remedy);
  }
}

}  // namespace cairn::perception
