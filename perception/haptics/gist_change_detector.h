#pragma once

/// @file
/// Scene-change detection while traversing an object, by the density gist (seed 000, §3.7).

#include <Eigen/Core>

namespace cairn::perception {

/// The gist of a scene is the ratio of the number of occupied cells of a regular grid (the reduced cloud) to the
/// number of points (§3.7): the inverse of the average points per voxel. A reference gist is taken before the
/// robot starts to traverse an object; at each progression step the current gist is compared with it, and the
/// scene has changed when |gist - reference| > ω.
class GistChangeDetector {
 public:
  /// The paper's parameters (§4.1) as defaults.
  struct Options {
    /// Grid cell side (m); the paper's "voxel size of 0.01".
    double voxel{0.01};
    /// Change threshold ω.
    double omega{0.03};
  };

  /// One comparison with the reference.
  struct Result {
    double gist{0.0};
    /// |gist - reference|.
    double difference{0.0};
    bool changed{false};
  };

  /// Throws std::invalid_argument for a non-positive voxel or a negative or non-finite ω.
  explicit GistChangeDetector(const Options& options);
  /// The paper's parameters.
  GistChangeDetector();

  /// Occupied voxels over points; an empty cloud (nothing in view) has gist 0. Throws std::invalid_argument for
  /// a cloud the voxel grid refuses.
  static double Gist(const Eigen::Matrix3Xd& points, double voxel);

  /// Takes the reference gist of the scene before traversing.
  void SetReference(const Eigen::Matrix3Xd& points);
  /// Sets the reference gist directly (e.g. one restored from a diagram's state). Throws std::invalid_argument
  /// for a value outside [0, 1].
  void SetReferenceGist(double gist);
  /// Compares the current scene with the reference. Throws std::logic_error when no reference was taken.
  Result Compare(const Eigen::Matrix3Xd& points) const;

  bool has_reference() const { return has_reference_; }
  double reference_gist() const { return reference_; }
  const Options& options() const { return options_; }

 private:
  Options options_;
  bool has_reference_{false};
  double reference_{0.0};
};

}  // namespace cairn::perception
