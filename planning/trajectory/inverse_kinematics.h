#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/multibody/pose.h>

namespace cairn::planning {

/// The outcome of an inverse-kinematics solve.
struct InverseKinematicsResult {
  /// True if the solver converged and every frame target is met within the tolerances given to Solve.
  bool success{false};
  /// The configuration (quaternion normalised), also on failure (the best point found).
  Eigen::VectorXd q;
  /// Largest position error over the frame targets, m.
  double max_position_error{0.0};
  /// Largest rotation error (axis-angle norm) over the frame targets, rad.
  double max_rotation_error{0.0};
  /// Solver iterations.
  int iterations{0};
  /// The solver's account of the ending, and the worst target when it is not met.
  std::string message;
};

/// Whole-body inverse kinematics as a weighted least-squares problem on the CHOLMOD Levenberg–Marquardt solver
/// (LeastSquaresSolver): frame pose targets (6-D, FramePoseError), an optional horizontal COM target, an
/// optional zero-roll target for a waist frame, and a posture regularisation towards a nominal configuration,
/// with the joint limits as bounds. The floating base's quaternion is read normalised and held at unit length by
/// a residual |quat|^2 - 1 (ConfigurationChart). Reusable: build it once, Solve from several guesses; Solve
/// never modifies the object.
class InverseKinematics {
 public:
  /// Throws std::invalid_argument for a null model.
  explicit InverseKinematics(std::shared_ptr<const multibody::Model> model);

  /// Asks frame `frame` to be at X_WF. Throws std::invalid_argument for an unknown frame or a weight that is not
  /// finite and positive.
  void AddFramePoseTarget(const std::string& frame, const multibody::Pose& X_WF, double weight = 100.0);

  /// Asks the horizontal projection of the COM to be at `xy`.
  void AddCenterOfMassTarget(const Eigen::Vector2d& xy, double weight = 10.0);

  /// Asks frame `frame` to have zero roll with respect to the world (WaistRollError).
  void AddZeroRollTarget(const std::string& frame, double weight = 10.0);

  /// Regularises the joint coordinates towards `nominal` (size nq; only the joint coordinates are used).
  void SetPosture(const Eigen::VectorXd& nominal, double weight = 0.1);

  /// Solves from `q_guess` (size nq, nonzero quaternion). Throws std::invalid_argument for a wrong size, a
  /// non-finite entry, max_iterations outside [1, 10000] or negative tolerances.
  InverseKinematicsResult Solve(const Eigen::VectorXd& q_guess, int max_iterations = 200,
                                double position_tolerance = 1e-4, double rotation_tolerance = 1e-3) const;

 private:
  struct FrameTarget {
    std::string frame;
    multibody::Pose X_WF;
    double weight;
  };
  std::shared_ptr<const multibody::Model> model_;
  std::vector<FrameTarget> frame_targets_;
  bool has_com_{false};
  Eigen::Vector2d com_xy_{Eigen::Vector2d::Zero()};
  double com_weight_{0.0};
  std::vector<std::pair<std::string, double>> roll_targets_;
  Eigen::VectorXd nominal_;
  double posture_weight_{0.0};
};

}  // namespace cairn::planning
