#pragma once

/// @file
/// SlopeRoughnessFilter: the geometric layers of seed 001 §4.1 (slope and roughness) from an elevation layer.

#include "cairn/perception/terrain/grid_map.h"

namespace cairn::perception {

/// For every cell, fits the plane z = a x + b y + c by least squares to the known heights of the square window
/// of (2 r + 1)² cells around it and writes
///   - "slope": the angle (rad) between the plane's normal and world z, atan(sqrt(a² + b²));
///   - "roughness": the standard deviation (m) of the window's heights about that plane. (About the plane rather
///     than about their mean, so that a tilted but smooth plane has zero roughness: slope already accounts for
///     the tilt.)
/// A cell whose own height is unknown, or whose window has fewer than min_valid_cells known heights or only
/// collinear ones, gets NaN in both layers. Rows run in parallel; nothing is allocated per call.
class SlopeRoughnessFilter {
 public:
  struct Options {
    /// Half-width r of the window in cells (r = 2 at 5 cm is a 25 cm window, about a foot's size).
    int window_radius{2};
    /// Fewest known heights for a fit (at least 3).
    int min_valid_cells{5};
    /// Threads (0 = one per core).
    int num_threads{0};
  };

  /// Most cells of window half-width (a 101 x 101 window).
  static constexpr int kMaxWindowRadius = 50;

  /// Throws std::invalid_argument for a window radius outside [1, kMaxWindowRadius], min_valid_cells outside
  /// [3, window cells], or a bad thread count.
  explicit SlopeRoughnessFilter(const Options& options);
  SlopeRoughnessFilter() : SlopeRoughnessFilter(Options{}) {}

  const Options& options() const { return options_; }

  /// Reads layer `elevation_layer` of `map` and writes its "slope" and "roughness" layers (added if missing).
  void Compute(GridMap* map, const std::string& elevation_layer = "elevation") const;

 private:
  Options options_;
  int threads_{1};
};

}  // namespace cairn::perception
