#include "cairn/optimization/solvers/solver_result.h"

namespace cairn::optimization {

const char* to_string(SolutionStatus status) {
  switch (status) {
    case SolutionStatus::kSolved:
      return "solved";
    case SolutionStatus::kInfeasible:
      return "infeasible";
    case SolutionStatus::kUnbounded:
      return "unbounded";
    case SolutionStatus::kIterationLimit:
      return "iteration limit";
    case SolutionStatus::kTimeLimit:
      return "time limit";
    case SolutionStatus::kNumericalFailure:
      return "numerical failure";
    case SolutionStatus::kFailed:
      return "failed";
  }
  return "unknown";
}

}  // namespace cairn::optimization
