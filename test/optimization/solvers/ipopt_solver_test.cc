#include "cairn/optimization/solvers/ipopt_solver.h"

#include <cstdio>
#include <fstream>
#include <limits>
#include <thread>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cairn/optimization/function_evaluator.h"
#include "../test_problems.h"
#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using ::testing::HasSubstr;
constexpr double kInf = std::numeric_limits<double>::infinity();

void ExpectSolves(const test::TestProblem& p, double cost_tolerance, double x_tolerance) {
  IpoptSolver solver;
  const SolverResult result = solver.Solve(*p.prog);
  ASSERT_EQ(result.status, SolutionStatus::kSolved) << p.name << ": " << result.message;
  EXPECT_NEAR(result.objective, p.optimal_cost, cost_tolerance) << p.name;
  if (p.optimal_x.size() > 0) {
    EXPECT_LT((result.x - p.optimal_x).cwiseAbs().maxCoeff(), x_tolerance) << p.name;
  }
  EXPECT_LT(result.constraint_violation, 1e-7) << p.name;
  EXPECT_GT(result.iterations, 0);
  EXPECT_EQ(result.solver_name, "ipopt");
}

TEST(IpoptSolverTest, Hs071WithExactHessian) {
  const test::TestProblem p = test::MakeHs071();
  ExpectSolves(p, 1e-6, 1e-6);
  const SolverResult result = IpoptSolver().Solve(*p.prog);
  // Ipopt's published HS071 run: 8 iterations with exact Hessians (limited-memory needs more).
  EXPECT_LE(result.iterations, 10);
  // Multipliers in L = f + lambda' g: the active product >= 25 row pushes down (negative), as Ipopt reports.
  ASSERT_EQ(result.constraint_duals.size(), 2);
  EXPECT_LT(result.constraint_duals[0], 0.0);
  ASSERT_EQ(result.bound_duals.size(), 4);
  EXPECT_LT(result.bound_duals[0], 0.0);  // x0 sits on its lower bound 1.
}

TEST(IpoptSolverTest, HockSchittkowskiSet) {
  ExpectSolves(test::MakeHs006(), 1e-8, 1e-5);
  ExpectSolves(test::MakeHs035(), 1e-8, 1e-6);
  ExpectSolves(test::MakeHs100(), 1e-5, 1e-4);
}

TEST(IpoptSolverTest, Rosenbrock) {
  ExpectSolves(test::MakeRosenbrock2(), 1e-10, 1e-5);
  ExpectSolves(test::MakeChainedRosenbrock(100), 1e-10, 1e-5);
}

TEST(IpoptSolverTest, SparseChainWithTenThousandVariables) {
  const test::TestProblem p = test::MakeSparseChain(10000);
  const SolverResult result = IpoptSolver().Solve(*p.prog);
  ASSERT_EQ(result.status, SolutionStatus::kSolved) << result.message;
  EXPECT_NEAR(result.objective, 10000.0, 1e-5);
  EXPECT_LT((result.x - p.optimal_x).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT(result.constraint_violation, 1e-8);
}

TEST(IpoptSolverTest, DetectsInfeasibleProgram) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(2, "x");
  auto disc = std::make_shared<FunctionEvaluator>(
      "unit_disc", 2, 1, Evaluator::DensePattern(1, 2),
      [](const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> y) { y[0] = v.squaredNorm(); },
      [](const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> y,
         Eigen::Ref<Eigen::VectorXd> j) {
        y[0] = v.squaredNorm();
        j = 2 * v;
      });
  prog.AddConstraint(disc, Eigen::Matrix<double, 1, 1>(-kInf), Eigen::Matrix<double, 1, 1>(1.0), x);
  prog.AddLinearConstraint(Eigen::RowVector2d(1, 1).sparseView(), Eigen::Matrix<double, 1, 1>(3.0),
                           Eigen::Matrix<double, 1, 1>(kInf), x);
  prog.AddLinearCost(Eigen::Vector2d(1, 0), 0.0, x);
  const SolverResult result = IpoptSolver().Solve(prog);
  EXPECT_EQ(result.status, SolutionStatus::kInfeasible) << result.message;
  EXPECT_GT(result.constraint_violation, 0.1);
  EXPECT_THAT(result.message, HasSubstr("Infeasible_Problem_Detected"));
  EXPECT_THAT(result.message, HasSubstr("largest violation constraint"));
}

