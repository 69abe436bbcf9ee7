#include "cairn/perception/stereo/stereo_source.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <yaml-cpp/yaml.h>

#include "cairn/perception/io/image_file.h"

namespace cairn::perception {

namespace {

std::string FolderOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

YAML::Node Require(const YAML::Node& node, const std::string& key, const std::string& where, const std::string& file) {
  const YAML::Node child = node[key];
  if (!child) throw std::runtime_error("StereoSource: '" + file + "': " + where + " has no '" + key + "' key");
  return child;
}

// Every frame holds two grey images in memory for the source's lifetime: bound them all, not only each one.
constexpr std::int64_t kMaxTotalPixels = std::int64_t{1} << 30;
constexpr int kMaxFrames = 100000;

cv::Mat ReadGrey(const std::string& path, const std::string& file, std::int64_t* pixel_budget) {
  try {
    cv::Mat image = ReadImageFile(path, cv::IMREAD_GRAYSCALE, std::min(kMaxImagePixels, *pixel_budget));
    *pixel_budget -= static_cast<std::int64_t>(image.total());
    return image;
  } catch (const std::exception& error) {
    const bool budget = *pixel_budget < kMaxImagePixels && dynamic_cast<const std::invalid_argument*>(&error);
    throw std::runtime_error("StereoSource: '" + file + "' names image '" + path + "', which cannot be read (" +
                             error.what() + ")" +
                             (budget ? "; a source holds at most " + std::to_string(kMaxTotalPixels) +
                                           " pixels in all its images"
                                     : std::string("; paths are relative to the YAML file's folder")));
  }
}

std::vector<double> FiniteNumbers(const YAML::Node& node, const std::string& key, const std::string& where,
                                  const std::string& file) {
  const auto values = node.as<std::vector<double>>();
  for (double v : values) {
    if (!std::isfinite(v)) {
      throw std::runtime_error("StereoSource: '" + file + "' line " + std::to_string(node.Mark().line + 1) + ": " +
                               where + " has a non-finite value in '" + key + "'");
    }
  }
  return values;
}

}  // namespace

StereoSource::StereoSource(const std::string& yaml_path, double period) : period_(period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("StereoSource: period " + std::to_string(period) +
                                " s must be positive and finite (e.g. 0.1 for 10 frames/s)");
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(yaml_path);
  } catch (const YAML::Exception& error) {
    throw std::runtime_error("StereoSource: cannot read '" + yaml_path + "': " + error.what());
  }
  try {
    const YAML::Node c = Require(root, "calibration", "the file", yaml_path);
    calibration_ = StereoCalibration{Require(c, "fx", "calibration", yaml_path).as<double>(),
                                     Require(c, "fy", "calibration", yaml_path).as<double>(),
                                     Require(c, "cx", "calibration", yaml_path).as<double>(),
                                     Require(c, "cy", "calibration", yaml_path).as<double>(),
                                     Require(c, "baseline", "calibration", yaml_path).as<double>()};
    const YAML::Node frames = Require(root, "frames", "the file", yaml_path);
    if (!frames.IsSequence() || frames.size() == 0) {
      throw std::runtime_error("StereoSource: '" + yaml_path + "': 'frames' must be a non-empty list of frames");
    }
    if (frames.size() > static_cast<std::size_t>(kMaxFrames)) {
      throw std::runtime_error("StereoSource: '" + yaml_path + "': 'frames' lists " + std::to_string(frames.size()) +
                               " frames, more than the " + std::to_string(kMaxFrames) + " a source may hold");
    }
    const std::string folder = FolderOf(yaml_path);
    std::int64_t pixel_budget = kMaxTotalPixels;
    for (std::size_t k = 0; k < frames.size(); ++k) {
      const YAML::Node f = frames[k];
      const std::string where = "frame " + std::to_string(k);
      left_.push_back(
          ReadGrey(folder + Require(f, "left", where, yaml_path).as<std::string>(), yaml_path, &pixel_budget));
      right_.push_back(
          ReadGrey(folder + Require(f, "right", where, yaml_path).as<std::string>(), yaml_path, &pixel_budget));
      if (left_.back().size() != right_.back().size()) {
        throw std::runtime_error("StereoSource: '" + yaml_path + "': " + where + " has left " +
                                 std::to_string(left_.back().cols) + "x" + std::to_string(left_.back().rows) +
                                 " but right " + std::to_string(right_.back().cols) + "x" +
                                 std::to_string(right_.back().rows) + "; give a rectified pair of equal size");
      }
      const auto t = FiniteNumbers(Require(f, "translation", where, yaml_path), "translation", where, yaml_path);
      const auto q = FiniteNumbers(Require(f, "rotation_wxyz", where, yaml_path), "rotation_wxyz", where, yaml_path);
      if (t.size() != 3 || q.size() != 4) {
        throw std::runtime_error("StereoSource: '" + yaml_path + "': " + where +
                                 " needs translation [x, y, z] and rotation_wxyz [w, x, y, z]");
      }
      const Eigen::Quaterniond rotation(q[0], q[1], q[2], q[3]);
      if (!(rotation.norm() > 1e-9)) {
        throw std::runtime_error("StereoSource: '" + yaml_path + "': " + where +
                                 " has a zero rotation quaternion; use [1, 0, 0, 0] for no rotation");
      }
      Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
      X_WC.linear() = rotation.normalized().toRotationMatrix();
      X_WC.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
      poses_.push_back(X_WC);
    }
  } catch (const YAML::Exception& error) {
    throw std::runtime_error("StereoSource: '" + yaml_path + "': " + error.what());
  }
  try {
    calibration_.Validate();
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error("StereoSource: '" + yaml_path + "': " + error.what());
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
