#pragma once

#include <string>
#include <vector>

#include "cairn/planning/footstep/biped_geometry.h"
#include "cairn/planning/walk/walk_run.h"

namespace cairn::cli {

/// One planned step's predictions next to what the plant measured over the step's planned time window (the
/// measured values are NaN for a step the walk did not complete).
struct WalkStepComparison {
  int index{0};
  std::string foot;               ///< the foot that swings
  double start{0.0}, end{0.0};    ///< planned window, s
  double predicted_rcof{0.0}, measured_rcof{0.0};
  /// The support stance's RCOF without its landing impact, and of both soles' low-passed net force (StancePhase).
  double measured_rcof_after_touchdown{0.0}, measured_net_rcof{0.0};
  double mu_allowed{0.0};
  double predicted_com_work{0.0}, predicted_heat{0.0};
  double measured_com_energy{0.0}, measured_electrical_energy{0.0};
  bool completed{false};
};

/// Top view: the plan's footholds (the support polygons' feet) in grey, the reference ZMP, the measured ZMP and
/// the measured COM, with metric axes and a legend. Throws std::runtime_error if PNG encoding fails.
std::string WalkZmpPng(const planning::WalkRecord& record, const planning::BipedGeometry& geometry);

/// The COM's x and y against time: the stabilised reference's and the plant's, with axes and a legend.
std::string WalkComPng(const planning::WalkRecord& record);

/// Per step: predicted against measured RCOF (with mu_allowed), and predicted against measured energy.
std::string WalkStepsPng(const std::vector<WalkStepComparison>& steps);

}  // namespace cairn::cli
