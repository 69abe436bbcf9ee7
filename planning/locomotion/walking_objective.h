#pragma once

#include <string>
#include <vector>

namespace cairn::planning {

struct StepEvaluation;

/// What a step's cost measures (thesis Table 2.1's objectives).
enum class WalkingObjective {
  kComWork,          ///< "ecom": COM mechanical work, eq. 2.1 (J)
  kComWorkPlusHeat,  ///< "ecom_heat": COM work plus motor heat, the second term of eq. 2.6 (J)
  kTravelTime,       ///< "time": step duration t_ds + t_sw (s)
  kSquaredTorque,    ///< "torque": integral of the squared static leg torques (N^2 m^2 s)
};

/// The objective's name: "ecom", "ecom_heat", "time" or "torque".
const char* to_string(WalkingObjective objective);

/// Every objective name, in enum order.
const std::vector<std::string>& WalkingObjectiveNames();

/// Parses a name from WalkingObjectiveNames(); throws std::invalid_argument naming the bad value, the closest
/// valid names and the full list.
WalkingObjective ParseWalkingObjective(const std::string& name);

/// The objective's value for an evaluated step.
double ObjectiveValue(WalkingObjective objective, const StepEvaluation& evaluation);

}  // namespace cairn::planning
