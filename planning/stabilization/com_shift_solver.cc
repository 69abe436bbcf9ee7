#include <cairn/planning/stabilization/com_shift_solver.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/jacobians.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::planning {

namespace {
Eigen::Vector3d RotationError(const Eigen::Matrix3d& target, const Eigen::Matrix3d& current) {
  const Eigen::AngleAxisd error(target * current.transpose());
  return error.angle() * error.axis();
}
}  // namespace

ComShiftSolver::ComShiftSolver(std::shared_ptr<const multibody::Model> model, const std::string& left_sole,
                               const std::string& right_sole)
    : model_(std::move(model)) {
  if (model_ == nullptr) throw std::invalid_argument("ComShiftSolver: the robot model is null");
  for (int i = 1; i < model_->num_bodies(); ++i) {
    if (model_->joint(i).type == multibody::JointType::kFloating) {
      base_body_ = i;
      base_v_ = model_->joint(i).idx_v;
      break;
    }
  }
  if (base_body_ < 0) {
    throw std::invalid_argument("ComShiftSolver: the model '" + model_->name() + "' has no floating base");
  }
  for (const std::string* sole : {&left_sole, &right_sole}) {
    if (!model_->HasFrame(*sole)) {
      throw std::invalid_argument("ComShiftSolver: the model '" + model_->name() + "' has no frame '" + *sole + "'");
    }
  }
  left_ = model_->GetFrameIndex(left_sole);
  right_ = model_->GetFrameIndex(right_sole);
  for (int i = 0; i < 6; ++i) columns_.push_back(base_v_ + i);
  for (int frame : {left_, right_}) {
    std::vector<int> chain;
    int body = model_->frame(frame).body;
    while (body > 0 && body != base_body_) {
      const multibody::Joint& joint = model_->joint(body);
      if (joint.nv == 1) chain.push_back(joint.idx_v);
      body = model_->parent(body);
    }
    if (body != base_body_) {
      throw std::invalid_argument("ComShiftSolver: the sole frame '" + model_->frame(frame).name +
                                  "' is not on a leg below the floating base");
    }
    columns_.insert(columns_.end(), chain.rbegin(), chain.rend());
  }
}

ComShiftResult ComShiftSolver::Solve(const Eigen::VectorXd& q_reference, const Eigen::Vector2d& com_target,
                                     int steps) const {
  if (q_reference.size() != model_->nq() || !q_reference.allFinite()) {
    throw std::invalid_argument("ComShiftSolver::Solve: the reference needs " + std::to_string(model_->nq()) +
                                " finite coordinates");
  }
  multibody::Data data(*model_);
  multibody::ForwardKinematics(*model_, data, q_reference);
  return Solve(q_reference, com_target, data.X_world[static_cast<std::size_t>(base_body_)].rotation(), steps);
}

ComShiftResult ComShiftSolver::Solve(const Eigen::VectorXd& q_reference, const Eigen::Vector2d& com_target,
                                     const Eigen::Matrix3d& R_base, int steps) const {
  const multibody::Model& m = *model_;
  if (q_reference.size() != m.nq() || !q_reference.allFinite() || !com_target.allFinite()) {
    throw std::invalid_argument("ComShiftSolver::Solve: the reference needs " + std::to_string(m.nq()) +
                                " finite coordinates and the COM target must be finite");
  }
  if (steps < 1 || steps > 50) {
    throw std::invalid_argument("ComShiftSolver::Solve: steps " + std::to_string(steps) + " must be in [1, 50]");
  }
  multibody::Data data(m);
  multibody::ForwardKinematics(m, data, q_reference);
  const multibody::Pose X_L = multibody::FramePose(m, data, left_), X_R = multibody::FramePose(m, data, right_);
  if (!R_base.allFinite() || !(R_base.transpose() * R_base).isApprox(Eigen::Matrix3d::Identity(), 1e-9)) {
    throw std::invalid_argument("ComShiftSolver::Solve: the base orientation must be a rotation matrix");
  }
  // Column scales of the weighted minimum-norm step (the base's linear velocity in world axes): the base's
  // vertical motion costs 100 times a joint's.
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(columns_.size()));
  scale[5] = 0.1;
  const auto cols = static_cast<Eigen::Index>(columns_.size());
  Eigen::MatrixXd J(6, m.nv()), A(17, cols);
  Eigen::VectorXd r(17), dv = Eigen::VectorXd::Zero(m.nv());
  ComShiftResult result;
  result.q = q_reference;
  for (int step = 0; step <= steps; ++step) {
    const Eigen::Matrix<double, 3, Eigen::Dynamic>& Jc = multibody::CenterOfMassJacobian(m, data, result.q);
    const Eigen::Vector3d com = data.com;
    int row = 0;
    double sole_error = 0.0;
    for (const auto& [frame, target] : {std::pair<int, const multibody::Pose*>{left_, &X_L}, {right_, &X_R}}) {
      const multibody::Pose X = multibody::FramePose(m, data, frame);
      r.segment<3>(row) = RotationError(target->rotation(), X.rotation());
      r.segment<3>(row + 3) = target->translation() - X.translation();
      sole_error = std::max(sole_error, r.segment<3>(row + 3).norm());
      multibody::FrameJacobian(m, data, frame, multibody::ReferenceFrame::kWorldAligned, J);
      for (Eigen::Index c = 0; c < cols; ++c) A.block<6, 1>(row, c) = J.col(columns_[static_cast<std::size_t>(c)]);
      row += 6;
    }
    r.segment<2>(row) = com_target - com.head<2>();
    for (Eigen::Index c = 0; c < cols; ++c) A.block<2, 1>(row, c) = Jc.block<2, 1>(0, columns_[static_cast<std::size_t>(c)]);
    row += 2;
    const Eigen::Matrix3d R = data.X_world[static_cast<std::size_t>(base_body_)].rotation();
    r.segment<3>(row) = RotationError(R_base, R);
    // The base's body angular velocity turns it by R w_body in world axes.
    A.block(row, 0, 3, cols).setZero();
    A.block<3, 3>(row, 0) = R;
    result.sole_error = sole_error;
    result.com_error = r.segment<2>(12).norm();
    if (step == steps) break;
    // Base linear columns in world axes (v_body = R^T u), then scaled.
    Eigen::MatrixXd scaled = A;
    scaled.middleCols<3>(3) = A.middleCols<3>(3) * R.transpose();
    scaled = scaled * scale.asDiagonal();
    const Eigen::MatrixXd normal = scaled * scaled.transpose() + 1e-10 * Eigen::MatrixXd::Identity(17, 17);
    Eigen::VectorXd delta = scale.asDiagonal() * (scaled.transpose() * normal.ldlt().solve(r));
    delta.segment<3>(3) = R.transpose() * delta.segment<3>(3);
    dv.setZero();
    for (Eigen::Index c = 0; c < cols; ++c) dv[columns_[static_cast<std::size_t>(c)]] = delta[c];
    result.q = multibody::Integrate(m, result.q, dv);
  }
  return result;
}

}  // namespace cairn::planning
