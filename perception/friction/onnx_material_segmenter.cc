#include "cairn/perception/friction/onnx_material_segmenter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <utility>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include "cairn/common/internal/yaml_reader.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/io/image_file.h"

namespace cairn::perception {

struct OnnxMaterialSegmenter::Network {
  cv::dnn::Net net;
  std::mutex mutex;
};

namespace {

using cairn::internal::YamlReader;

// Runs the network on `bgr` (8-bit, 3 channels) and returns the raw 1 x C x H x W output.
cv::Mat Forward(cv::dnn::Net* net, std::mutex* mutex, const OnnxMaterialSegmenter::Preprocessing& pre,
                const cv::Mat& bgr) {
  const cv::Mat blob = cv::dnn::blobFromImage(bgr, pre.scale, cv::Size(pre.width, pre.height),
                                              cv::Scalar(pre.mean[0], pre.mean[1], pre.mean[2]), pre.rgb, false,
                                              CV_32F);
  std::lock_guard<std::mutex> lock(*mutex);
  net->setInput(blob);
  return net->forward().clone();
}

}  // namespace

OnnxMaterialSegmenter::OnnxMaterialSegmenter(std::vector<std::string> labels, Preprocessing preprocessing,
                                             std::string model_path, std::shared_ptr<Network> network)
    : MaterialSegmenter(std::move(labels)),
      preprocessing_(std::move(preprocessing)),
      model_path_(std::move(model_path)),
      network_(std::move(network)) {}

OnnxMaterialSegmenter OnnxMaterialSegmenter::Load(const std::string& yaml_path) {
  const YamlReader yaml(yaml_path);
  const YAML::Node& root = yaml.root();
  const std::string where = "the model description";
  yaml.CheckKeys(root, {"model", "labels", "input", "training"}, where);
  if (!YamlReader::Has(root, "model")) yaml.Fail(root, "missing key 'model': name the .onnx file.");
  const std::string model = yaml.String(root, "model", where);
  const std::vector<std::string> labels = yaml.Strings(yaml.Require(root, "labels", where), "labels");
  if (labels.empty()) yaml.Fail(root["labels"], "key 'labels' must be a non-empty list, one label per output channel.");
  const YAML::Node input = yaml.Require(root, "input", where);
  yaml.CheckKeys(input, {"width", "height", "channel_order", "mean", "scale"}, "'input'");
  Preprocessing pre;
  constexpr long long kMaxInt = std::numeric_limits<int>::max();
  pre.width = static_cast<int>(yaml.AsInteger(yaml.Require(input, "width", "'input'"), "input.width", 1, kMaxInt));
  pre.height = static_cast<int>(yaml.AsInteger(yaml.Require(input, "height", "'input'"), "input.height", 1, kMaxInt));
  if (static_cast<std::int64_t>(pre.width) * pre.height > kMaxImagePixels) {
    yaml.Fail(input, "keys 'input.width' and 'input.height' give " + cairn::FormatShort(pre.width) + "x" +
                         cairn::FormatShort(pre.height) + " pixels, more than the " + cairn::FormatShort(kMaxImagePixels) +
                         " an input may have.");
  }
  const std::string order = yaml.String(input, "channel_order", "'input'", "");
  if (order != "rgb" && order != "bgr") {
    yaml.Fail(YamlReader::Has(input, "channel_order") ? input["channel_order"] : input,
              "key 'input.channel_order' must be 'rgb' or 'bgr'; got '" + order + "'.");
  }
  pre.rgb = order == "rgb";
  if (YamlReader::Has(input, "mean")) pre.mean = yaml.Numbers(input["mean"], "input.mean", 3);
  pre.scale = YamlReader::Has(input, "scale") ? yaml.AsNumber(input["scale"], "input.scale") : 1.0;
  if (!(pre.scale > 0.0)) {
    yaml.Fail(input["scale"], "key 'input.scale' must be positive; got " + FormatShort(pre.scale) + ".");
  }
  const std::string model_path = yaml.Resolve(model);
  if (!std::ifstream(model_path).good()) {
    throw std::runtime_error("OnnxMaterialSegmenter: the model file '" + model_path + "' named by '" + yaml_path +
                             "' cannot be opened; check the 'model' key (relative paths start at the YAML's "
                             "folder).");
  }
  auto network = std::make_shared<Network>();
  try {
    network->net = cv::dnn::readNetFromONNX(model_path);
  } catch (const cv::Exception&) {
    // OpenCV's text spans lines and names its own sources; the user needs the file and what to check.
    throw std::runtime_error("OnnxMaterialSegmenter: the model file '" + model_path + "' named by '" + yaml_path +
                             "' is not an ONNX network OpenCV can read (corrupt, truncated or using unsupported "
                             "operators).");
  }
  if (network->net.empty()) {
    throw std::runtime_error("OnnxMaterialSegmenter: the ONNX model '" + model_path + "' has no layers.");
  }
  network->net.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  network->net.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  // One forward pass on a blank image tells the output's channel count.
  cv::Mat output;
  try {
    output = Forward(&network->net, &network->mutex, pre, cv::Mat(pre.height, pre.width, CV_8UC3, cv::Scalar::all(128)));
  } catch (const cv::Exception&) {
    throw std::runtime_error("OnnxMaterialSegmenter: the model '" + model_path + "' fails on a " +
                             cairn::FormatShort(pre.width) + "x" + cairn::FormatShort(pre.height) +
                             " input; check input.width/height in '" + yaml_path + "' against the network's input.");
  }
  if (output.dims != 4 || output.size[0] != 1) {
    throw std::invalid_argument("OnnxMaterialSegmenter: the model '" + model_path +
                                "' must output a 1 x C x H x W tensor of per-label scores; its output has " +
                                cairn::FormatShort(output.dims) + " dimensions.");
  }
  if (output.size[1] != static_cast<int>(labels.size())) {
    throw std::invalid_argument("OnnxMaterialSegmenter: the label map in '" + yaml_path + "' has " +
                                cairn::FormatShort(labels.size()) + " labels but the model '" + model_path +
                                "' outputs " + cairn::FormatShort(output.size[1]) +
                                " channels; list exactly one label per output channel, in channel order.");
  }
  return OnnxMaterialSegmenter(std::move(labels), pre, model_path, std::move(network));
}

cv::Mat OnnxMaterialSegmenter::SegmentNative(const cv::Mat& image) const {
  if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3)) {
    throw std::invalid_argument("OnnxMaterialSegmenter: needs an 8-bit image with 1 or 3 channels; got depth " +
                                cairn::FormatShort(image.depth()) + " with " + cairn::FormatShort(image.channels()) +
                                " channel(s).");
  }
  cv::Mat bgr;
  if (image.channels() == 1) {
    cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
  } else {
    bgr = image;
  }
  cv::Mat output;
  try {
    output = Forward(&network_->net, &network_->mutex, preprocessing_, bgr);
  } catch (const cv::Exception&) {
    throw std::runtime_error("OnnxMaterialSegmenter: the model '" + model_path_ + "' failed on a " +
                             cairn::FormatShort(image.cols) + "x" + cairn::FormatShort(image.rows) + " image.");
  }
  const int n = output.size[1];
  const int rows = output.size[2];
  const int cols = output.size[3];
  const float* scores = output.ptr<float>();
  const std::size_t plane = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  cv::Mat probabilities(rows, cols, CV_32FC(n));
  for (int r = 0; r < rows; ++r) {
    float* out = probabilities.ptr<float>(r);
    for (int c = 0; c < cols; ++c) {
      const std::size_t at = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
      float top = scores[at];
      for (int k = 1; k < n; ++k) top = std::max(top, scores[static_cast<std::size_t>(k) * plane + at]);
      float sum = 0.0f;
      float* p = out + c * n;
      for (int k = 0; k < n; ++k) {
        p[k] = std::exp(scores[static_cast<std::size_t>(k) * plane + at] - top);
        sum += p[k];
      }
      for (int k = 0; k < n; ++k) p[k] /= sum;
    }
  }
  return probabilities;
}

cv::Mat OnnxMaterialSegmenter::DoSegment(const cv::Mat& image) const {
  const cv::Mat native = SegmentNative(image);
  cv::Mat resized;
  cv::resize(native, resized, image.size(), 0.0, 0.0, cv::INTER_LINEAR);
  return resized;
}

}  // namespace cairn::perception
