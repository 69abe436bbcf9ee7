#pragma once

#include <memory>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "cairn/perception/friction/friction_point_cloud.h"
#include "cairn/perception/friction/friction_quantile_image.h"
#include "cairn/perception/friction/material_registry.h"
#include "cairn/perception/friction/material_segmenter.h"
#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Friction from vision with its uncertainty (thesis 3.5 and 5.2.1): segments the image into material
/// probabilities, turns them into the per-pixel friction mixture and its lower quantile Q_{1−η}, and, given
/// depth and the camera pose, annotates world points with both.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `image` | cv::Mat, 8-bit 1 or 3 channels | the camera image |
/// | input `depth` (with geometry) | cv::Mat CV_32F | depth along the optical axis [m]; 0 or NaN = none |
/// | input `X_WC` (with geometry) | Eigen::Isometry3d | pose of the camera in the world |
/// | output `material_probabilities` | cv::Mat CV_32FC(registry labels) | P(x_k = l_i), registry order |
/// | output `friction_quantile` | cv::Mat CV_32F | Q_{1−η} per pixel |
/// | output `friction_points` (with geometry) | FrictionPointCloud | world points with quantile and weights |
///
/// Parameters (per context): numeric η (`eta_parameter()`), abstract MaterialRegistry (`registry_parameter()`),
/// so a registry refined by contacts (MaterialRegistry::UpdateFromContact) can be swapped in while running.
/// The quantile tables are a cache entry that depends on those two only.
class FrictionEstimator final : public systems::LeafSystem {
 public:
  struct Options {
    double eta{0.95};
    QuantileMethod method{QuantileMethod::kExact};
    /// Step of QuantileMethod::kSearch.
    double search_step{0.02};
    /// Threads (0 = one per core; rule: cairn::ResolveThreadCount).
    int num_threads{0};
    /// Declares the depth and pose inputs and the point output, using these intrinsics.
    bool with_geometry{false};
    StereoCalibration camera;
  };

  /// Every segmenter label must be in the registry (registry labels the segmenter lacks get probability 0);
  /// throws std::invalid_argument naming a label that is not, and the registry's labels.
  FrictionEstimator(MaterialRegistry registry, std::shared_ptr<const MaterialSegmenter> segmenter,
                    const Options& options);

  int eta_parameter() const { return 0; }
  int registry_parameter() const { return 0; }
  const MaterialSegmenter& segmenter() const { return *segmenter_; }

  /// Sets η in `context`; throws std::invalid_argument unless η is in (0, 1).
  void SetEta(systems::Context* context, double eta) const;

 private:
  void CalcProbabilities(const systems::Context& context, cv::Mat* probabilities) const;
  void CalcQuantiles(const systems::Context& context, cv::Mat* quantiles) const;
  void CalcPoints(const systems::Context& context, FrictionPointCloud* cloud) const;

  std::shared_ptr<const MaterialSegmenter> segmenter_;
  Options options_;
  std::vector<int> registry_index_of_channel_;
  int num_labels_;
  int probabilities_cache_{-1};
  int tables_cache_{-1};
};

}  // namespace cairn::perception
