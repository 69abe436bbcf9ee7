#include "cairn/perception/friction/contact_friction_learner.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

namespace cairn::perception {

ContactFrictionLearner::ContactFrictionLearner(MaterialRegistry registry, double period, double radius,
                                               double height_window)
    : period_(period), radius_(radius), height_window_(height_window), num_labels_(registry.size()) {
  if (registry.size() == 0) {
    throw std::invalid_argument("ContactFrictionLearner: the registry is empty; give the materials to learn about");
  }
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("ContactFrictionLearner: period " + cairn::FormatShort(period) +
                                " s must be positive and finite (e.g. 0.1)");
  }
  for (const auto& [value, name] : {std::pair{radius, "radius"}, {height_window, "height_window"}}) {
    if (!(value > 0.0 && value <= 10.0)) {
      throw std::invalid_argument(std::string("ContactFrictionLearner: ") + name + " " + cairn::FormatShort(value) +
                                  " m must be in (0, 10] (e.g. 0.05, about a sole's half-width)");
    }
  }
  DeclareAbstractInputPort("contacts", systems::Value<std::vector<FootContact>>(std::vector<FootContact>()));
  DeclareAbstractInputPort("friction_points", systems::Value<FrictionPointCloud>(FrictionPointCloud()));
  ContactLearning initial;
  initial.registry = std::move(registry);
  state_ = DeclareAbstractState(systems::Value<ContactLearning>(initial));
  const int state = state_;
  DeclareAbstractOutputPort(
      "registry", systems::Value<MaterialRegistry>(initial.registry),
      [state](const systems::Context& c, systems::AbstractValue* v) {
        v->get_mutable_value<MaterialRegistry>() = c.get_abstract_state<ContactLearning>(state).registry;
      },
      {abstract_state_ticket(state)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, 0.0, &ContactFrictionLearner::Learn);
  DeclareForcedUnrestrictedUpdateEvent(&ContactFrictionLearner::Learn);
}

const ContactLearning& ContactFrictionLearner::learning(const systems::Context& context) const {
  ValidateContext(context);
  return context.get_abstract_state<ContactLearning>(state_);
}

bool ContactFrictionLearner::MixtureUnder(const FrictionPointCloud& points, const Eigen::Vector3d& position_W,
                                          Eigen::VectorXd* mixture) const {
  if (points.weights.rows() != points.size() || (points.size() > 0 && points.weights.cols() != num_labels_)) {
    throw std::invalid_argument("ContactFrictionLearner: the friction points have " +
                                cairn::FormatShort(points.weights.rows()) + " x " +
                                cairn::FormatShort(points.weights.cols()) + " weights for " +
                                cairn::FormatShort(points.size()) + " points; give one row of " +
                                cairn::FormatShort(num_labels_) + " registry-order weights per point");
  }
  mixture->setZero(num_labels_);
  int n = 0;
  for (int i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points.points_W[static_cast<std::size_t>(i)];
    // Written so that a NaN coordinate matches nothing.
    if (!(std::hypot(p.x() - position_W.x(), p.y() - position_W.y()) <= radius_)) continue;
    if (!(std::abs(p.z() - position_W.z()) <= height_window_)) continue;
    *mixture += points.weights.row(i).transpose().cast<double>();
    ++n;
  }
  const double total = mixture->sum();
  if (n == 0 || !(total > 0.0)) return false;
  *mixture /= total;
  return true;
}

void ContactFrictionLearner::Learn(const systems::Context& context, systems::State* next) const {
  const auto& contacts = get_contacts_input_port().Eval<std::vector<FootContact>>(context);
  ContactLearning& learning = next->get_mutable_abstract_state<ContactLearning>(state_);
  if (static_cast<int>(contacts.size()) < learning.seen) {
    throw std::logic_error("ContactFrictionLearner: the contact log shrank from " +
                           cairn::FormatShort(learning.seen) + " to " + cairn::FormatShort(contacts.size()) +
                           " contacts; its input must be an append-only log (start a new context to learn afresh)");
  }
  if (static_cast<int>(contacts.size()) == learning.seen) return;
  const auto& points = get_friction_points_input_port().Eval<FrictionPointCloud>(context);
  Eigen::VectorXd mixture;
  for (std::size_t k = static_cast<std::size_t>(learning.seen); k < contacts.size(); ++k) {
    ++learning.seen;
    if (!MixtureUnder(points, contacts[k].position_W, &mixture)) {
      ++learning.skipped;
      continue;
    }
    try {
      learning.registry.UpdateFromContact(mixture, contacts[k].observation);
      ++learning.learned;
    } catch (const std::invalid_argument&) {
      // The registry cannot use it (a bad value, or materials under the foot that cannot learn): a contact the
      // learner reads once and sets aside, rather than one that stops every later update.
      ++learning.rejected;
    }
  }
}

}  // namespace cairn::perception
