#include <cairn/planning/stabilization/pelvis_pose_solver.h>

#include <stdexcept>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/jacobians.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::planning {

namespace {
Eigen::Vector3d RotationError(const Eigen::Matrix3d& target, const Eigen::Matrix3d& current) {
  const Eigen::AngleAxisd error(target * current.transpose());
  return error.angle() * error.axis();
}

// Leg solves stop below this sole error (m, rad) or after this many steps.
constexpr double kLegTolerance = 1e-9;
constexpr int kLegSteps = 30;
// COM passes (the waist moves by the remaining error each time).
constexpr int kComPasses = 8;
constexpr double kComTolerance = 1e-7;
// Damping of the leg steps (rad^2): small, so that converged solutions are exact, but it keeps a stretched knee
// from producing a huge step.
constexpr double kDamping = 1e-8;
}  // namespace

PelvisPoseSolver::PelvisPoseSolver(std::shared_ptr<const multibody::Model> model, const std::string& left_sole,
                                   const std::string& right_sole)
    : model_(std::move(model)) {
  if (model_ == nullptr) throw std::invalid_argument("PelvisPoseSolver: the robot model is null");
  if (model_->num_bodies() < 2 || model_->joint(1).type != multibody::JointType::kFloating) {
    throw std::invalid_argument("PelvisPoseSolver: the model '" + model_->name() +
                                "' has no floating base as its first joint");
  }
  const std::string* names[2] = {&left_sole, &right_sole};
  for (int side = 0; side < 2; ++side) {
    if (!model_->HasFrame(*names[side])) {
      throw std::invalid_argument("PelvisPoseSolver: the model '" + model_->name() + "' has no frame '" +
                                  *names[side] + "'");
    }
    frames_[side] = model_->GetFrameIndex(*names[side]);
    int body = model_->frame(frames_[side]).body;
    while (body > 1) {
      const multibody::Joint& joint = model_->joint(body);
      if (joint.nv == 1) {
        leg_v_[side].push_back(joint.idx_v);
        leg_q_[side].push_back(joint.idx_q);
      }
      body = model_->parent(body);
    }
    if (body != 1 || leg_v_[side].size() != 6) {
      throw std::invalid_argument("PelvisPoseSolver: the sole frame '" + *names[side] + "' is not on a leg of six " +
                                  "joints below the floating base (found " + std::to_string(leg_v_[side].size()) + ")");
    }
  }
}

PelvisPoseResult PelvisPoseSolver::Solve(const Eigen::VectorXd& seed, const Eigen::Vector2d& com_target,
                                         const Eigen::Matrix3d& R_base, double base_height,
                                         const multibody::Pose& X_left, const multibody::Pose& X_right) const {
  const multibody::Model& m = *model_;
  const bool finite_poses = X_left.rotation().allFinite() && X_left.translation().allFinite() &&
                            X_right.rotation().allFinite() && X_right.translation().allFinite();
  if (seed.size() != m.nq() || !seed.allFinite() || !com_target.allFinite() || !R_base.allFinite() ||
      !std::isfinite(base_height) || !finite_poses) {
    throw std::invalid_argument("PelvisPoseSolver::Solve: the seed needs " + std::to_string(m.nq()) +
                                " finite coordinates and every target must be finite");
  }
  if (!(R_base.transpose() * R_base).isApprox(Eigen::Matrix3d::Identity(), 1e-9)) {
    throw std::invalid_argument("PelvisPoseSolver::Solve: the base orientation must be a rotation matrix");
  }
  PelvisPoseResult result;
  result.q = seed;
  const Eigen::Quaterniond quat(R_base);
  result.q(2) = base_height;
  result.q.segment<4>(3) << quat.w(), quat.x(), quat.y(), quat.z();
  multibody::Data data(m);
  Eigen::MatrixXd J(6, m.nv());
  Eigen::Matrix<double, 6, 6> A;
  const multibody::Pose* targets[2] = {&X_left, &X_right};
  for (int pass = 0; pass < kComPasses; ++pass) {
    result.sole_error = 0.0;
    for (int side = 0; side < 2; ++side) {
      const multibody::Pose& target = *targets[side];
      for (int step = 0; step <= kLegSteps; ++step) {
        multibody::ForwardKinematics(m, data, result.q);
        const multibody::Pose X = multibody::FramePose(m, data, frames_[side]);
        Eigen::Matrix<double, 6, 1> r;
        r << RotationError(target.rotation(), X.rotation()), target.translation() - X.translation();
        if (r.norm() < kLegTolerance || step == kLegSteps) {
          result.sole_error = std::max(result.sole_error, r.tail<3>().norm());
          break;
        }
        multibody::FrameJacobian(m, data, frames_[side], multibody::ReferenceFrame::kWorldAligned, J);
        for (int c = 0; c < 6; ++c) A.col(c) = J.col(leg_v_[side][static_cast<std::size_t>(c)]);
        const Eigen::Matrix<double, 6, 1> d =
            (A.transpose() * A + kDamping * Eigen::Matrix<double, 6, 6>::Identity()).ldlt().solve(A.transpose() * r);
        for (int c = 0; c < 6; ++c) result.q(leg_q_[side][static_cast<std::size_t>(c)]) += d(c);
      }
    }
    const Eigen::Vector2d error = com_target - multibody::CenterOfMass(m, data, result.q).head<2>();
    result.com_error = error.norm();
    if (result.com_error < kComTolerance || pass + 1 == kComPasses) break;
    result.q.head<2>() += error;  // then the legs are solved again, so the soles end where they were asked
  }
  return result;
}

}  // namespace cairn::planning
