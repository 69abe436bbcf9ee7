#pragma once

#include <string>
#include <vector>

#include <cairn/multibody/model.h>
#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/walk/walk_run.h>

namespace cairn::planning {

/// One planned step's predictions next to what the plant measured over the step's planned time window [start, end]
/// (the measured values are NaN for a step the walk did not complete).
struct WalkStepComparison {
  int index{0};                   ///< 1 for the plan's first step
  std::string foot;               ///< the foot that swings ("left" or "right")
  double start{0.0}, end{0.0};    ///< planned window, s
  double predicted_rcof{0.0};
  /// The support sole's RCOF (StancePhase::rcof of the stance that holds the middle of the swing), the same without
  /// its landing impact, and of both soles' low-passed net force (the quantity the planner's model predicts).
  double measured_rcof{0.0}, measured_rcof_after_touchdown{0.0}, measured_net_rcof{0.0};
  double mu_allowed{0.0};
  double predicted_com_work{0.0}, predicted_heat{0.0};
  /// E_COM and E_ele spent over the window, J (differences of the samples nearest its ends).
  double measured_com_energy{0.0}, measured_electrical_energy{0.0};
  /// E_ele's Joule heat over the window, J (what predicted_heat predicts).
  double measured_heat{0.0};
  bool completed{false};          ///< the walk lasted to the window's end
};

/// Each step of record.plan against the plant, as `cairn walk` reports it. The windows follow each other from
/// t = 0 with the steps' planned durations; energies are read from the samples nearest the windows' ends, so their
/// resolution is the run's log period.
std::vector<WalkStepComparison> CompareWalkSteps(const WalkRecord& record);

/// Where the soles ended against a stance (the goal's, or the plan's last): the larger of the two soles' horizontal
/// distances from their footholds at record's last sample, m. `soles` names the left and the right sole body (the
/// plant's sole_bodies). Throws std::invalid_argument for a record without samples, fewer than two sole names or a
/// name `robot` has no body of.
double SoleDistance(const multibody::Model& robot, const std::vector<std::string>& soles, const WalkRecord& record,
                    const Stance& stance);

}  // namespace cairn::planning
