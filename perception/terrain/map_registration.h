#pragma once

/// @file
/// MapRegistration: local layers fused into a fixed global map (seed 001 §4.2).

#include <string>
#include <vector>

#include "cairn/perception/terrain/grid_map.h"

namespace cairn::perception {

/// Registers layers of a robot-centred local map into a global map fixed in the world, cell by cell with the
/// one-dimensional Kalman update of eq. (1): each global cell whose centre falls in a known local cell fuses that
/// cell's value; the global estimate's variance lives in "<global layer>_variance". The measurement variance is
/// either a constant per layer (seed 001: semantics and collapsibility have constant variances, probing the
/// smaller) or read per cell from a local variance layer (elevation and geometry-based traversability, from the
/// sensor model). Maps may differ in size, resolution and position; global rows run in parallel and nothing is
/// allocated.
class MapRegistration {
 public:
  /// One layer to register.
  struct Layer {
    std::string local_layer;
    std::string global_layer;
    /// Constant measurement variance (used when variance_layer is empty).
    double variance{0.01};
    /// Local layer holding each cell's measurement variance, or empty.
    std::string variance_layer;
  };

  /// Throws std::invalid_argument for an empty layer list, an empty name, or a non-positive constant variance
  /// where no variance layer is given.
  MapRegistration(std::vector<Layer> layers, int num_threads = 0);

  const std::vector<Layer>& layers() const { return layers_; }

  /// Adds the global layers and their variance layers to `global` where missing.
  void AddLayers(GridMap* global) const;

  /// Fuses `local` into `global` (which needs AddLayers' layers). Throws std::invalid_argument naming a local
  /// layer `local` lacks. Cells with a non-positive or non-finite local variance are skipped.
  void Register(const GridMap& local, GridMap* global) const;

 private:
  std::vector<Layer> layers_;
  std::vector<std::string> variance_names_;  // "<global>_variance", named once
  int threads_{1};
};

}  // namespace cairn::perception
