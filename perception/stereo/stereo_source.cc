#include "cairn/common/number_text.h"
#include "cairn/perception/stereo/stereo_source.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "cairn/common/internal/yaml_reader.h"
#include "cairn/perception/io/image_file.h"

namespace cairn::perception {

namespace {

using cairn::internal::YamlReader;

// Every frame holds two grey images in memory for the source's lifetime: bound them all, not only each one.
constexpr std::int64_t kMaxTotalPixels = std::int64_t{1} << 30;
constexpr int kMaxFrames = 100000;

cv::Mat ReadGrey(const YamlReader& yaml, const YAML::Node& frame, const std::string& key, const std::string& where,
                 std::int64_t* pixel_budget) {
  const std::string path = yaml.Resolve(yaml.String(frame, key, where));
  try {
    cv::Mat image = ReadImageFile(path, cv::IMREAD_GRAYSCALE, std::min(kMaxImagePixels, *pixel_budget));
    *pixel_budget -= static_cast<std::int64_t>(image.total());
    return image;
  } catch (const std::exception& error) {
    const bool budget = *pixel_budget < kMaxImagePixels && dynamic_cast<const std::invalid_argument*>(&error);
    yaml.Fail(frame[key], where + " names image '" + path + "', which cannot be read (" + error.what() + ")" +
                              (budget ? "; a source holds at most " + cairn::FormatShort(kMaxTotalPixels) +
                                            " pixels in all its images."
                                      : std::string("; paths are relative to the YAML file's folder.")));
  }
}

}  // namespace

StereoSource::StereoSource(const std::string& yaml_path, double period) : period_(period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("StereoSource: period " + cairn::FormatShort(period) +
                                " s must be positive and finite (e.g. 0.1 for 10 frames/s)");
  }
  const YamlReader yaml(yaml_path);
  const YAML::Node& root = yaml.root();
  yaml.CheckKeys(root, {"calibration", "frames"}, "the stereo source");
  const YAML::Node c = yaml.Require(root, "calibration", "the stereo source");
  yaml.CheckKeys(c, {"fx", "fy", "cx", "cy", "baseline"}, "calibration");
  calibration_ = StereoCalibration{yaml.Number(c, "fx", "calibration"), yaml.Number(c, "fy", "calibration"),
                                   yaml.Number(c, "cx", "calibration"), yaml.Number(c, "cy", "calibration"),
                                   yaml.Number(c, "baseline", "calibration")};
  try {
    calibration_.Validate();
  } catch (const std::invalid_argument& error) {
    yaml.Fail(c, error.what());
  }
  const YAML::Node frames = yaml.Require(root, "frames", "the stereo source");
  if (!frames.IsSequence() || frames.size() == 0) yaml.Fail(frames, "'frames' must be a non-empty list of frames.");
  if (frames.size() > static_cast<std::size_t>(kMaxFrames)) {
    yaml.Fail(frames, "'frames' lists " + cairn::FormatShort(frames.size()) + " frames, more than the " +
                          cairn::FormatShort(kMaxFrames) + " a source may hold.");
  }
  std::int64_t pixel_budget = kMaxTotalPixels;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const YAML::Node f = frames[k];
    const std::string where = "frame " + cairn::FormatShort(k);
    yaml.CheckKeys(f, {"left", "right", "translation", "rotation_wxyz"}, where);
    left_.push_back(ReadGrey(yaml, f, "left", where, &pixel_budget));
    right_.push_back(ReadGrey(yaml, f, "right", where, &pixel_budget));
    if (left_.back().size() != right_.back().size()) {
      yaml.Fail(f, where + " has left " + cairn::FormatShort(left_.back().cols) + "x" + cairn::FormatShort(left_.back().rows) +
                       " but right " + cairn::FormatShort(right_.back().cols) + "x" + cairn::FormatShort(right_.back().rows) +
                       "; give a rectified pair of equal size.");
    }
    const Eigen::VectorXd t = yaml.Numbers(yaml.Require(f, "translation", where), "translation", 3);
    const Eigen::VectorXd q = yaml.Numbers(yaml.Require(f, "rotation_wxyz", where), "rotation_wxyz", 4);
    const Eigen::Quaterniond rotation(q[0], q[1], q[2], q[3]);
    if (!(rotation.norm() > 1e-9)) {
      yaml.Fail(f["rotation_wxyz"], where + " has a zero rotation quaternion; use [1, 0, 0, 0] for no rotation.");
    }
    Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
    X_WC.linear() = rotation.normalized().toRotationMatrix();
    X_WC.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
    poses_.push_back(X_WC);
  }
  using systems::AbstractValue;
  using systems::Context;
  DeclareAbstractOutputPort(
      "left", systems::Value<cv::Mat>(cv::Mat()),
      [this](const Context& c, AbstractValue* v) {
        v->get_mutable_value<cv::Mat>() = left_[FrameIndexAt(c.get_time())];
      },
      {time_ticket()});
  DeclareAbstractOutputPort(
      "right", systems::Value<cv::Mat>(cv::Mat()),
      [this](const Context& c, AbstractValue* v) {
        v->get_mutable_value<cv::Mat>() = right_[FrameIndexAt(c.get_time())];
      },
      {time_ticket()});
  DeclareAbstractOutputPort(
      "X_WC", systems::Value<Eigen::Isometry3d>(Eigen::Isometry3d::Identity()),
      [this](const Context& c, AbstractValue* v) {
        v->get_mutable_value<Eigen::Isometry3d>() = poses_[FrameIndexAt(c.get_time())];
      },
      {time_ticket()});
}

int StereoSource::FrameIndexAt(double t) const {
  // A small slack so that t = k * period computed in floating point selects frame k, not k - 1.
  const double k = std::floor(t / period_ + 1e-9);
  return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(left_.size() - 1)));
}

}  // namespace cairn::perception
