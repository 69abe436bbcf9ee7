#include <cairn/planning/walk/balance_feedback.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/jacobians.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/plant/sole_state.h>

namespace cairn::planning {
namespace {

// Two Data, so the reference's and the plant's kinematics do not overwrite each other; per context, so the
// output calculation allocates nothing and contexts in different threads share nothing.
struct Scratch {
  multibody::Data measured;
  multibody::Data reference;
  Eigen::MatrixXd jacobian;  // 6 x nv
};

void CheckRange(const char* name, double value, double low, double high, bool open_low = false) {
  const bool ok = std::isfinite(value) && (open_low ? value > low : value >= low) && value <= high;
  if (!ok) {
    throw std::invalid_argument(std::string("BalanceFeedback: ") + name + " " + FormatShort(value) + " must be in " +
                                (open_low ? "(" : "[") + FormatShort(low) + ", " + FormatShort(high) + "]");
  }
}

}  // namespace

BalanceFeedback::BalanceFeedback(std::shared_ptr<const multibody::Model> model, const BalanceFeedbackOptions& options)
    : model_(std::move(model)), options_(options) {
  if (model_ == nullptr) throw std::invalid_argument("BalanceFeedback: the robot model is null");
  if (model_->num_bodies() < 2 || model_->joint(1).type != multibody::JointType::kFloating) {
    throw std::invalid_argument("BalanceFeedback: model '" + model_->name() +
                                "' has no floating base; load the URDF with a floating base");
  }
  CheckRange("pitch_gain", options_.pitch_gain, 0.0, 1e3);
  CheckRange("roll_gain", options_.roll_gain, 0.0, 1e3);
  CheckRange("max_pitch", options_.max_pitch, 0.0, 0.5);
  CheckRange("max_roll", options_.max_roll, 0.0, 0.5);
  CheckRange("com_height", options_.com_height, 0.1, 3.0, true);
  if (!(model_->gravity().z() < 0.0)) {
    throw std::invalid_argument("BalanceFeedback: model '" + model_->name() + "' has gravity z " +
                                FormatShort(model_->gravity().z()) +
                                " m/s^2; the capture point needs gravity pointing down (-z)");
  }
  const auto ankle = [&](const std::string& name, int axis) {
    if (!model_->HasJoint(name)) {
      throw std::invalid_argument("BalanceFeedback: model '" + model_->name() + "' has no joint '" + name +
                                  "'; name the ankle joints in BalanceFeedbackOptions");
    }
    const multibody::Joint& joint = model_->joint(model_->GetJointIndex(name));
    if (joint.type != multibody::JointType::kRevolute || joint.axis_index != axis) {
      throw std::invalid_argument("BalanceFeedback: joint '" + name + "' must be revolute about its " +
                                  (axis == 0 ? "x" : "y") + " axis (the ankle's " + (axis == 0 ? "roll" : "pitch") +
                                  ")");
    }
    return Ankle{joint.idx_q, static_cast<double>(joint.axis_sign)};
  };
  CheckRange("foothold_gain", options_.foothold_gain, 0.0, 1.0);
  CheckRange("swing_orientation_gain", options_.swing_orientation_gain, 0.0, 1.0);
  CheckRange("swing_position_gain", options_.swing_position_gain, 0.0, 1.0);
  const std::string* soles[2] = {&options_.left_sole, &options_.right_sole};
  for (int side = 0; side < 2 && uses_legs(); ++side) {
    if (!model_->HasFrame(*soles[side])) {
      throw std::invalid_argument("BalanceFeedback: model '" + model_->name() + "' has no frame '" + *soles[side] +
                                  "'; name the sole frames in BalanceFeedbackOptions, or set foothold_gain and the "
                                  "swing gains 0");
    }
    sole_frame_[side] = model_->GetFrameIndex(*soles[side]);
    int joints = 0;
    for (int body = model_->frame(sole_frame_[side]).body; body > 1; body = model_->parent(body)) {
      const multibody::Joint& joint = model_->joint(body);
      if (joint.nv == 0) continue;
      if (joint.nv != 1 || joints == 6) {
        joints = -1;
        break;
      }
      leg_v_[side][joints] = joint.idx_v;
      leg_q_[side][joints] = joint.idx_q;
      ++joints;
    }
    if (joints != 6) {
      throw std::invalid_argument("BalanceFeedback: the sole frame '" + *soles[side] +
                                  "' is not on a leg of six one-axis joints below the floating base; name the sole "
                                  "frames of six-joint legs, or set foothold_gain and the swing gains 0");
    }
  }
  pitch_[0] = ankle(options_.left_ankle_pitch, 1);
  pitch_[1] = ankle(options_.right_ankle_pitch, 1);
  roll_[0] = ankle(options_.left_ankle_roll, 0);
  roll_[1] = ankle(options_.right_ankle_roll, 0);

  const int n = model_->nq() + model_->nv();
  DeclareVectorInputPort("reference", n);
  DeclareVectorInputPort("state", n);
  DeclareAbstractInputPort("contacts", systems::Value<std::vector<multibody::SoleState>>(
                                           std::vector<multibody::SoleState>(2)));
  scratch_ = DeclarePerContextStorage(systems::Value<Scratch>(
      Scratch{multibody::Data(*model_), multibody::Data(*model_), Eigen::MatrixXd::Zero(6, model_->nv())}));
  DeclareVectorOutputPort(
      "reference", n,
      [this](const systems::Context& context, Eigen::VectorXd* y) {
        const auto& soles = get_contacts_input_port().Eval<std::vector<multibody::SoleState>>(context);
        if (soles.size() != 2) {
          throw std::invalid_argument("BalanceFeedback: the contacts input has " + FormatShort(soles.size()) +
                                      " soles; connect the HumanoidPlant's `contacts` (left, right)");
        }
        Scratch& scratch = GetMutablePerContextStorage<Scratch>(context, scratch_);
        const Eigen::VectorXd& reference = get_reference_input_port().Eval<Eigen::VectorXd>(context);
        const Eigen::VectorXd& state = get_state_input_port().Eval<Eigen::VectorXd>(context);
        *y = reference;
        Apply(reference, state, soles[0].loaded, soles[1].loaded, &scratch.measured, &scratch.reference,
              &scratch.jacobian, y);
      },
      {input_port_ticket(0), input_port_ticket(1), input_port_ticket(2)});
}

Eigen::VectorXd BalanceFeedback::Correct(const Eigen::VectorXd& reference, const Eigen::VectorXd& state,
                                         bool left_loaded, bool right_loaded) const {
  const int n = model_->nq() + model_->nv();
  if (reference.size() != n || state.size() != n) {
    throw std::invalid_argument("BalanceFeedback: reference and state must have nq + nv = " + FormatShort(n) +
                                " entries; got " + FormatShort(reference.size()) + " and " +
                                FormatShort(state.size()));
  }
  multibody::Data measured(*model_), planned(*model_);
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(6, model_->nv());
  Eigen::VectorXd y = reference;
  Apply(reference, state, left_loaded, right_loaded, &measured, &planned, &jacobian, &y);
  return y;
}

void BalanceFeedback::Apply(const Eigen::VectorXd& reference, const Eigen::VectorXd& state, bool left_loaded,
                            bool right_loaded, multibody::Data* measured, multibody::Data* planned,
                            Eigen::MatrixXd* jacobian, Eigen::VectorXd* y) const {
  if (!left_loaded && !right_loaded) return;  // in the air: nothing to stand on
  const int nq = model_->nq();
  const double omega = std::sqrt(-model_->gravity().z() / options_.com_height);
  const auto capture_point = [&](const Eigen::VectorXd& x, multibody::Data* data) {
    // The Jacobian pass also computes the COM (data->com), so one kinematics pass serves both.
    const Eigen::Vector3d c_dot = multibody::CenterOfMassJacobian(*model_, *data, x.head(nq)) * x.tail(model_->nv());
    const Eigen::Vector3d c = data->com;
    return Eigen::Vector2d((c + c_dot / omega).head<2>());
  };
  const Eigen::Vector2d error = capture_point(state, measured) - capture_point(reference, planned);
  const int b = model_->joint(1).idx_q + 3;  // the floating base's quaternion (w, x, y, z)
  const Eigen::Quaterniond base(state[b], state[b + 1], state[b + 2], state[b + 3]);
  const Eigen::Vector3d forward = base * Eigen::Vector3d::UnitX();
  const double yaw = std::atan2(forward.y(), forward.x());
  const double e_forward = std::cos(yaw) * error.x() + std::sin(yaw) * error.y();
  const double e_left = -std::sin(yaw) * error.x() + std::cos(yaw) * error.y();
  // A joint rotation theta about the ankle's axis (sign s along the tilt axis) tilts the leg over the flat foot by
  // -s theta; tilting it by rho about y moves the COM forward by h rho, about x sideways by -h rho.
  const double tilt_y = std::clamp(-options_.pitch_gain * e_forward, -options_.max_pitch, options_.max_pitch);
  const double tilt_x = std::clamp(options_.roll_gain * e_left, -options_.max_roll, options_.max_roll);
  const bool loaded[2] = {left_loaded, right_loaded};
  // The capture points ran the kinematics of both configurations, so the soles' and the base's poses are in the
  // Data already.
  const multibody::Pose& base_measured = measured->X_world[1];
  const multibody::Pose& base_planned = planned->X_world[1];
  for (int leg = 0; leg < 2 && uses_legs(); ++leg) {
    // [rotation; translation] of the sole in world axes with the base held.
    Eigen::Matrix<double, 6, 1> move = Eigen::Matrix<double, 6, 1>::Zero();
    const multibody::Pose X_planned = multibody::FramePose(*model_, *planned, sole_frame_[leg]);
    if (loaded[leg]) {
      // Horizontal only (the sole's height and tilt are the ground's; re-posing the yaw too measured more slips,
      // docs/walk.md).
      const multibody::Pose X_measured = multibody::FramePose(*model_, *measured, sole_frame_[leg]);
      move.segment<2>(3) = options_.foothold_gain * (X_measured.translation() - X_planned.translation()).head<2>();
    } else if (loaded[1 - leg]) {
      // The sole the reference's leg angles give on the measured base: T X_planned with T = X_base_measured
      // X_base_planned^-1. Moving the planned sole by T^-1 cancels the base's error.
      const multibody::Pose T = base_measured * base_planned.Inverse();
      const Eigen::AngleAxisd rotation_error(T.rotation());
      move.head<3>() = -options_.swing_orientation_gain * rotation_error.angle() * rotation_error.axis();
      const Eigen::Vector3d target = T.Inverse() * X_planned.translation();
      move.tail<3>() = options_.swing_position_gain * (target - X_planned.translation());
    }
    if (move.isZero(0.0)) continue;
    multibody::FrameJacobian(*model_, *planned, sole_frame_[leg], multibody::ReferenceFrame::kWorldAligned, *jacobian);
    Eigen::Matrix<double, 6, 6> leg_jacobian;
    for (int c = 0; c < 6; ++c) leg_jacobian.col(c) = jacobian->col(leg_v_[leg][c]);
    // Damped, as a bent leg's Jacobian is well conditioned but a straight knee's is not.
    constexpr double kDamping = 1e-6;
    const Eigen::Matrix<double, 6, 1> dq =
        (leg_jacobian.transpose() * leg_jacobian + kDamping * Eigen::Matrix<double, 6, 6>::Identity())
            .ldlt()
            .solve(leg_jacobian.transpose() * move);
    for (int c = 0; c < 6; ++c) (*y)[leg_q_[leg][c]] += dq[c];
  }
  for (int leg = 0; leg < 2; ++leg) {
    if (!loaded[leg]) continue;
    (*y)[pitch_[leg].q] -= tilt_y / pitch_[leg].sign;
    (*y)[roll_[leg].q] -= tilt_x / roll_[leg].sign;
  }
}

}  // namespace cairn::planning
