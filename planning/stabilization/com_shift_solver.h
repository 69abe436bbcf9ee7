#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/model.h>

namespace cairn::planning {

/// The outcome of a COM shift.
struct ComShiftResult {
  Eigen::VectorXd q;              ///< the shifted configuration
  double sole_error{0.0};         ///< largest sole position error after the steps, m
  double com_error{0.0};          ///< horizontal COM error after the steps, m
};

/// Moves the horizontal COM of a posture by leg inverse kinematics, as the thesis' compensation does with
/// WABIAN-2's analytic leg IK (2.5.1c): both soles stay where they are in the reference posture, the waist
/// (floating base) keeps its orientation (so its roll stays what the optimiser made it, zero), the upper body keeps
/// its joint angles relative to the waist, and the waist's position and the twelve leg joints move. Each step is a
/// weighted minimum-norm Gauss-Newton step on the 17 x 18 system (sole poses 2 x 6, COM x y, base orientation 3;
/// base twist 6 and the leg joints' 12 velocities), dv = S A^T (A S^2 A^T + 1e-10 I)^-1 r with S scaling the
/// waist's vertical motion by 0.1 (it costs 100 times a joint's motion, so the waist moves mostly sideways as the
/// thesis' analytic IK has it, and rises or sinks only where a leg would otherwise not reach). A fixed number of steps from
/// the reference posture makes the result a smooth function of the reference and the target, so a trajectory
/// shifted sample by sample stays smooth enough to difference twice (an iterative solver stopped at a tolerance
/// would not). Joint limits are not imposed (the caller reports whether they hold); no clamping.
class ComShiftSolver {
 public:
  /// Throws std::invalid_argument for a null model, a model without a floating base or without the frames, or
  /// a sole that is not below the floating base.
  ComShiftSolver(std::shared_ptr<const multibody::Model> model, const std::string& left_sole,
                 const std::string& right_sole);

  /// `q_reference` with its horizontal COM moved to `com_target`, soles and base orientation held, after
  /// `steps` Gauss-Newton steps (in [1, 50]). Throws std::invalid_argument for a wrong size or a non-finite entry.
  ComShiftResult Solve(const Eigen::VectorXd& q_reference, const Eigen::Vector2d& com_target, int steps = 8) const;

  /// The same with the base turned to `R_base` (world) instead of keeping the reference's orientation.
  ComShiftResult Solve(const Eigen::VectorXd& q_reference, const Eigen::Vector2d& com_target,
                       const Eigen::Matrix3d& R_base, int steps = 8) const;

 private:
  std::shared_ptr<const multibody::Model> model_;
  int left_{-1}, right_{-1}, base_body_{-1}, base_v_{-1};
  std::vector<int> columns_;  // base twist then the leg joints' velocity indices
};

}  // namespace cairn::planning
