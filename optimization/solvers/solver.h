#pragma once

#include <string>

#include <Eigen/Core>

#include "cairn/optimization/mathematical_program.h"
#include "cairn/optimization/solvers/solver_options.h"
#include "cairn/optimization/solvers/solver_result.h"

namespace cairn::optimization {

/// A swappable solver for MathematicalProgram (Ipopt, NLopt, least squares). Create one by type or by name
/// (MakeSolver) and call Solve; a solver is stateless between solves, so one instance may be shared.
///
/// Solve checks, in order: that the program is supported (CheckSupport's sentence becomes the
/// std::invalid_argument message), the initial guess, and that every options key names a known solver; then it
/// times the solver-specific DoSolve.
class Solver {
 public:
  virtual ~Solver();
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  /// The name MakeSolver accepts for this solver, e.g. "ipopt" or "nlopt:LD_SLSQP".
  const std::string& name() const { return name_; }

  /// The SolverOptions key this solver reads ("ipopt", "nlopt" or "least_squares").
  const std::string& options_key() const { return options_key_; }

  /// True if the solver's library is present in this build.
  virtual bool available() const = 0;

  /// Returns "" if the solver can handle `prog`, otherwise one sentence saying why not and what to do.
  std::string CheckSupport(const MathematicalProgram& prog) const;

  /// Solves from prog.initial_guess() with default options.
  SolverResult Solve(const MathematicalProgram& prog) const;

  /// Solves from `initial_guess` (one value per decision variable) with `options`. Throws std::invalid_argument
  /// if the program is unsupported, the guess has the wrong size or a non-finite entry, or an option is unknown
  /// or has the wrong type.
  SolverResult Solve(const MathematicalProgram& prog, const Eigen::Ref<const Eigen::VectorXd>& initial_guess,
                     const SolverOptions& options = SolverOptions()) const;

  /// The SolverOptions keys of every solver: "ipopt", "least_squares", "nlopt".
  static const std::vector<std::string>& known_options_keys();

 protected:
  /// `name` is what MakeSolver accepts; `options_key` the key of SolverOptions the solver reads.
  Solver(std::string name, std::string options_key);

  /// Returns "" or a sentence explaining why `prog` is not supported.
  virtual std::string DoCheckSupport(const MathematicalProgram& prog) const = 0;

  /// Solves; inputs are already validated. Fills everything except wall_time_seconds and solver_name.
  virtual SolverResult DoSolve(const MathematicalProgram& prog, const Eigen::VectorXd& initial_guess,
                               const SolverOptions::OptionMap& options) const = 0;

 private:
  std::string name_;
  std::string options_key_;
};

}  // namespace cairn::optimization
