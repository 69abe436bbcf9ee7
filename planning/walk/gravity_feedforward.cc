#include <cairn/planning/walk/gravity_feedforward.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/gravity_torques.h>
#include <cairn/multibody/plant/sole_state.h>

namespace cairn::planning {

GravityFeedforward::GravityFeedforward(std::shared_ptr<const multibody::Model> model,
                                       std::vector<std::string> sole_bodies, double gain)
    : model_(std::move(model)), gain_(gain) {
  if (model_ == nullptr) throw std::invalid_argument("GravityFeedforward: the robot model is null");
  if (model_->num_bodies() < 2 || model_->joint(1).type != multibody::JointType::kFloating) {
    throw std::invalid_argument("GravityFeedforward: model '" + model_->name() +
                                "' has no floating base; load the URDF with a floating base");
  }
  if (!(std::isfinite(gain_) && gain_ >= 0.0 && gain_ <= 1.0)) {
    throw std::invalid_argument("GravityFeedforward: gain " + FormatShort(gain_) + " must be in [0, 1]");
  }
  if (sole_bodies.size() != 2) {
    throw std::invalid_argument("GravityFeedforward: " + FormatShort(sole_bodies.size()) +
                                " sole bodies given; name the left and the right sole");
  }
  for (int side = 0; side < 2; ++side) {
    const std::string& name = sole_bodies[static_cast<std::size_t>(side)];
    int body = -1;
    if (model_->HasBody(name)) {
      body = model_->GetBodyIndex(name);
    } else if (model_->HasFrame(name)) {
      body = model_->frame(model_->GetFrameIndex(name)).body;
    } else {
      throw std::invalid_argument("GravityFeedforward: model '" + model_->name() + "' has no body or frame '" + name +
                                  "'; name the sole bodies of its feet");
    }
    off_chain_[side] = Eigen::VectorXd::Ones(model_->nv());
    for (; body > 0; body = model_->parent(body)) {
      const multibody::Joint& joint = model_->joint(body);
      off_chain_[side].segment(joint.idx_v, joint.nv).setZero();
    }
  }
  const int n = model_->nq() + model_->nv();
  DeclareVectorInputPort("state", n);
  DeclareAbstractInputPort("contacts", systems::Value<std::vector<multibody::SoleState>>(
                                           std::vector<multibody::SoleState>(2)));
  scratch_ = DeclarePerContextStorage(systems::Value<multibody::Data>(multibody::Data(*model_)));
  DeclareVectorOutputPort(
      "torque", model_->nv(),
      [this](const systems::Context& context, Eigen::VectorXd* torque) {
        const auto& soles = get_contacts_input_port().Eval<std::vector<multibody::SoleState>>(context);
        if (soles.size() != 2) {
          throw std::invalid_argument("GravityFeedforward: the contacts input has " + FormatShort(soles.size()) +
                                      " soles; connect the HumanoidPlant's `contacts` (left, right)");
        }
        const Eigen::VectorXd& state = get_state_input_port().Eval<Eigen::VectorXd>(context);
        Compute(state.head(model_->nq()), soles[0].loaded, soles[1].loaded,
                &GetMutablePerContextStorage<multibody::Data>(context, scratch_), torque);
      },
      {input_port_ticket(0), input_port_ticket(1)});
}

Eigen::VectorXd GravityFeedforward::Torques(const Eigen::VectorXd& q, bool left_loaded, bool right_loaded) const {
  if (q.size() != model_->nq()) {
    throw std::invalid_argument("GravityFeedforward: q has " + FormatShort(q.size()) + " entries; the model has nq = " +
                                FormatShort(model_->nq()));
  }
  multibody::Data data(*model_);
  Eigen::VectorXd torque(model_->nv());
  Compute(q, left_loaded, right_loaded, &data, &torque);
  return torque;
}

void GravityFeedforward::Compute(const Eigen::Ref<const Eigen::VectorXd>& q, bool left_loaded, bool right_loaded,
                                 multibody::Data* data, Eigen::VectorXd* torque) const {
  *torque = gain_ * multibody::GravityTorques(*model_, *data, q);
  const int base_nv = model_->joint(1).nv;
  torque->head(base_nv).setZero();  // the base is not actuated
  if (left_loaded) torque->array() *= off_chain_[0].array();
  if (right_loaded) torque->array() *= off_chain_[1].array();
}

}  // namespace cairn::planning