TEST(IpoptSolverTest, DetectsUnboundedProgram) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(1, "x");
  // min -x^3 with x >= 0 decreases without bound; Ipopt reports diverging iterates.
  auto cubic = std::make_shared<FunctionEvaluator>(
      "negative_cube", 1, 1, Evaluator::DensePattern(1, 1),
      [](const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> y) { y[0] = -v[0] * v[0] * v[0]; },
      [](const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> y,
         Eigen::Ref<Eigen::VectorXd> j) {
        y[0] = -v[0] * v[0] * v[0];
        j[0] = -3 * v[0] * v[0];
      });
  prog.AddCost(cubic, x);
  prog.AddBoundingBoxConstraint(0.0, kInf, x);
  prog.SetInitialGuess(x, Eigen::Matrix<double, 1, 1>(1.0));
  const SolverResult result = IpoptSolver().Solve(prog);
  EXPECT_EQ(result.status, SolutionStatus::kUnbounded) << result.message;
}

TEST(IpoptSolverTest, OptionsByNameAndType) {
  const test::TestProblem p = test::MakeHs071();
  SolverOptions options;
  options.Set("ipopt", "max_iter", 2);
  options.Set("ipopt", "tol", 1e-10);
  options.Set("ipopt", "mu_strategy", "adaptive");
  const SolverResult limited = IpoptSolver().Solve(*p.prog, p.prog->initial_guess(), options);
  EXPECT_EQ(limited.status, SolutionStatus::kIterationLimit) << limited.message;
  EXPECT_EQ(limited.iterations, 2);

  SolverOptions typo;
  typo.Set("ipopt", "max_iters", 10);
  CAIRN_EXPECT_THROWS_WITH(IpoptSolver().Solve(*p.prog, p.prog->initial_guess(), typo), std::invalid_argument,
                           "unknown Ipopt option 'max_iters'; did you mean 'max_iter'");
  SolverOptions wrong_type;
  wrong_type.Set("ipopt", "max_iter", "ten");
  CAIRN_EXPECT_THROWS_WITH(IpoptSolver().Solve(*p.prog, p.prog->initial_guess(), wrong_type), std::invalid_argument,
                           "option 'max_iter' is an integer but was given 'ten'");
  SolverOptions bad_value;
  bad_value.Set("ipopt", "mu_strategy", "fastest");
  CAIRN_EXPECT_THROWS_WITH(
      IpoptSolver().Solve(*p.prog, p.prog->initial_guess(), bad_value), std::invalid_argument,
      "rejected the value 'fastest' for option 'mu_strategy'; valid values are 'monotone', 'adaptive'");
  SolverOptions wrong_key;
  wrong_key.Set("iopt", "max_iter", 10);
  CAIRN_EXPECT_THROWS_WITH(
      IpoptSolver().Solve(*p.prog, p.prog->initial_guess(), wrong_key), std::invalid_argument,
      "unknown solver key 'iopt'; valid keys are 'ipopt', 'least_squares', 'nlopt' (did you mean 'ipopt'?)");
}

TEST(IpoptSolverTest, TimeLimit) {
  // A problem that takes hundreds of milliseconds, so Ipopt's CPU clock (coarse on some kernels) has surely
  // advanced past the limit after the first iteration.
  const test::TestProblem p = test::MakeSparseChain(10000);
  SolverOptions options;
  options.Set("ipopt", "max_cpu_time", 1e-9);
  const SolverResult result = IpoptSolver().Solve(*p.prog, p.prog->initial_guess(), options);
  EXPECT_EQ(result.status, SolutionStatus::kTimeLimit) << result.message;
  EXPECT_THAT(result.message, HasSubstr("Maximum_CpuTime_Exceeded"));
}

TEST(IpoptSolverTest, RejectsExactHessianWhenATermHasNone) {
  const test::TestProblem p = test::MakeHs100();  // autodiff evaluators declare no Hessian
  SolverOptions options;
  options.Set("ipopt", "hessian_approximation", "exact");
  CAIRN_EXPECT_THROWS_WITH(IpoptSolver().Solve(*p.prog, p.prog->initial_guess(), options), std::invalid_argument,
                           "hessian_approximation = 'exact' needs a Hessian from every cost and constraint");
}

