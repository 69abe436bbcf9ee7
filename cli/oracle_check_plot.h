#pragma once

#include <string>

#include "cairn/planning/locomotion/oracle_held_out_error.h"

namespace cairn::cli {

/// PNG bytes of `cairn oracle check`'s picture: the table's predicted cost against its source's measured cost for
/// each held-out step both call feasible, with the line of perfect prediction, and the disagreements on
/// feasibility and the error figures in the legend. `unit` labels the axes ("J", "s"). Throws std::runtime_error
/// if PNG encoding fails.
std::string OracleHeldOutPng(const planning::OracleHeldOutError& error, const std::string& title,
                             const std::string& unit);

}  // namespace cairn::cli
