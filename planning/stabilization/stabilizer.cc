#include <cairn/planning/stabilization/stabilizer.h>

#include <exception>
#include <stdexcept>
#include <utility>

#include <cairn/planning/stabilization/stabilize_trajectory.h>
#include <cairn/systems/framework/state.h>

namespace cairn::planning {

namespace {

StabilizedTrajectory NotStabilizedYet() {
  StabilizedTrajectory reference;
  reference.report.message = "not stabilised yet: the stabilisation runs at initialization, on forced events and "
                             "when the input trajectory changes";
  return reference;
}

WholeBodyTrajectory NoSource() {
  WholeBodyTrajectory source;
  source.report.status = "none";
  return source;
}

// Whether two trajectories would stabilise alike (the report's wall times do not matter).
bool SameTrajectory(const WholeBodyTrajectory& a, const WholeBodyTrajectory& b) {
  if (a.found != b.found || a.waypoints.size() != b.waypoints.size() || a.report.status != b.report.status ||
      a.report.message != b.report.message) {
    return false;
  }
  for (std::size_t i = 0; i < a.waypoints.size(); ++i) {
    const WholeBodyWaypoint& x = a.waypoints[i];
    const WholeBodyWaypoint& y = b.waypoints[i];
    if (x.time != y.time || x.single_support != y.single_support || x.contacts != y.contacts ||
        x.q.size() != y.q.size() || x.q != y.q) {
      return false;
    }
  }
  return true;
}

}  // namespace

Stabilizer::Stabilizer(std::shared_ptr<const multibody::Model> model, const StabilizerOptions& options)
    : model_(std::move(model)), options_(options) {
  if (model_ == nullptr) throw std::invalid_argument("Stabilizer: the robot model is null");
  ValidateStabilizerOptions(options_);
  DeclareAbstractInputPort("trajectory", systems::Value<WholeBodyTrajectory>(WholeBodyTrajectory()));
  source_state_ = DeclareAbstractState(systems::Value<WholeBodyTrajectory>(NoSource()));
  reference_state_ = DeclareAbstractState(systems::Value<StabilizedTrajectory>(NotStabilizedYet()));
  const int state = reference_state_;
  DeclareAbstractOutputPort(
      "reference", systems::Value<StabilizedTrajectory>(NotStabilizedYet()),
      [state](const systems::Context& c, systems::AbstractValue* v) { v->SetFrom(c.get_abstract_state_value(state)); },
      {abstract_state_ticket(state)});
  DeclareInitializationUnrestrictedUpdateEvent(
      [this](const systems::Context& c, systems::State* s) { return Update(c, s, false); });
  DeclareForcedUnrestrictedUpdateEvent(
      [this](const systems::Context& c, systems::State* s) { return Update(c, s, false); });
  DeclarePerStepUnrestrictedUpdateEvent(
      [this](const systems::Context& c, systems::State* s) { return Update(c, s, true); });
}

systems::EventStatus Stabilizer::Update(const systems::Context& context, systems::State* next,
                                        bool only_if_changed) const {
  const auto& trajectory = get_trajectory_input_port().Eval<WholeBodyTrajectory>(context);
  if (only_if_changed && SameTrajectory(trajectory, context.get_abstract_state<WholeBodyTrajectory>(source_state_))) {
    return systems::EventStatus::DidNothing();
  }
  StabilizedTrajectory reference;
  if (!trajectory.found) {
    reference.report.message = "no trajectory to stabilise: " + trajectory.report.message;
  } else {
    try {
      reference = StabilizeTrajectory(model_, trajectory, options_);
    } catch (const std::exception& error) {
      // A trajectory this stage cannot use is a result for the diagram, as a plan that is not found is.
      reference = StabilizedTrajectory();
      reference.report.method = options_.method;
      reference.report.message = error.what();
    }
  }
  next->get_mutable_abstract_state<WholeBodyTrajectory>(source_state_) = trajectory;
  next->get_mutable_abstract_state<StabilizedTrajectory>(reference_state_) = std::move(reference);
  return systems::EventStatus::Succeeded();
}

}  // namespace cairn::planning
