#include "cairn/perception/terrain/probe_controller.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

namespace cairn::perception {

ProbeController::ProbeController(const CollapsibilityEstimator::Options& options, double period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("ProbeController: period " + FormatShort(period) +
                                " s must be positive and finite (the force sensor's sample period, e.g. 0.01)");
  }
  const CollapsibilityEstimator estimator(options);
  DeclareVectorInputPort("force", 1);
  DeclareVectorInputPort("probing", 1);
  estimator_state_ = DeclareAbstractState(systems::Value<CollapsibilityEstimator>(estimator));
  flag_state_ = DeclareDiscreteState(Eigen::VectorXd::Zero(1));
  const int e = estimator_state_;
  DeclareVectorOutputPort(
      "collapsibility", 2,
      [e](const systems::Context& c, Eigen::VectorXd* y) {
        const auto& estimator = c.get_abstract_state<CollapsibilityEstimator>(e);
        (*y)[0] = estimator.num_samples() > 0 ? estimator.Collapsibility() : std::numeric_limits<double>::quiet_NaN();
        (*y)[1] = estimator.num_samples();
      },
      {abstract_state_ticket(e)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, 0.0, &ProbeController::Update);
}

void ProbeController::Update(const systems::Context& context, systems::State* next) const {
  const bool probing = get_probing_input_port().Eval<Eigen::VectorXd>(context)[0] >= 0.5;
  Eigen::VectorXd& flag = next->get_mutable_discrete_state().get_mutable_value(flag_state_);
  if (probing) {
    auto& estimator = next->get_mutable_abstract_state<CollapsibilityEstimator>(estimator_state_);
    if (flag[0] < 0.5) estimator.Reset();
    estimator.AddSample(get_force_input_port().Eval<Eigen::VectorXd>(context)[0]);
  }
  flag[0] = probing ? 1.0 : 0.0;
}

}  // namespace cairn::perception
