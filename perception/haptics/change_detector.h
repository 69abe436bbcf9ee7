#pragma once

/// @file
/// ChangeDetector: the §3.7 gist change detection as a block-diagram system.

#include <Eigen/Core>

#include "cairn/perception/haptics/gist_change_detector.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Every `period` seconds compares the gist of the cloud on its input with the reference gist taken at its first
/// update (the moment the robot starts to traverse an object), and holds the result as state.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `points_C` | Eigen::Matrix3Xd | the depth sensor's points |
/// | output `change` | vector (3) | [gist, |gist - reference|, changed (1) or not (0)] (state) |
///
/// State: the detector with its reference (abstract) and the last result (discrete, zeros before the first
/// comparison). The output depends on the state only.
class ChangeDetector final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for invalid options or a non-positive period.
  ChangeDetector(const GistChangeDetector::Options& options, double period);

  double period() const { return period_; }

  const systems::InputPort& get_points_input_port() const { return get_input_port(0); }
  const systems::OutputPort& get_change_output_port() const { return get_output_port(0); }

 private:
  void Update(const systems::Context& context, systems::State* next) const;

  double period_;
  int detector_state_{};
  int result_state_{};
};

}  // namespace cairn::perception
