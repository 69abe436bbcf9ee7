#include "cairn/common/number_text.h"
#include "cairn/planning/locomotion/leg_torque_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "cairn/common/cairn_assert.h"
#include "cairn/multibody/configuration.h"
#include "cairn/multibody/data.h"
#include "cairn/multibody/gravity_torques.h"
#include "cairn/multibody/jacobians.h"
#include "cairn/multibody/kinematics.h"

namespace cairn::planning {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

std::string Num(double x) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.4g", x);
  return text;
}

double Lerp(double lo, double hi, int i, int n) { return n == 1 ? lo : lo + (hi - lo) * i / (n - 1); }

// Cell index and fraction of `x` on an axis of n nodes over [lo, hi], clamped to the axis.
void Locate(double x, double lo, double hi, int n, int* i, double* t) {
  if (n == 1) {
    *i = 0;
    *t = 0.0;
    return;
  }
  const double u = std::clamp((x - lo) / (hi - lo), 0.0, 1.0) * (n - 1);
  *i = std::min(static_cast<int>(u), n - 2);
  *t = u - *i;
}

}  // namespace

LegTorqueTable LegTorqueTable::Compute(const multibody::Model& model, const std::array<std::string, 6>& joint_names,
                                       const std::string& sole_frame, const LegTorqueGrid& grid) {
  if (grid.length_count < 1 || grid.pitch_count < 1 || grid.roll_count < 1 || !(grid.length_min > 0.0) ||
      !(grid.length_max >= grid.length_min) || !(grid.pitch_max >= grid.pitch_min) ||
      !(grid.roll_max >= grid.roll_min)) {
    throw std::invalid_argument("LegTorqueTable: the posture grid is empty or its ranges are reversed; give counts >= 1 "
                                "and min <= max with a positive length.");
  }
  const int frame = model.GetFrameIndex(sole_frame);
  std::array<int, 6> iq{}, iv{};
  std::array<double, 6> lower{}, upper{};
  for (int j = 0; j < 6; ++j) {
    const multibody::Joint& joint = model.joint(model.GetJointIndex(joint_names[j]));
    if (joint.nv != 1) {
      throw std::invalid_argument("LegTorqueTable: joint '" + joint_names[j] + "' is not a one-axis joint.");
    }
    iq[j] = joint.idx_q;
    iv[j] = joint.idx_v;
    lower[j] = joint.lower_limit;
    upper[j] = joint.upper_limit;
  }
  // Hip centre = origin of the hip roll joint's child (on the hip yaw axis, so independent of the yaw angle);
  // ankle centre = origin of the ankle pitch joint's child. Both at the zero configuration, pelvis at identity.
  multibody::Data data(model);
  const Eigen::VectorXd q0 = multibody::NeutralConfiguration(model);
  multibody::ForwardKinematics(model, data, q0);
  const int hip_body = model.GetBodyIndex(model.body(model.GetJointIndex(joint_names[1])).name);
  const int ankle_body = model.GetBodyIndex(model.body(model.GetJointIndex(joint_names[4])).name);
  const Eigen::Vector3d hip = data.X_world[hip_body].translation();
  const Eigen::Vector3d sole_from_ankle =
      multibody::FramePose(model, data, frame).translation() - data.X_world[ankle_body].translation();

  LegTorqueTable table;
  table.grid_ = grid;
  table.nodes_.assign(static_cast<std::size_t>(grid.length_count * grid.pitch_count * grid.roll_count) * kStride, 0.0);
  Eigen::MatrixXd J(6, model.nv());
  Eigen::VectorXd q = q0;
  // A bent-knee start; each node then starts from its neighbour's solution (continuation, deterministic order).
  const double start[6] = {0.0, 0.0, -0.3, 0.6, -0.3, 0.0};
  for (int i = 0; i < grid.length_count; ++i) {
    for (int j = 0; j < grid.pitch_count; ++j) {
      for (int k = 0; k < grid.roll_count; ++k) {
        const double length = Lerp(grid.length_min, grid.length_max, i, grid.length_count);
        const double pitch = Lerp(grid.pitch_min, grid.pitch_max, j, grid.pitch_count);
        const double roll = Lerp(grid.roll_min, grid.roll_max, k, grid.roll_count);
        const Eigen::Vector3d e = length * Eigen::Vector3d(std::tan(pitch), std::tan(roll), -1.0).normalized();
        const Eigen::Vector3d target = hip + e + sole_from_ankle;
        if (k == 0) {
          q = q0;
          for (int c = 0; c < 6; ++c) q[iq[c]] = start[c];
        }
        double residual = 1.0;
        for (int iteration = 0; iteration < 100 && residual > 1e-12; ++iteration) {
          multibody::ForwardKinematics(model, data, q);
          const multibody::Pose X = multibody::FramePose(model, data, frame);
          const Eigen::AngleAxisd rotation_error(X.rotation().transpose());  // target rotation is the identity
          Vector6d error;
          error.head<3>() = rotation_error.angle() * rotation_error.axis();
          error.tail<3>() = target - X.translation();
          residual = error.norm();
          multibody::FrameJacobian(model, data, frame, multibody::ReferenceFrame::kWorldAligned, J);
          Eigen::Matrix<double, 6, 6> J_leg;
          for (int c = 0; c < 6; ++c) J_leg.col(c) = J.col(iv[c]);
          const Vector6d step = J_leg.partialPivLu().solve(error);
          for (int c = 0; c < 6; ++c) q[iq[c]] += step[c];
        }
        multibody::ForwardKinematics(model, data, q);
        const double position_error = (multibody::FramePose(model, data, frame).translation() - target).norm();
        if (!(position_error < 1e-8)) {
          throw std::runtime_error("LegTorqueTable: inverse kinematics did not converge for the ankle at length " +
                                   Num(length) + " m, pitch " + Num(pitch) + " rad, roll " + Num(roll) +
                                   " rad from the hip; shrink the leg_torque_grid ranges.");
        }
        table.max_ik_residual_ = std::max(table.max_ik_residual_, position_error);
        double limit_excess = -std::numeric_limits<double>::infinity();
        for (int c = 0; c < 6; ++c) limit_excess = std::max({limit_excess, lower[c] - q[iq[c]], q[iq[c]] - upper[c]});
        if (limit_excess > 0.0) ++table.nodes_outside_joint_limits_;

        const Eigen::VectorXd& g = multibody::GravityTorques(model, data, q);
        multibody::ForwardKinematics(model, data, q);
        multibody::FrameJacobian(model, data, frame, multibody::ReferenceFrame::kWorldAligned, J);
        // tau = g - J_c^T F for F = f e_z at the sole point c = o + (cop_x, cop_y, 0):
        // J_c^T F = f (J_v,z + cop_y J_w,x - cop_x J_w,y).
        double* node = &table.nodes_[static_cast<std::size_t>(table.Index(i, j, k)) * kStride];
        for (int c = 0; c < 6; ++c) {
          node[c] = g[iv[c]];
          node[6 + c] = -J(5, iv[c]);
          node[12 + c] = J(1, iv[c]);
          node[18 + c] = -J(0, iv[c]);
          node[24 + c] = q[iq[c]];
        }
        node[30] = limit_excess;
      }
    }
  }
  return table;
}

