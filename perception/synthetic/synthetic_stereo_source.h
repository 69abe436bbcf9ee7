#pragma once

/// @file
/// SyntheticStereoSource: renders a synthetic scene along a camera trajectory, one frame per period.

#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"
#include "cairn/perception/synthetic/synthetic_stereo_scene.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Frame k = floor(t / period) of the trajectory (the last one after the trajectory ends), rendered by a
/// SyntheticStereoRenderer (deterministic: the noise depends on the frame index only).
///
/// | port | type | meaning |
/// |---|---|---|
/// | output `left` | cv::Mat (CV_8UC1) | rectified left image |
/// | output `right` | cv::Mat (CV_8UC1) | rectified right image |
/// | output `depth` | cv::Mat (CV_32F) | ground-truth depth of the left image (metres, +inf for sky) |
/// | output `labels` | cv::Mat | ground-truth material labels of the left image |
/// | output `X_WC` | Eigen::Isometry3d | left camera pose in the world |
/// | output `left_colour` | cv::Mat (CV_8UC3) | left colour image (BGR); empty unless the scene has colour textures |
/// | output `right_colour` | cv::Mat (CV_8UC3) | right colour image (BGR); empty likewise |
///
/// No state: the frame is a cached function of time, rendered once per frame and shared by the outputs.
class SyntheticStereoSource final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for an empty trajectory or a non-positive period.
  SyntheticStereoSource(SyntheticStereoScene scene, SyntheticStereoRenderer renderer,
                        std::vector<Eigen::Isometry3d> trajectory, double period);

  /// The trajectory frame shown at time t.
  int FrameIndexAt(double t) const;
  int num_frames() const { return static_cast<int>(trajectory_.size()); }
  double period() const { return period_; }
  const SyntheticStereoRenderer& renderer() const { return renderer_; }

  const systems::OutputPort& get_left_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_right_output_port() const { return get_output_port(1); }
  const systems::OutputPort& get_depth_output_port() const { return get_output_port(2); }
  const systems::OutputPort& get_labels_output_port() const { return get_output_port(3); }
  const systems::OutputPort& get_pose_output_port() const { return get_output_port(4); }
  const systems::OutputPort& get_left_colour_output_port() const { return get_output_port(5); }
  const systems::OutputPort& get_right_colour_output_port() const { return get_output_port(6); }

 private:
  SyntheticStereoScene scene_;
  SyntheticStereoRenderer renderer_;
  std::vector<Eigen::Isometry3d> trajectory_;
  double period_;
  int frame_cache_{};
};

}  // namespace cairn::perception
