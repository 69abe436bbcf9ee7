#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/plant/bullet_plant.h>
#include <cairn/multibody/plant/contact_monitor_options.h>
#include <cairn/multibody/plant/joint_drive.h>
#include <cairn/multibody/plant/slip_event.h>
#include <cairn/multibody/plant/sole_state.h>
#include <cairn/multibody/plant/stance_phase.h>

namespace cairn::multibody {

/// What a walking experiment measures, updated after every plant step: per sole the contact wrench, centre of
/// pressure, loaded flag and slips; each stance's RCOF (thesis eq. 2.2); the ZMP; a fall; E_COM (eq. 2.1,
/// ∫|v_COM · F| dt with F the total external force) and E_ele (eq. 2.6, Σ_i ∫|τ_i ω_i| + R_i I_i² dt with
/// I = τ / (r K_τ), over the joints that have drive data) with its Joule-heat share Σ_i ∫ R_i I_i² dt (the motor heat
/// the walking model predicts, eq. 2.6's second term).
class ContactMonitor {
 public:
  /// Monitors `plant`'s robot: `sole_bodies` names the left and right sole bodies (or links), `base_body` the
  /// pelvis; `drives` has one entry per velocity coordinate (or is empty: no electrical energy). Throws
  /// std::invalid_argument for unknown bodies, a wrong drive count or thresholds out of range (the load, slip and fall
  /// thresholds finite and > 0; stance_gap and touchdown_time in [0, 1] s; force_filter_time finite and >= 0).
  ContactMonitor(const BulletPlant& plant, const std::vector<std::string>& sole_bodies, const std::string& base_body,
                 std::vector<JointDrive> drives = {}, const ContactMonitorOptions& options = ContactMonitorOptions());

  /// Reads the plant's state and contacts after a step that applied `tau` (size nv) and updates every measurement.
  void Update(const BulletPlant& plant, const Eigen::Ref<const Eigen::VectorXd>& tau);

  /// The soles' contacts after the last update.
  const std::vector<SoleState>& soles() const { return soles_; }
  /// Every slip event so far, in time order.
  const std::vector<SlipEvent>& slips() const { return slips_; }
  /// Every stance so far (the last ones may be unfinished), in start order.
  const std::vector<StancePhase>& stances() const { return stances_; }
  /// The zero-moment point: the normal-force-weighted mean of all foot contact points (exact for coplanar
  /// contacts); NaN without foot contact.
  const Eigen::Vector3d& zmp() const { return zmp_; }
  /// True once a fall was detected (it stays true).
  bool fallen() const { return fallen_; }
  /// Why the robot fell ("" if it did not), e.g. "base 0.31 m above the lower sole, below 0.5 m".
  const std::string& fall_reason() const { return fall_reason_; }
  /// Time of the fall (s; NaN if none).
  double fall_time() const { return fall_time_; }
  /// E_COM so far (J).
  double com_energy() const { return com_energy_; }
  /// E_ele so far (J).
  double electrical_energy() const { return electrical_energy_; }
  /// The Joule heat in E_ele so far, Σ_i ∫ R_i I_i² dt (J).
  double heat() const { return heat_; }
  /// Base height above the lower sole frame (m) after the last update.
  double base_height() const { return base_height_; }

 private:
  void Fall(double time, const std::string& reason);

  ContactMonitorOptions options_;
  std::vector<JointDrive> drives_;
  Model model_;
  Data data_;
  std::vector<int> sole_bodies_;
  std::vector<int> foot_bodies_;  // the plant's merged bodies of the soles
  int base_body_ = 1;
  std::vector<SoleState> soles_;
  std::vector<bool> has_previous_;
  std::vector<double> slide_distance_;
  std::vector<bool> slide_reported_;
  std::vector<int> open_stance_;  // index into stances_, -1 once unloaded for longer than stance_gap
  std::vector<SlipEvent> slips_;
  std::vector<StancePhase> stances_;
  Eigen::Vector3d net_force_;  // low-passed sum of the soles' contact forces
  Eigen::Vector3d zmp_;
  bool fallen_ = false;
  std::string fall_reason_;
  double fall_time_;
  double com_energy_ = 0.0;
  double electrical_energy_ = 0.0;
  double heat_ = 0.0;
  double base_height_ = 0.0;
};

}  // namespace cairn::multibody
