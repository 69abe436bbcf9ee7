#include "cairn/perception/haptics/interaction_planner.h"

namespace cairn::perception {

InteractionPlanner::InteractionPlanner() : InteractionPlanner(HapticInteractionPlanner::Options{}) {}

InteractionPlanner::InteractionPlanner(const HapticInteractionPlanner::Options& options) : planner_(options) {
  DeclareAbstractInputPort("object_C", systems::Value<Eigen::Matrix3Xd>(Eigen::Matrix3Xd(3, 0)));
  DeclareAbstractInputPort("recall", systems::Value<AffordanceRecall>(AffordanceRecall{}));
  DeclareAbstractOutputPort("plan", systems::Value<InteractionPlan>(InteractionPlan{}),
                            [this](const systems::Context& c, systems::AbstractValue* v) {
                              v->get_mutable_value<InteractionPlan>() =
                                  planner_.Plan(get_object_input_port().Eval<Eigen::Matrix3Xd>(c),
                                                get_recall_input_port().Eval<AffordanceRecall>(c).confidence);
                            });
}

}  // namespace cairn::perception