bool LegTorqueTable::Contains(const Eigen::Vector3d& e) const {
  if (nodes_.empty() || !(e.z() < 0.0)) return false;
  const double length = e.norm();
  const double pitch = std::atan2(e.x(), -e.z());
  const double roll = std::atan2(e.y(), -e.z());
  return length >= grid_.length_min && length <= grid_.length_max && pitch >= grid_.pitch_min &&
         pitch <= grid_.pitch_max && roll >= grid_.roll_min && roll <= grid_.roll_max;
}

void LegTorqueTable::Interpolate(const Eigen::Vector3d& e, int first, int count, double* values) const {
  CAIRN_CHECK(!nodes_.empty());
  const double length = e.norm();
  const double down = std::max(-e.z(), 1e-9);
  int i, j, k;
  double u, v, w;
  Locate(length, grid_.length_min, grid_.length_max, grid_.length_count, &i, &u);
  Locate(std::atan2(e.x(), down), grid_.pitch_min, grid_.pitch_max, grid_.pitch_count, &j, &v);
  Locate(std::atan2(e.y(), down), grid_.roll_min, grid_.roll_max, grid_.roll_count, &k, &w);
  std::fill(values, values + count, 0.0);
  for (int corner = 0; corner < 8; ++corner) {
    const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
    const double weight = (di ? u : 1.0 - u) * (dj ? v : 1.0 - v) * (dk ? w : 1.0 - w);
    if (weight == 0.0) continue;
    const int ii = std::min(i + di, grid_.length_count - 1);
    const int jj = std::min(j + dj, grid_.pitch_count - 1);
    const int kk = std::min(k + dk, grid_.roll_count - 1);
    const double* node = &nodes_[static_cast<std::size_t>(Index(ii, jj, kk)) * kStride + first];
    for (int c = 0; c < count; ++c) values[c] += weight * node[c];
  }
}

void LegTorqueTable::Torques(const Eigen::Vector3d& e, double load, const Eigen::Vector2d& cop,
                             Eigen::Ref<Eigen::Matrix<double, 6, 1>> tau) const {
  double coefficient[24];
  Interpolate(e, 0, 24, coefficient);
  for (int c = 0; c < 6; ++c) {
    tau[c] = coefficient[c] + load * (coefficient[6 + c] + cop.x() * coefficient[12 + c] + cop.y() * coefficient[18 + c]);
  }
}

double LegTorqueTable::JointLimitExcess(const Eigen::Vector3d& e) const {
  double excess;
  Interpolate(e, 30, 1, &excess);
  return excess;
}

Eigen::Matrix<double, 6, 1> LegTorqueTable::NodeAngles(int i, int j, int k) const {
  if (i < 0 || i >= grid_.length_count || j < 0 || j >= grid_.pitch_count || k < 0 || k >= grid_.roll_count) {
    throw std::out_of_range("LegTorqueTable::NodeAngles: node (" + cairn::FormatShort(i) + ", " + cairn::FormatShort(j) +
                            ", " + cairn::FormatShort(k) + ") is outside the grid.");
  }
  const double* node = &nodes_[static_cast<std::size_t>(Index(i, j, k)) * kStride];
  Eigen::Matrix<double, 6, 1> angles;
  for (int c = 0; c < 6; ++c) angles[c] = node[24 + c];
  return angles;
}

}  // namespace cairn::planning