TEST(IpoptSolverTest, GaussNewtonLeastSquaresHessian) {
  // Zero residual at the optimum: Gauss-Newton reaches it as the exact Hessian does.
  const test::TestProblem p = test::MakeChainedRosenbrock(30);
  SolverOptions options;
  options.Set("ipopt", "least_squares_hessian", "gauss-newton");
  const SolverResult result = IpoptSolver().Solve(*p.prog, p.prog->initial_guess(), options);
  ASSERT_EQ(result.status, SolutionStatus::kSolved) << result.message;
  EXPECT_LT((result.x - p.optimal_x).cwiseAbs().maxCoeff(), 1e-5);

  SolverOptions bad;
  bad.Set("ipopt", "least_squares_hessian", "newton");
  CAIRN_EXPECT_THROWS_WITH(IpoptSolver().Solve(*p.prog, p.prog->initial_guess(), bad), std::invalid_argument,
                           "option 'least_squares_hessian' is 'newton'; give 'exact'");
}

TEST(IpoptSolverTest, NeverReadsIpoptOptFromTheWorkingDirectory) {
  // An ipopt.opt that would stop Ipopt after one iteration must have no effect.
  {
    std::ofstream file("ipopt.opt");
    file << "max_iter 1\n";
  }
  const test::TestProblem p = test::MakeHs071();
  const SolverResult result = IpoptSolver().Solve(*p.prog);
  std::remove("ipopt.opt");
  EXPECT_EQ(result.status, SolutionStatus::kSolved) << result.message;
  EXPECT_GT(result.iterations, 1);
}

TEST(IpoptSolverTest, RejectsBadInitialGuess) {
  const test::TestProblem p = test::MakeHs071();
  CAIRN_EXPECT_THROWS_WITH(IpoptSolver().Solve(*p.prog, Eigen::Vector3d(1, 2, 3)), std::invalid_argument,
                           "the initial guess has 3 entries but the program has 4 variables");
  CAIRN_EXPECT_THROWS_WITH(IpoptSolver().Solve(*p.prog, Eigen::Vector4d(1, std::nan(""), 1, 1)), std::invalid_argument,
                           "initial guess of variable 'x(1)' is nan");
  MathematicalProgram empty;
  CAIRN_EXPECT_THROWS_WITH(IpoptSolver().Solve(empty), std::invalid_argument, "the program has no decision variables");
}

TEST(IpoptSolverTest, EvaluatorExceptionsReachTheCaller) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(1, "x");
  prog.AddCost(std::make_shared<FunctionEvaluator>(
                   "throws_above_two", 1, 1,
                   [](const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> y) {
                     if (v[0] > 2.0) throw std::runtime_error("model evaluated outside its range at " +
                                                              std::to_string(v[0]));
                     y[0] = -v[0];
                   }),
               x);
  CAIRN_EXPECT_THROWS_WITH(IpoptSolver().Solve(prog), std::runtime_error, "model evaluated outside its range");
}

TEST(IpoptSolverTest, TwoThreadsSolvingAtOnceBothGetCorrectAnswers) {
  // Ipopt 3.11 is not thread-safe here; IpoptSolver serialises solves, so concurrent callers must both succeed.
  const test::TestProblem hs071 = test::MakeHs071();
  const test::TestProblem hs100 = test::MakeHs100();
  std::vector<SolverResult> results_a, results_b;
  std::thread a([&] {
    for (int i = 0; i < 5; ++i) results_a.push_back(IpoptSolver().Solve(*hs071.prog));
  });
  std::thread b([&] {
    for (int i = 0; i < 5; ++i) results_b.push_back(IpoptSolver().Solve(*hs100.prog));
  });
  a.join();
  b.join();
  for (const SolverResult& r : results_a) {
    EXPECT_EQ(r.status, SolutionStatus::kSolved);
    EXPECT_NEAR(r.objective, hs071.optimal_cost, 1e-6);
  }
  for (const SolverResult& r : results_b) {
    EXPECT_EQ(r.status, SolutionStatus::kSolved);
    EXPECT_NEAR(r.objective, hs100.optimal_cost, 1e-5);
  }
}

}  // namespace
}  // namespace cairn::optimization
