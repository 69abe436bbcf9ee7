#include "cairn/planning/locomotion/walking_objective.h"

#include <stdexcept>

#include "cairn/common/text_suggestions.h"
#include "cairn/planning/locomotion/step_evaluator.h"

namespace cairn::planning {

const char* to_string(WalkingObjective objective) {
  switch (objective) {
    case WalkingObjective::kComWork:
      return "ecom";
    case WalkingObjective::kComWorkPlusHeat:
      return "ecom_heat";
    case WalkingObjective::kTravelTime:
      return "time";
    case WalkingObjective::kSquaredTorque:
      return "torque";
  }
  return "unknown";
}

const std::vector<std::string>& WalkingObjectiveNames() {
  static const std::vector<std::string> names = {"ecom", "ecom_heat", "time", "torque"};
  return names;
}

WalkingObjective ParseWalkingObjective(const std::string& name) {
  const std::vector<std::string>& names = WalkingObjectiveNames();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<WalkingObjective>(i);
  }
  throw std::invalid_argument("Unknown walking objective '" + name + "'; did you mean " +
                              QuotedList(ClosestNames(name, names, 1)) + "? Valid objectives: " + QuotedList(names) +
                              ".");
}

double ObjectiveValue(WalkingObjective objective, const StepEvaluation& evaluation) {
  switch (objective) {
    case WalkingObjective::kComWork:
      return evaluation.com_work;
    case WalkingObjective::kComWorkPlusHeat:
      return evaluation.com_work + evaluation.heat;
    case WalkingObjective::kTravelTime:
      return evaluation.duration;
    case WalkingObjective::kSquaredTorque:
      return evaluation.squared_torque;
  }
  return evaluation.com_work;
}

}  // namespace cairn::planning
