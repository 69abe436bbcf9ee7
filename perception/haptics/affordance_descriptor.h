#pragma once

/// @file
/// The depth descriptor of an object facing the robot (seed 000, §3.3, eq. 6).

#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cairn::perception {

/// The object descriptor of §3.3: the object's points (sensor frame C: x right, y down, z along the optical axis)
/// are down-sampled so that no two lie within 1 cm, cut to the antenna's reach, and projected onto a histogram
/// of the xy-plane (columns along x, lines along y). Per line l four metrics are kept — the number of clusters
/// n_l (runs of occupied bins separated by empty ones), the size in bins of the largest cluster s_l, the point
/// density d_l (points in the line over bins in the line) and the most points in one cluster m_l — so a 16 x 14
/// histogram gives 4 x 14 = 56 values, stored line by line as (n, s, d, m) (eq. 6).
class AffordanceDescriptor {
 public:
  /// Most histogram lines or columns: 1024.
  static constexpr int kMaxBins = 1024;

  /// The paper's parameters (§4.1) as defaults.
  struct Options {
    /// No two kept points closer than this (m).
    double min_point_distance{0.01};
    /// The antenna's reach: points farther than reach_radius from reach_center_C are dropped (the antenna
    /// stretches to 1 m; its base is at reach_center_C in the sensor frame).
    Eigen::Vector3d reach_center_C{Eigen::Vector3d::Zero()};
    double reach_radius{1.0};
    /// Histogram bins along x (per line) and lines along y.
    int columns{16};
    int lines{14};
    /// The xy region the histogram covers. Unset (the default): the bounding box of the kept points, which is
    /// the paper's object bounding box; set it to compare objects in a fixed window instead. Points outside a
    /// set window are ignored.
    std::optional<Eigen::AlignedBox2d> window_C;
  };

  /// A descriptor of `lines` all-zero lines (an object with no points). Throws std::invalid_argument unless
  /// 1 <= lines <= kMaxBins.
  explicit AffordanceDescriptor(int lines = 14);

  /// A descriptor from its values, (n, s, d, m) per line. Throws std::invalid_argument when the size is not a
  /// positive multiple of 4 up to 4 kMaxBins, or a value is negative or not finite (naming its index).
  static AffordanceDescriptor FromValues(const Eigen::VectorXd& values);

  /// The four metrics of every line of a histogram of point counts (rows = lines, columns = bins along x).
  /// Throws std::invalid_argument for an empty or over-sized histogram or a negative count.
  static AffordanceDescriptor FromHistogram(const Eigen::MatrixXi& histogram);

  /// The histogram of §3.3 of an object's points (after down-sampling and the reach cut). Throws
  /// std::invalid_argument for invalid options (naming the value) or a cloud the reductions refuse.
  static Eigen::MatrixXi Histogram(const Eigen::Matrix3Xd& points_C, const Options& options);

  /// The descriptor of an object's points: FromHistogram(Histogram(points_C, options)).
  static AffordanceDescriptor Compute(const Eigen::Matrix3Xd& points_C, const Options& options);

  /// Throws std::invalid_argument naming the first invalid option.
  static void Validate(const Options& options);

  /// Number of histogram lines |L_H|.
  int lines() const { return static_cast<int>(values_.size() / 4); }
  /// All 4 |L_H| values, (n, s, d, m) per line.
  const Eigen::VectorXd& values() const { return values_; }
  /// Clusters in line l.
  double n(int l) const { return values_[4 * l]; }
  /// Bins of the largest cluster of line l.
  double s(int l) const { return values_[4 * l + 1]; }
  /// Points per bin of line l.
  double d(int l) const { return values_[4 * l + 2]; }
  /// Most points in one cluster of line l.
  double m(int l) const { return values_[4 * l + 3]; }

 private:
  Eigen::VectorXd values_;
};

}  // namespace cairn::perception
