#pragma once

/// @file
/// Labelled colour renders of ground planes tiled with materials, for training and testing material segmenters.

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace cairn::perception {

/// A random scene family: a perspective camera above a ground plane tiled with polygonal (Voronoi) regions of
/// materials, with a few boxes standing on it and sky above the horizon. Render(seed) draws one scene of the
/// family (camera height, pitch, yaw and roll; regions and their MaterialTexture instances; boxes; lighting) and
/// ray-casts it. The result depends only on the options and the seed.
///
/// Kept separate from the grey-level SyntheticStereoRenderer on purpose: this renderer is about colour and labels,
/// not about geometry accuracy.
class MaterialScene {
 public:
  /// What to render.
  struct Options {
    /// Image size in pixels; > 0.
    int width{320};
    int height{240};
    /// Horizontal field of view in degrees, in (10, 150).
    double field_of_view_deg{70.0};
    /// The label space: the label image holds indices into this list. Defaults to MaterialTexture's labels
    /// (= MaterialRegistry::ThesisTable33()'s order).
    std::vector<std::string> labels;
    /// Materials of the ground regions; default: every label but "sky". Each must be in `labels`.
    std::vector<std::string> ground_labels;
    /// Materials of the boxes; default: wood, metal, marble, rock, ceramic, carpet, cloth, paper (those in
    /// `labels`). Each must be in `labels`.
    std::vector<std::string> box_labels;
    /// Number of ground regions; >= 1.
    int num_regions{10};
    /// Number of boxes; >= 0.
    int num_boxes{2};
    /// Standard deviation of the zero-mean Gaussian noise added to each colour channel (0..255 scale); >= 0.
    double noise_stddev{0.0};
    /// Supersampling: samples per pixel along each axis for colours (labels use the pixel centre); >= 1.
    int samples_per_axis{1};
  };

  /// One render.
  struct Rendering {
    /// CV_8UC3, BGR.
    cv::Mat image;
    /// CV_8UC1: index into Options::labels per pixel, kNoLabel where the material is not in the label space
    /// (the sky when "sky" is not a label).
    cv::Mat labels;
  };

  /// Label-image value of pixels without a label.
  static constexpr std::uint8_t kNoLabel = 255;

  /// Validates and completes the options; throws std::invalid_argument naming the bad option and its value.
  explicit MaterialScene(Options options);

  /// Renders scene number `seed` of the family.
  Rendering Render(std::uint32_t seed) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace cairn::perception
