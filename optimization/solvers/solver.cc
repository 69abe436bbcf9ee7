#include "cairn/common/number_text.h"
#include "cairn/optimization/solvers/solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "cairn/common/text_suggestions.h"

namespace cairn::optimization {

Solver::Solver(std::string name, std::string options_key)
    : name_(std::move(name)), options_key_(std::move(options_key)) {}

Solver::~Solver() = default;

const std::vector<std::string>& Solver::known_options_keys() {
  static const std::vector<std::string> kKeys = {"ipopt", "least_squares", "nlopt"};
  return kKeys;
}

std::string Solver::CheckSupport(const MathematicalProgram& prog) const {
  if (!available()) return "Solver '" + name_ + "' is not available in this build.";
  return DoCheckSupport(prog);
}

SolverResult Solver::Solve(const MathematicalProgram& prog) const { return Solve(prog, prog.initial_guess()); }

SolverResult Solver::Solve(const MathematicalProgram& prog, const Eigen::Ref<const Eigen::VectorXd>& initial_guess,
                           const SolverOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  const std::string why_not = CheckSupport(prog);
  if (!why_not.empty()) throw std::invalid_argument(why_not);
  if (initial_guess.size() != prog.num_vars()) {
    throw std::invalid_argument("Solver '" + name_ + "': the initial guess has " +
                                cairn::FormatShort(initial_guess.size()) + " entries but the program has " +
                                cairn::FormatShort(prog.num_vars()) + " variables; pass one value per variable.");
  }
  for (int i = 0; i < initial_guess.size(); ++i) {
    if (!std::isfinite(initial_guess[i])) {
      throw std::invalid_argument("Solver '" + name_ + "': the initial guess of variable '" + prog.VariableName(i) +
                                  "' is " + cairn::FormatShort(initial_guess[i]) + "; pass a finite value.");
    }
  }
  for (const std::string& key : options.solver_keys()) {
    const auto& keys = known_options_keys();
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      const std::vector<std::string> closest = ClosestNames(key, keys, 1);
      throw std::invalid_argument("SolverOptions: unknown solver key '" + key + "'; valid keys are " +
                                  QuotedList(keys) + (closest.empty() ? "" : " (did you mean '" + closest[0] + "'?)") +
                                  ".");
    }
  }
  SolverResult result = DoSolve(prog, initial_guess, options.Get(options_key_));
  result.solver_name = name_;
  result.wall_time_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace cairn::optimization
