#pragma once

/// @file
/// ElevationMapper: point clouds into a grid map of elevation, semantics, slope and roughness, as a system.

#include <Eigen/Core>

#include "cairn/perception/terrain/elevation_fusion.h"
#include "cairn/perception/terrain/grid_map.h"
#include "cairn/perception/terrain/semantic_fusion.h"
#include "cairn/perception/terrain/slope_roughness_filter.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Every `period` seconds (from t = 0) fuses the point cloud on its input into the map it holds as state:
/// heights with ElevationFusion (eq. 1, range-dependent variance), class probabilities with SemanticFusion, then
/// slope and roughness (SlopeRoughnessFilter). With `follow_sensor` the map is robot-centred: it is first moved
/// to the sensor's x-y (GridMap::Move, an index shift; cells that leave are cleared).
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `points_W` | Eigen::Matrix3Xd | the cloud, world frame |
/// | input `sensor_W` | vector of size 3 | the sensor's position (ray lengths for the noise model) |
/// | input `probabilities` | Eigen::MatrixXd | SemanticFusion's classes (or input_labels) x points; 0 columns: none |
/// | output `map` | GridMap | layers elevation, elevation_variance, semantic_*, slope, roughness (the state) |
///
/// State: the GridMap and the fusion's scratch (abstract), updated by a periodic unrestricted update; the output
/// depends on the state only, so the system breaks algebraic loops.
class ElevationMapper final : public systems::LeafSystem {
 public:
  struct Options {
    ElevationFusion::Options elevation{};
    SemanticFusion::Options semantics{};
    SlopeRoughnessFilter::Options geometry{};
    bool follow_sensor{false};
  };

  /// `prototype` fixes the map's size, resolution and initial position (its layers are added to). Throws
  /// std::invalid_argument for a non-positive or non-finite period or bad options.
  ElevationMapper(const GridMap& prototype, double period, const Options& options);

  double period() const { return period_; }
  const systems::InputPort& get_points_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_sensor_input_port() const { return get_input_port(1); }
  const systems::InputPort& get_probabilities_input_port() const { return get_input_port(2); }
  const systems::OutputPort& get_map_output_port() const { return get_output_port(0); }

 private:
  struct Workspace {
    ElevationFusion elevation;
    SemanticFusion semantics;
  };
  void Update(const systems::Context& context, systems::State* next) const;

  double period_;
  Options options_;
  SlopeRoughnessFilter filter_;
  int map_state_{};
  int workspace_state_{};
};

}  // namespace cairn::perception
