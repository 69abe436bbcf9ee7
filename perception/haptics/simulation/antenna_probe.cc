#include "cairn/perception/haptics/simulation/antenna_probe.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

namespace cairn::perception {

AntennaProbe::AntennaProbe(const SimulatedAntenna::Options& antenna, std::vector<HapticSceneObject> objects_W,
                           const Eigen::Isometry3d& X_CA, int descriptor_lines, double period, double offset)
    : antenna_(antenna), objects_W_(std::move(objects_W)), X_CA_(X_CA) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("AntennaProbe: period " + FormatShort(period) +
                                " s must be positive and finite (e.g. 0.5)");
  }
  if (!(offset >= 0.0) || !std::isfinite(offset)) {
    throw std::invalid_argument("AntennaProbe: offset " + FormatShort(offset) + " s must be non-negative");
  }
  DeclareAbstractInputPort("plan", systems::Value<InteractionPlan>(InteractionPlan{}));
  DeclareAbstractInputPort("descriptor", systems::Value<AffordanceDescriptor>(AffordanceDescriptor(descriptor_lines)));
  DeclareAbstractInputPort("X_WC", systems::Value<Eigen::Isometry3d>(Eigen::Isometry3d::Identity()));
  HapticOutcome none;
  none.descriptor = AffordanceDescriptor(descriptor_lines);
  outcome_state_ = DeclareAbstractState(systems::Value<HapticOutcome>(none));
  count_state_ = DeclareDiscreteState(Eigen::Vector2d::Zero());
  const int outcome = outcome_state_;
  DeclareAbstractOutputPort(
      "outcome", systems::Value<HapticOutcome>(none),
      [outcome](const systems::Context& c, systems::AbstractValue* v) { v->SetFrom(c.get_abstract_state_value(outcome)); },
      {abstract_state_ticket(outcome)});
  DeclareStateOutputPort("interactions", count_state_);
  DeclarePeriodicUnrestrictedUpdateEvent(period, offset, &AntennaProbe::Probe);
}

void AntennaProbe::Probe(const systems::Context& context, systems::State* next) const {
  const InteractionPlan& plan = get_plan_input_port().Eval<InteractionPlan>(context);
  if (plan.targets_C.empty()) return;
  const Eigen::Isometry3d X_AC = X_CA_.inverse();
  std::vector<Eigen::Vector3d> targets_A;
  targets_A.reserve(plan.targets_C.size());
  for (const Eigen::Vector3d& t : plan.targets_C) targets_A.push_back(X_AC * t);
  const Eigen::Isometry3d X_WA = get_pose_input_port().Eval<Eigen::Isometry3d>(context) * X_CA_;
  const AntennaInteraction result = antenna_.Probe(targets_A, objects_W_, X_WA);
  HapticOutcome& outcome = next->get_mutable_abstract_state<HapticOutcome>(outcome_state_);
  ++outcome.sequence;
  outcome.traversable = !result.blocked;
  outcome.descriptor = get_descriptor_input_port().Eval<AffordanceDescriptor>(context);
  Eigen::VectorXd& counts = next->get_mutable_discrete_state().get_mutable_value(count_state_);
  counts[0] += 1.0;
  counts[1] = static_cast<double>(plan.targets_C.size());
}

}  // namespace cairn::perception
