#include "cairn/common/number_text.h"
#include "cairn/optimization/solvers/ipopt_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include "cairn/common/text_suggestions.h"
#include "cairn/optimization/program_assembly.h"

namespace cairn::optimization {

namespace {

// Ipopt treats bounds beyond +/-1e19 as infinite (nlp_lower_bound_inf / nlp_upper_bound_inf).
constexpr double kIpoptInfinity = 1e20;

std::mutex& IpoptMutex() {
  static std::mutex mutex;
  return mutex;
}

double ToIpoptBound(double value) {
  if (value == std::numeric_limits<double>::infinity()) return kIpoptInfinity;
  if (value == -std::numeric_limits<double>::infinity()) return -kIpoptInfinity;
  return value;
}

// Adapts a ProgramAssembly to Ipopt's TNLP. Every callback reads or writes the caller's arrays directly.
class ProgramTnlp final : public Ipopt::TNLP {
 public:
  ProgramTnlp(ProgramAssembly* assembly, const Eigen::VectorXd* initial_guess, SolverResult* result)
      : assembly_(assembly), initial_guess_(initial_guess), result_(result) {}

  bool get_nlp_info(Ipopt::Index& n, Ipopt::Index& m, Ipopt::Index& nnz_jac_g, Ipopt::Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = assembly_->num_vars();
    m = assembly_->num_constraints();
    nnz_jac_g = assembly_->jacobian_nonzeros();
    nnz_h_lag = assembly_->has_hessian() ? static_cast<Ipopt::Index>(assembly_->hessian_rows().size()) : 0;
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Ipopt::Index n, Ipopt::Number* x_l, Ipopt::Number* x_u, Ipopt::Index m, Ipopt::Number* g_l,
                       Ipopt::Number* g_u) override {
    for (Ipopt::Index i = 0; i < n; ++i) {
      x_l[i] = ToIpoptBound(assembly_->variable_lower_bounds()[i]);
      x_u[i] = ToIpoptBound(assembly_->variable_upper_bounds()[i]);
    }
    for (Ipopt::Index i = 0; i < m; ++i) {
      g_l[i] = ToIpoptBound(assembly_->constraint_lower_bounds()[i]);
      g_u[i] = ToIpoptBound(assembly_->constraint_upper_bounds()[i]);
    }
    return true;
  }

  bool get_starting_point(Ipopt::Index n, bool init_x, Ipopt::Number* x, bool init_z, Ipopt::Number*,
                          Ipopt::Number*, Ipopt::Index, bool init_lambda, Ipopt::Number*) override {
    // Without warm-start options Ipopt asks for x only.
    if (init_z || init_lambda) return false;
    if (init_x) std::copy(initial_guess_->data(), initial_guess_->data() + n, x);
    return true;
  }

  bool eval_f(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number& obj_value) override {
    obj_value = assembly_->EvalCost(x);
    return std::isfinite(obj_value);
  }

  bool eval_grad_f(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number* grad_f) override {
    return std::isfinite(assembly_->EvalCostAndGradient(x, grad_f));
  }

  bool eval_g(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Index, Ipopt::Number* g) override {
    assembly_->EvalConstraints(x, g);
    return true;
  }

  bool eval_jac_g(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Index, Ipopt::Index, Ipopt::Index* iRow,
                  Ipopt::Index* jCol, Ipopt::Number* values) override {
    if (values == nullptr) {
      std::copy(assembly_->jacobian_rows().begin(), assembly_->jacobian_rows().end(), iRow);
      std::copy(assembly_->jacobian_cols().begin(), assembly_->jacobian_cols().end(), jCol);
    } else {
      assembly_->EvalConstraintsAndJacobian(x, nullptr, values);
    }
    return true;
  }

  bool eval_h(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number obj_factor, Ipopt::Index,
              const Ipopt::Number* lambda, bool, Ipopt::Index, Ipopt::Index* iRow, Ipopt::Index* jCol,
              Ipopt::Number* values) override {
    if (!assembly_->has_hessian()) return false;
    if (values == nullptr) {
      std::copy(assembly_->hessian_rows().begin(), assembly_->hessian_rows().end(), iRow);
      std::copy(assembly_->hessian_cols().begin(), assembly_->hessian_cols().end(), jCol);
    } else {
      assembly_->EvalLagrangianHessian(x, obj_factor, lambda, values);
    }
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn, Ipopt::Index n, const Ipopt::Number* x, const Ipopt::Number* z_L,
                         const Ipopt::Number* z_U, Ipopt::Index m, const Ipopt::Number*, const Ipopt::Number* lambda,
                         Ipopt::Number obj_value, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    result_->x = Eigen::Map<const Eigen::VectorXd>(x, n);
    result_->objective = obj_value;
    result_->constraint_duals = Eigen::Map<const Eigen::VectorXd>(lambda, m);
    result_->bound_duals =
        Eigen::Map<const Eigen::VectorXd>(z_U, n) - Eigen::Map<const Eigen::VectorXd>(z_L, n);
  }

