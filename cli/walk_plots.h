#pragma once

#include <string>
#include <vector>

#include "cairn/planning/footstep/biped_geometry.h"
#include "cairn/planning/walk/walk_run.h"
#include "cairn/planning/walk/walk_step_comparison.h"

namespace cairn::cli {

using planning::WalkStepComparison;

/// Top view: the plan's footholds (the support polygons' feet) in grey, the reference ZMP, the measured ZMP and
/// the measured COM, with metric axes and a legend. Throws std::runtime_error if PNG encoding fails.
std::string WalkZmpPng(const planning::WalkRecord& record, const planning::BipedGeometry& geometry);

/// The COM's x and y against time: the stabilised reference's and the plant's, with axes and a legend.
std::string WalkComPng(const planning::WalkRecord& record);

/// Per step: predicted against measured RCOF (with mu_allowed), and predicted against measured energy.
std::string WalkStepsPng(const std::vector<WalkStepComparison>& steps);

}  // namespace cairn::cli
