#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>

namespace cairn::planning {

/// The leg postures a LegTorqueTable covers. A posture is the position of the ankle centre relative to the hip
/// centre, e = ankle - hip, in the pelvis axes of the LEFT leg, written as a length l = |e| and two lean angles
/// pitch = atan2(e_x, -e_z) (ankle ahead of the hip > 0) and roll = atan2(e_y, -e_z) (ankle outward > 0).
struct LegTorqueGrid {
  double length_min{0.0}, length_max{0.0};  ///< m
  int length_count{0};
  double pitch_min{0.0}, pitch_max{0.0};  ///< rad
  int pitch_count{0};
  double roll_min{0.0}, roll_max{0.0};  ///< rad
  int roll_count{0};
};

/// Static joint torques of one stance leg as a function of its posture and of the load it carries, tabulated
/// once (thesis eq. 2.11: gravity torques at an inverse-kinematics posture, with the contact wrench).
///
/// At every grid posture the leg's six joints are solved by Newton inverse kinematics on the multibody model (the
/// sole flat and aligned with the pelvis, the rest of the robot at its zero configuration), and the torques are
/// written as tau = a + f (b0 + cop_x bx + cop_y by): a are the gravity torques of the leg's own links, and f is a
/// vertical ground force on the sole acting at the centre of pressure `cop` (offset from the sole centre, sole
/// axes), since tau = g(q) - J_c(q)^T F is linear in f and in f * cop. Queries interpolate a, b0, bx, by
/// trilinearly in (length, pitch, roll), so a lookup costs about a hundred flops and never runs the kinematics.
///
/// The right leg is the mirror image (y -> -y): query it with e_y and cop_y negated; the URDF mirrors the
/// right roll and yaw axes, so the torques come out identical.
class LegTorqueTable {
 public:
  /// An empty table (Contains() is false everywhere).
  LegTorqueTable() = default;

  /// Tabulates the left leg of `model` (a floating-base model at its zero configuration standing upright).
  /// `joint_names` are the leg's hip yaw, hip roll, hip pitch, knee, ankle pitch and ankle roll joints,
  /// `sole_frame` the frame at the sole centre. Throws std::runtime_error naming the posture if the inverse
  /// kinematics fails to converge at a grid node (a grid reaching beyond the leg), std::invalid_argument for
  /// unknown names or an empty grid.
  static LegTorqueTable Compute(const multibody::Model& model, const std::array<std::string, 6>& joint_names,
                                const std::string& sole_frame, const LegTorqueGrid& grid);

  /// The tabulated postures.
  const LegTorqueGrid& grid() const { return grid_; }

  /// True if the posture `ankle_from_hip` (left-leg pelvis axes) lies inside the tabulated box.
  bool Contains(const Eigen::Vector3d& ankle_from_hip) const;

  /// Joint torques (N m, leg-joint order) of the left leg at posture `ankle_from_hip` carrying the vertical
  /// ground force `load` (N) at `cop` (m, from the sole centre). Postures outside the box are clamped to it,
  /// so callers that need the exact posture check Contains() first (the swing leg uses the clamped value).
  void Torques(const Eigen::Vector3d& ankle_from_hip, double load, const Eigen::Vector2d& cop,
               Eigen::Ref<Eigen::Matrix<double, 6, 1>> tau) const;

  /// How far the posture's joint angles exceed the leg's URDF joint limits, rad (the largest excess over the
  /// six joints, negative when all are inside: minus the smallest margin), interpolated like the torques.
  /// Postures outside the box are clamped to it.
  double JointLimitExcess(const Eigen::Vector3d& ankle_from_hip) const;

  /// Joint angles of the inverse-kinematics solution at grid node (i_length, i_pitch, i_roll) (for tests).
  Eigen::Matrix<double, 6, 1> NodeAngles(int i_length, int i_pitch, int i_roll) const;

  /// Largest residual of the inverse kinematics over the grid (sole position error, m).
  double max_ik_residual() const { return max_ik_residual_; }

  /// Number of grid nodes whose posture violates one of the leg's URDF joint limits (such postures are
  /// infeasible through JointLimitExcess; the table still holds their torques for interpolation).
  int nodes_outside_joint_limits() const { return nodes_outside_joint_limits_; }

 private:
  // Per node: a, b0, bx, by (6 each), the 6 joint angles, the joint-limit excess.
  static constexpr int kStride = 31;
  // Trilinear interpolation of node values first .. first + count - 1 at posture e (clamped to the box).
  void Interpolate(const Eigen::Vector3d& e, int first, int count, double* values) const;
  int Index(int i, int j, int k) const { return (i * grid_.pitch_count + j) * grid_.roll_count + k; }

  LegTorqueGrid grid_;
  std::vector<double> nodes_;
  double max_ik_residual_{0.0};
  int nodes_outside_joint_limits_{0};
};

}  // namespace cairn::planning