 private:
  ProgramAssembly* assembly_;
  const Eigen::VectorXd* initial_guess_;
  SolverResult* result_;
};

const char* TypeName(Ipopt::RegisteredOptionType type) {
  switch (type) {
    case Ipopt::OT_Number:
      return "a number";
    case Ipopt::OT_Integer:
      return "an integer";
    case Ipopt::OT_String:
      return "a string";
    default:
      return "of unknown type";
  }
}

// Cairn's own option (Ipopt knows only the Lagrangian's Hessian, not how a least-squares cost forms it).
constexpr const char* kLeastSquaresHessianOption = "least_squares_hessian";

ProgramAssembly::LeastSquaresHessian LeastSquaresHessianOption(const SolverOptions::OptionMap& options) {
  const auto it = options.find(kLeastSquaresHessianOption);
  if (it == options.end()) return ProgramAssembly::LeastSquaresHessian::kExact;
  const std::string* text = std::get_if<std::string>(&it->second);
  if (text != nullptr && *text == "exact") return ProgramAssembly::LeastSquaresHessian::kExact;
  if (text != nullptr && *text == "gauss-newton") return ProgramAssembly::LeastSquaresHessian::kGaussNewton;
  throw std::invalid_argument(std::string("IpoptSolver: option '") + kLeastSquaresHessianOption + "' is " +
                              SolverOptions::ToString(it->second) + "; give 'exact' (J'J plus the residuals' curvature) " +
                              "or 'gauss-newton' (J'J alone).");
}

void ApplyOption(Ipopt::IpoptApplication* app, const std::string& name, const SolverOptions::Value& value) {
  Ipopt::SmartPtr<const Ipopt::RegisteredOption> option = app->RegOptions()->GetOption(name);
  if (!Ipopt::IsValid(option)) {
    std::vector<std::string> names;
    for (const auto& entry : app->RegOptions()->RegisteredOptionsList()) names.push_back(entry.first);
    const std::vector<std::string> closest = ClosestNames(name, names);
    throw std::invalid_argument("IpoptSolver: unknown Ipopt option '" + name + "'" +
                                (closest.empty() ? "" : "; did you mean " + QuotedList(closest) + "?") +
                                " (see Ipopt's option reference for all " + cairn::FormatShort(names.size()) +
                                " names).");
  }
  // Values are checked against the registered option first: Ipopt's own setters print to stdout on failure.
  bool accepted = false;
  const Ipopt::RegisteredOptionType type = option->Type();
  if (type == Ipopt::OT_Number && (std::holds_alternative<double>(value) || std::holds_alternative<int>(value))) {
    const double number =
        std::holds_alternative<double>(value) ? std::get<double>(value) : static_cast<double>(std::get<int>(value));
    accepted = option->IsValidNumberSetting(number) && app->Options()->SetNumericValue(name, number);
  } else if (type == Ipopt::OT_Integer && std::holds_alternative<int>(value)) {
    accepted = option->IsValidIntegerSetting(std::get<int>(value)) &&
               app->Options()->SetIntegerValue(name, std::get<int>(value));
  } else if (type == Ipopt::OT_String && std::holds_alternative<std::string>(value)) {
    accepted = option->IsValidStringSetting(std::get<std::string>(value)) &&
               app->Options()->SetStringValue(name, std::get<std::string>(value));
  } else {
    throw std::invalid_argument("IpoptSolver: option '" + name + "' is " + TypeName(type) + " but was given " +
                                SolverOptions::ToString(value) + "; pass " + TypeName(type) + ".");
  }
  if (!accepted) {
    std::string valid;
    if (type == Ipopt::OT_String) {
      std::vector<std::string> strings;
      for (const auto& entry : option->GetValidStrings()) strings.push_back(entry.value_);
      valid = "; valid values are " + QuotedList(strings);
    }
    throw std::invalid_argument("IpoptSolver: Ipopt rejected the value " + SolverOptions::ToString(value) +
                                " for option '" + name + "'" + valid +
                                (valid.empty() ? " (it is out of the option's range)" : "") + ".");
  }
}

SolutionStatus MapStatus(Ipopt::ApplicationReturnStatus status) {
  switch (status) {
    case Ipopt::Solve_Succeeded:
    case Ipopt::Solved_To_Acceptable_Level:
      return SolutionStatus::kSolved;
    case Ipopt::Infeasible_Problem_Detected:
      return SolutionStatus::kInfeasible;
    case Ipopt::Diverging_Iterates:
      return SolutionStatus::kUnbounded;
    case Ipopt::Maximum_Iterations_Exceeded:
      return SolutionStatus::kIterationLimit;
    case Ipopt::Maximum_CpuTime_Exceeded:
      return SolutionStatus::kTimeLimit;
    case Ipopt::Restoration_Failed:
    case Ipopt::Error_In_Step_Computation:
    case Ipopt::Invalid_Number_Detected:
    case Ipopt::Search_Direction_Becomes_Too_Small:
      return SolutionStatus::kNumericalFailure;
    default:
      return SolutionStatus::kFailed;
  }
}

const char* StatusName(Ipopt::ApplicationReturnStatus status) {
  switch (status) {
    case Ipopt::Solve_Succeeded: return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level: return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected: return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small: return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates: return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop: return "User_Requested_Stop";
    case Ipopt::Feasible_Point_Found: return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded: return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed: return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation: return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded: return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom: return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition: return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option: return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected: return "Invalid_Number_Detected";
    case Ipopt::Unrecoverable_Exception: return "Unrecoverable_Exception";
    case Ipopt::NonIpopt_Exception_Thrown: return "NonIpopt_Exception_Thrown";
    case Ipopt::Insufficient_Memory: return "Insufficient_Memory";
    case Ipopt::Internal_Error: return "Internal_Error";
  }
  return "unknown Ipopt status";
}

}  // namespace

IpoptSolver::IpoptSolver() : Solver("ipopt", "ipopt") {}

std::string IpoptSolver::DoCheckSupport(const MathematicalProgram& prog) const {
  if (prog.num_vars() == 0) {
    return "IpoptSolver: the program has no decision variables; add some with NewContinuousVariables.";
  }
  return "";
}

SolverResult IpoptSolver::DoSolve(const MathematicalProgram& prog, const Eigen::VectorXd& initial_guess,
                                  const SolverOptions::OptionMap& options) const {
  ProgramAssembly assembly(prog, LeastSquaresHessianOption(options));
  SolverResult result;
  result.x = initial_guess;

  std::lock_guard<std::mutex> lock(IpoptMutex());
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->RethrowNonIpoptException(true);  // An evaluator's exception reaches the caller with its own message.
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetStringValue("hessian_approximation", assembly.has_hessian() ? "exact" : "limited-memory");
  for (const auto& [name, value] : options) {
    if (name == "hessian_approximation" && value == SolverOptions::Value(std::string("exact")) &&
        !assembly.has_hessian()) {
      throw std::invalid_argument(
          "IpoptSolver: hessian_approximation = 'exact' needs a Hessian from every cost and constraint, but some "
          "term (an evaluator or residual that declares no Hessian pattern) has none; use "
          "'limited-memory' or provide Hessians.");
    }
    if (name == kLeastSquaresHessianOption) continue;
    ApplyOption(app.operator->(), name, value);
  }
  // Initialize("") skips ./ipopt.opt, which Initialize() would silently read from the working directory.
  const Ipopt::ApplicationReturnStatus init_status = app->Initialize("");
  if (init_status != Ipopt::Solve_Succeeded) {
    throw std::runtime_error(std::string("IpoptSolver: Ipopt failed to initialise (") + StatusName(init_status) +
                             "); check the options passed under 'ipopt'.");
  }
  Ipopt::SmartPtr<Ipopt::TNLP> tnlp = new ProgramTnlp(&assembly, &initial_guess, &result);
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(tnlp);
  result.status = MapStatus(status);
  result.message = std::string("Ipopt: ") + StatusName(status);
  if (Ipopt::IsValid(app->Statistics())) result.iterations = app->Statistics()->IterationCount();
  if (result.x.size() == prog.num_vars()) {
    result.objective = assembly.EvalCost(result.x.data());
    result.constraint_violation = assembly.ConstraintViolation(result.x.data());
    if (result.status != SolutionStatus::kSolved && result.constraint_violation > 0.0) {
      result.message += "; largest violation " + assembly.DescribeWorstViolation(result.x.data());
    }
  }
  return result;
}

}  // namespace cairn::optimization
