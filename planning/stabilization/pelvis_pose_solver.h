#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/multibody/pose.h>

namespace cairn::planning {

/// The outcome of PelvisPoseSolver::Solve.
struct PelvisPoseResult {
  Eigen::VectorXd q;          ///< the posture
  double sole_error{0.0};     ///< largest sole position error, m
  double com_error{0.0};      ///< horizontal COM error, m
};

/// A walking posture from task-space targets, the way ZMP pattern generators build one: the waist (floating base)
/// at a given orientation and height, both soles at their poses, and the waist's horizontal position chosen so that
/// the horizontal COM is at its target; the upper body keeps the joint angles of the seed posture.
///
/// Each leg (the six joints between the waist and its sole) is solved by damped Gauss-Newton on its sole pose, to
/// convergence, from the seed's leg angles; the waist then moves by the remaining COM error and the legs are solved
/// again (the COM moves almost one to one with the waist, which carries most of the mass). Seeded with the
/// previous sample's posture, consecutive samples stay on one branch of the leg IK, so a smooth target path gives a
/// smooth motion. Unlike ComShiftSolver, which moves a given posture by a fixed number of steps on the whole-body
/// system, it keeps the waist exactly where it is asked to be: the motion's vertical and rotational parts are
/// chosen by the caller, not by the solver's weights.
class PelvisPoseSolver {
 public:
  /// Throws std::invalid_argument for a null model, a model without a floating base or without the sole frames,
  /// or a sole that is not on a six-joint leg below the floating base.
  PelvisPoseSolver(std::shared_ptr<const multibody::Model> model, const std::string& left_sole,
                   const std::string& right_sole);

  /// The posture: `seed` (size nq) gives the upper body's joints and the legs' starting angles; the waist turned
  /// to `R_base` at height `base_height` (world z of its origin), soles at `X_left` and `X_right` (world), and the
  /// horizontal COM at `com_target`. Throws std::invalid_argument for a wrong size or a non-finite input.
  PelvisPoseResult Solve(const Eigen::VectorXd& seed, const Eigen::Vector2d& com_target, const Eigen::Matrix3d& R_base,
                         double base_height, const multibody::Pose& X_left, const multibody::Pose& X_right) const;

 private:
  std::shared_ptr<const multibody::Model> model_;
  int frames_[2]{-1, -1};
  std::vector<int> leg_v_[2];  // velocity indices of each leg's joints
  std::vector<int> leg_q_[2];  // and their configuration indices
};

}  // namespace cairn::planning
