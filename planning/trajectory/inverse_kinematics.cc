#include <cairn/planning/trajectory/inverse_kinematics.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/optimization/mathematical_program.h>
#include <cairn/optimization/solvers/least_squares_solver.h>
#include <cairn/planning/trajectory/center_of_mass_projection.h>
#include <cairn/planning/trajectory/configuration_chart.h>
#include <cairn/planning/trajectory/frame_pose_error.h>
#include <cairn/planning/trajectory/posture_residual.h>
#include <cairn/planning/trajectory/quaternion_norm_error.h>
#include <cairn/planning/trajectory/scaled_evaluator.h>
#include <cairn/planning/trajectory/waist_roll_error.h>

namespace cairn::planning {

namespace {
// Proximal rounds of Solve (each a full Levenberg-Marquardt solve).
constexpr int kRounds = 8;

void CheckWeight(double weight, const std::string& what) {
  if (!(weight > 0.0) || !std::isfinite(weight)) {
    throw std::invalid_argument("InverseKinematics: the weight of " + what + " is " + FormatShort(weight) +
                                "; give a finite positive weight");
  }
}
}  // namespace

InverseKinematics::InverseKinematics(std::shared_ptr<const multibody::Model> model) : model_(std::move(model)) {
  if (model_ == nullptr) throw std::invalid_argument("InverseKinematics: the robot model is null");
}

void InverseKinematics::AddFramePoseTarget(const std::string& frame, const multibody::Pose& X_WF, double weight) {
  model_->GetFrameIndex(frame);
  CheckWeight(weight, "the pose target of '" + frame + "'");
  frame_targets_.push_back({frame, X_WF, weight});
}

void InverseKinematics::AddCenterOfMassTarget(const Eigen::Vector2d& xy, double weight) {
  CheckWeight(weight, "the COM target");
  if (!xy.allFinite()) throw std::invalid_argument("InverseKinematics: the COM target is not finite");
  has_com_ = true;
  com_xy_ = xy;
  com_weight_ = weight;
}

void InverseKinematics::AddZeroRollTarget(const std::string& frame, double weight) {
  model_->GetFrameIndex(frame);
  CheckWeight(weight, "the roll target of '" + frame + "'");
  roll_targets_.emplace_back(frame, weight);
}

void InverseKinematics::SetPosture(const Eigen::VectorXd& nominal, double weight) {
  if (nominal.size() != model_->nq() || !nominal.allFinite()) {
    throw std::invalid_argument("InverseKinematics: the nominal posture has " +
                                FormatShort(static_cast<int>(nominal.size())) + " entries; give nq = " +
                                FormatShort(model_->nq()) + " finite values");
  }
  CheckWeight(weight, "the posture");
  nominal_ = nominal;
  posture_weight_ = weight;
}

InverseKinematicsResult InverseKinematics::Solve(const Eigen::VectorXd& q_guess, int max_iterations,
                                                 double position_tolerance, double rotation_tolerance) const {
  const multibody::Model& model = *model_;
  const ConfigurationChart chart(model);
  if (q_guess.size() != model.nq() || !q_guess.allFinite()) {
    throw std::invalid_argument("InverseKinematics::Solve: the guess has " + FormatShort(static_cast<int>(q_guess.size())) +
                                " entries; give nq = " + FormatShort(model.nq()) + " finite values");
  }
  if (max_iterations < 1 || max_iterations > 10000) {
    throw std::invalid_argument("InverseKinematics::Solve: max_iterations is " + FormatShort(max_iterations) +
                                "; it lies in [1, 10000]");
  }
  if (!(position_tolerance >= 0.0) || !(rotation_tolerance >= 0.0)) {
    throw std::invalid_argument("InverseKinematics::Solve: tolerances must be >= 0");
  }
  const Eigen::VectorXd start = chart.Normalized(q_guess);

  optimization::MathematicalProgram prog;
  const optimization::DecisionVariables q = prog.NewContinuousVariables(model.nq(), "q");
  std::vector<std::shared_ptr<FramePoseError>> pose_errors;
  for (const FrameTarget& target : frame_targets_) {
    auto error = std::make_shared<FramePoseError>(model_, target.frame, target.X_WF);
    pose_errors.push_back(error);
    prog.AddLeastSquaresCost(std::make_shared<ScaledEvaluator>(error, target.weight), q);
  }
  if (has_com_) {
    auto com = std::make_shared<CenterOfMassProjection>(model_, Eigen::Matrix2d::Identity(), com_xy_);
    prog.AddLeastSquaresCost(std::make_shared<ScaledEvaluator>(com, com_weight_), q);
  }
  for (const auto& [frame, weight] : roll_targets_) {
    prog.AddLeastSquaresCost(std::make_shared<ScaledEvaluator>(std::make_shared<WaistRollError>(model_, frame), weight), q);
  }
  if (chart.has_floating_base()) {
    prog.AddLeastSquaresCost(std::make_shared<QuaternionNormError>(), q.Segment(3, 4));
  }
  Eigen::VectorXd lower = Eigen::VectorXd::Constant(model.nq(), -std::numeric_limits<double>::infinity());
  Eigen::VectorXd upper = Eigen::VectorXd::Constant(model.nq(), std::numeric_limits<double>::infinity());
  for (int i : chart.joint_coordinates()) {
    lower(i) = model.lower_position_limits()(i);
    upper(i) = model.upper_position_limits()(i);
  }
  prog.AddBoundingBoxConstraint(lower, upper, q);
  Eigen::VectorXd x = start.cwiseMax(lower).cwiseMin(upper);

  // The posture term would trade a little pose error for posture; so after the first round it is re-centred on
  // the last solution (proximal-point rounds), which drives the targets' residuals to zero while it still picks
  // the solution near the nominal posture.
  optimization::SolverOptions options;
  options.Set("least_squares", "max_iterations", max_iterations);
  optimization::SolverResult solved;
  int iterations = 0;
  Eigen::VectorXd center = posture_weight_ > 0.0 ? nominal_ : x;
  for (int round = 0; round < kRounds; ++round) {
    optimization::MathematicalProgram round_prog = prog;
    if (posture_weight_ > 0.0) {
      auto posture = std::make_shared<PostureResidual>(model.nq(), chart.joint_coordinates(), center);
      round_prog.AddLeastSquaresCost(std::make_shared<ScaledEvaluator>(posture, posture_weight_), q);
    }
    solved = optimization::LeastSquaresSolver().Solve(round_prog, x, options);
    iterations += std::max(solved.iterations, 0);
    x = chart.Normalized(solved.x);
    center = x;
    double worst = 0.0, worst_rotation = 0.0;
    for (const auto& error : pose_errors) {
      const Eigen::VectorXd e = error->Eval(x);
      worst = std::max(worst, e.head<3>().norm());
      worst_rotation = std::max(worst_rotation, e.tail<3>().norm());
    }
    if (posture_weight_ <= 0.0 || (worst <= position_tolerance && worst_rotation <= rotation_tolerance)) break;
  }

  InverseKinematicsResult result;
  result.q = x;
  result.iterations = iterations;
  std::string worst;
  for (const auto& error : pose_errors) {
    const Eigen::VectorXd e = error->Eval(result.q);
    const double position = e.head<3>().norm(), rotation = e.tail<3>().norm();
    if (position > result.max_position_error || rotation > result.max_rotation_error) worst = error->name();
    result.max_position_error = std::max(result.max_position_error, position);
    result.max_rotation_error = std::max(result.max_rotation_error, rotation);
  }
  const bool met = result.max_position_error <= position_tolerance && result.max_rotation_error <= rotation_tolerance;
  result.success = met;
  result.message = std::string(optimization::to_string(solved.status)) + ": " + solved.message;
  if (!met) {
    result.message += "; worst target " + worst + ": position error " + FormatShort(result.max_position_error) +
                      " m, rotation error " + FormatShort(result.max_rotation_error) + " rad";
  }
  return result;
}

}  // namespace cairn::planning
