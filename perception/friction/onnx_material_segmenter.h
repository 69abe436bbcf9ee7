#pragma once

/// @file
/// A material segmenter running a segmentation network (ONNX) through OpenCV's dnn module.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "cairn/perception/friction/material_segmenter.h"

namespace cairn::perception {

/// Runs a fully-convolutional network whose output has one channel of logits (or scores) per label: the image
/// is resized to the network's input size, converted to its channel order, shifted and scaled, the output is
/// softmax-normalised over channels and bilinearly resized to the image.
///
/// The network is described by a YAML file beside it:
/// @code{.yaml}
/// model: tiny_material_net.onnx      # relative to this file's folder
/// labels: [asphalt, grass, rock, ...] # one per output channel, in channel order
/// input:
///   width: 160
///   height: 120
///   channel_order: rgb               # rgb or bgr: the order the network expects
///   mean: [0, 0, 0]                  # subtracted per channel (in that order), 0..255 units
///   scale: 0.00392156862745098       # multiplies after the subtraction
/// @endcode
/// Segment() is thread-safe (calls into the network are serialised).
class OnnxMaterialSegmenter final : public MaterialSegmenter {
 public:
  /// The network's input convention.
  struct Preprocessing {
    int width{0};
    int height{0};
    bool rgb{true};
    Eigen::Vector3d mean{Eigen::Vector3d::Zero()};
    double scale{1.0};
  };

  /// Reads the YAML description and the model, and runs the network once to check that its output has one
  /// channel per label. Throws std::invalid_argument for an unreadable or malformed YAML file, a bad key (naming
  /// the file, the line, the key and the expected form) or a label map that disagrees with the model's output
  /// channels, and std::runtime_error for a model file that cannot be opened or run.
  static OnnxMaterialSegmenter Load(const std::string& yaml_path);

  const Preprocessing& preprocessing() const { return preprocessing_; }
  /// Absolute or YAML-relative-resolved path of the model file.
  const std::string& model_path() const { return model_path_; }

  /// Softmax probabilities at the network's output resolution: CV_32FC(num_labels()).
  cv::Mat SegmentNative(const cv::Mat& image) const;

 protected:
  cv::Mat DoSegment(const cv::Mat& image) const override;

 private:
  struct Network;
  OnnxMaterialSegmenter(std::vector<std::string> labels, Preprocessing preprocessing, std::string model_path,
                        std::shared_ptr<Network> network);

  Preprocessing preprocessing_;
  std::string model_path_;
  // cv::dnn stays out of this header; shared so that copies share one network (and its lock).
  std::shared_ptr<Network> network_;
};

}  // namespace cairn::perception
