#pragma once

#include <string>
#include <vector>

#include "cairn/optimization/solvers/solver.h"

namespace cairn::optimization {

/// NLopt: any of its algorithms by name, alone or as a chain of stages (e.g. a global DIRECT search polished
/// by SLSQP, as the footstep oracle of the thesis does).
///
/// Algorithms are named as NLopt spells them ("LD_SLSQP", "GN_ORIG_DIRECT", "LN_COBYLA") or by the part after
/// the prefix when that is unambiguous ("SLSQP", "ORIG_DIRECT", "COBYLA"); stages are joined by '+' and each
/// starts from the previous stage's best point: `NloptSolver("ORIG_DIRECT+SLSQP")`. MakeSolver accepts
/// "nlopt:<stages>".
///
/// Constraints: each stacked constraint row lb <= g(x) <= ub becomes an NLopt equality (lb == ub) or one or
/// two inequalities (a two-sided row is registered twice, g - ub <= 0 and lb - g <= 0); bounding boxes become
/// NLopt's bounds. Gradients come from the program's sparse Jacobians scattered into NLopt's dense layout.
///
/// Options (key "nlopt"): maxeval (integer), maxtime (seconds), xtol_rel, xtol_abs, ftol_rel, ftol_abs,
/// stopval, constraint_tol (number; NLopt's constraint tolerance and the feasibility test of the result,
/// default 1e-8), population (integer), seed (integer, default 1: stochastic algorithms such as ISRES, CRS2,
/// ESCH and MLSL are seeded with it before their stage, so results are reproducible; NLopt's generator is
/// process-wide, so concurrent stochastic solves are not reproducible). A name applies to every stage;
/// "<STAGE>.<name>" (e.g.
/// "GN_ORIG_DIRECT.maxeval") to one stage only. Defaults: local stages xtol_rel = 1e-10, ftol_rel = 1e-14,
/// maxeval = 100000; global stages maxeval = 2000, because DIRECT-type searches never stop on their own.
/// Ranges (std::invalid_argument otherwise): maxeval >= 1, population >= 0, seed >= 0, maxtime > 0, the
/// tolerances and constraint_tol finite and >= 0, stopval not NaN.
///
/// Status (of the last stage): a final point that violates the constraints by more than constraint_tol is
/// kInfeasible; otherwise converged (ftol/xtol/stopval) and round-off-limited endings are kSolved (SLSQP ends
/// round-off-limited when the tolerances ask for more than double precision gives, e.g. on HS100);
/// maxeval -> kIterationLimit; maxtime -> kTimeLimit; an objective below -1e20 (the default stopval) or a
/// non-finite point -> kUnbounded; NLopt's generic failures -> kNumericalFailure. NLopt reports no duals.
/// Thread safety: each Solve builds its own NLopt objects, so concurrent solves are independent.
class NloptSolver final : public Solver {
 public:
  /// Parses the stage list; throws std::invalid_argument naming an unknown or ambiguous algorithm together with
  /// the valid names.
  explicit NloptSolver(const std::string& algorithms);

  /// NLopt's names of the stages, in order (e.g. {"GN_ORIG_DIRECT", "LD_SLSQP"}).
  const std::vector<std::string>& stages() const { return stages_; }

  /// Always true: NLopt is a required dependency of Cairn::optimization.
  bool available() const override { return true; }

  /// Every algorithm name NLopt 2.7 defines, in NLopt's order.
  static std::vector<std::string> AlgorithmNames();

 private:
  // Per-stage properties, looked up once at construction rather than by name on every solve.
  enum StageFlag : unsigned char { kGlobal = 1, kStochastic = 2, kEqualities = 4, kInequalities = 8 };
  struct ParsedStages {
    std::string name;
    std::vector<std::string> stages;
    std::vector<int> algorithms;
    std::vector<unsigned char> flags;
  };
  static ParsedStages Parse(const std::string& algorithms);
  explicit NloptSolver(ParsedStages parsed);

  std::string DoCheckSupport(const MathematicalProgram& prog) const override;
  SolverResult DoSolve(const MathematicalProgram& prog, const Eigen::VectorXd& initial_guess,
                       const SolverOptions::OptionMap& options) const override;

  std::vector<std::string> stages_;
  std::vector<int> algorithms_;  // nlopt::algorithm values, kept as int so nlopt.hpp stays out of this header.
  std::vector<unsigned char> flags_;  // StageFlag bits per stage
};

}  // namespace cairn::optimization
