#include <cairn/planning/stabilization/stabilized_reference_player.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>

namespace cairn::planning {

StabilizedReferencePlayer::StabilizedReferencePlayer(std::shared_ptr<const multibody::Model> model)
    : model_(std::move(model)) {
  if (model_ == nullptr) throw std::invalid_argument("StabilizedReferencePlayer: the robot model is null");
  if (model_->num_bodies() < 2 || model_->joint(1).type != multibody::JointType::kFloating) {
    throw std::invalid_argument("StabilizedReferencePlayer: model '" + model_->name() +
                                "' has no floating base; load the URDF with a floating base");
  }
  const auto& input =
      DeclareAbstractInputPort("reference", systems::Value<StabilizedTrajectory>(StabilizedTrajectory()));
  const int input_index = input.get_index();
  DeclareVectorOutputPort(
      "reference", model_->nq() + model_->nv(),
      [this](const systems::Context& context, Eigen::VectorXd* y) {
        *y = Sample(get_reference_input_port().Eval<StabilizedTrajectory>(context), context.get_time());
      },
      {time_ticket(), input_port_ticket(input_index)});
}

Eigen::VectorXd StabilizedReferencePlayer::Sample(const StabilizedTrajectory& reference, double t) const {
  if (reference.q.empty()) {
    throw std::runtime_error("StabilizedReferencePlayer: the stabilised reference is empty (" +
                             (reference.report.message.empty() ? std::string("no message")
                                                               : reference.report.message) +
                             "); run the Stabilizer's events before simulating the plant");
  }
  if (!std::isfinite(t)) {
    throw std::invalid_argument("StabilizedReferencePlayer: time " + FormatShort(t) + " is not finite");
  }
  const int nq = model_->nq(), nv = model_->nv();
  if (reference.v.size() != reference.q.size()) {
    throw std::invalid_argument("StabilizedReferencePlayer: the reference has " + FormatShort(reference.q.size()) +
                                " configurations but " + FormatShort(reference.v.size()) + " velocities");
  }
  const auto check = [&](std::size_t k) {
    if (reference.q[k].size() != nq || reference.v[k].size() != nv) {
      throw std::invalid_argument("StabilizedReferencePlayer: sample " + FormatShort(k) + " has q of size " +
                                  FormatShort(reference.q[k].size()) + " and v of size " +
                                  FormatShort(reference.v[k].size()) + "; model '" + model_->name() +
                                  "' needs " + FormatShort(nq) + " and " + FormatShort(nv));
    }
  };
  Eigen::VectorXd y(nq + nv);
  const std::size_t last = reference.q.size() - 1;
  if (last == 0 || t <= 0.0 || !(reference.period > 0.0)) {
    check(0);
    y << reference.q[0], reference.v[0];
    return y;
  }
  if (t >= reference.duration()) {
    check(last);
    y << reference.q[last], Eigen::VectorXd::Zero(nv);
    return y;
  }
  const double s = t / reference.period;
  const std::size_t k = std::min(static_cast<std::size_t>(std::floor(s)), last - 1);
  const double a = std::clamp(s - static_cast<double>(k), 0.0, 1.0);
  check(k);
  check(k + 1);
  const Eigen::VectorXd& q0 = reference.q[k];
  const Eigen::VectorXd& q1 = reference.q[k + 1];
  Eigen::VectorXd q = (1.0 - a) * q0 + a * q1;
  const Eigen::Quaterniond r0(q0[3], q0[4], q0[5], q0[6]);
  const Eigen::Quaterniond r1(q1[3], q1[4], q1[5], q1[6]);
  const Eigen::Quaterniond r = r0.normalized().slerp(a, r1.normalized());
  q.segment<4>(3) << r.w(), r.x(), r.y(), r.z();
  y << q, (1.0 - a) * reference.v[k] + a * reference.v[k + 1];
  return y;
}

}  // namespace cairn::planning
