#pragma once

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/plant/slip_event.h>
#include <cairn/multibody/plant/sole_state.h>
#include <cairn/multibody/plant/stance_phase.h>

namespace cairn::multibody {

/// What a HumanoidPlant has measured up to the current step (its abstract state).
struct HumanoidMeasurements {
  /// The two soles' contacts after the last step (left, right).
  std::vector<SoleState> soles = std::vector<SoleState>(2);
  /// Every slip so far.
  std::vector<SlipEvent> slips;
  /// Every stance so far with its RCOF.
  std::vector<StancePhase> stances;
  /// ZMP of the last step (NaN without foot contact).
  Eigen::Vector3d zmp = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  /// E_COM (J) so far.
  double com_energy = 0.0;
  /// E_ele (J) so far.
  double electrical_energy = 0.0;
  /// The Joule heat in E_ele (J) so far, Σ R I² dt: what the walking model's heat term predicts.
  double heat = 0.0;
  /// True once the robot fell.
  bool fallen = false;
  /// Why it fell.
  std::string fall_reason;
  /// The torques applied in the last step (size nv).
  Eigen::VectorXd torque;
};

}  // namespace cairn::multibody
