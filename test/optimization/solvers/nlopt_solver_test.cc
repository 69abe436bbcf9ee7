#include "cairn/optimization/solvers/nlopt_solver.h"

#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cairn/optimization/function_evaluator.h"
#include "../test_problems.h"
#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using Eigen::Ref;
using Eigen::VectorXd;
using ::testing::HasSubstr;
constexpr double kInf = std::numeric_limits<double>::infinity();

void ExpectSolves(const std::string& algorithm, const test::TestProblem& p, double cost_tolerance,
                  double x_tolerance) {
  const NloptSolver solver(algorithm);
  const SolverResult result = solver.Solve(*p.prog);
  ASSERT_EQ(result.status, SolutionStatus::kSolved) << p.name << ": " << result.message;
  EXPECT_NEAR(result.objective, p.optimal_cost, cost_tolerance) << p.name;
  if (p.optimal_x.size() > 0) {
    EXPECT_LT((result.x - p.optimal_x).cwiseAbs().maxCoeff(), x_tolerance) << p.name;
  }
  EXPECT_LE(result.constraint_violation, 1e-8) << p.name;
  EXPECT_GT(result.evaluations, 0);
}

TEST(NloptSolverTest, SlsqpSolvesHockSchittkowskiSet) {
  ExpectSolves("SLSQP", test::MakeHs071(), 1e-6, 1e-5);
  ExpectSolves("SLSQP", test::MakeHs006(), 1e-8, 1e-4);
  ExpectSolves("SLSQP", test::MakeHs035(), 1e-8, 1e-6);
  ExpectSolves("SLSQP", test::MakeHs100(), 1e-5, 1e-4);
}

TEST(NloptSolverTest, SlsqpSolvesRosenbrock) {
  ExpectSolves("LD_SLSQP", test::MakeRosenbrock2(), 1e-10, 1e-4);
  ExpectSolves("LD_SLSQP", test::MakeChainedRosenbrock(100), 1e-8, 1e-3);
}

TEST(NloptSolverTest, DerivativeFreeCobylaSolvesHs35) {
  test::TestProblem p = test::MakeHs035();
  SolverOptions options;
  options.Set("nlopt", "xtol_rel", 1e-9);
  const SolverResult result = NloptSolver("COBYLA").Solve(*p.prog, p.prog->initial_guess(), options);
  ASSERT_EQ(result.status, SolutionStatus::kSolved) << result.message;
  EXPECT_NEAR(result.objective, 1.0 / 9.0, 1e-6);
  EXPECT_EQ(result.solver_name, "nlopt:LN_COBYLA");
}

// A Rastrigin function f = sum x_i^2 + 2 (1 - cos(2 pi x_i)) over [-5, 6]^2 subject to x0 + x1 >= 2:
// f >= |x|^2 >= (x0 + x1)^2 / 2 >= 2, with equality only at (1, 1), so the constrained global minimum is f* = 2
// at (1, 1), among dozens of local minima.
std::unique_ptr<MathematicalProgram> MakeConstrainedRastrigin(DecisionVariables* x) {
  auto prog = std::make_unique<MathematicalProgram>();
  *x = prog->NewContinuousVariables(2, "p");
  auto rastrigin = std::make_shared<FunctionEvaluator>(
      "rastrigin", 2, 1, Evaluator::DensePattern(1, 2),
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y) {
        y[0] = 4 + v.squaredNorm() - 2 * (std::cos(2 * M_PI * v[0]) + std::cos(2 * M_PI * v[1]));
      },
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = 4 + v.squaredNorm() - 2 * (std::cos(2 * M_PI * v[0]) + std::cos(2 * M_PI * v[1]));
        j << 2 * v[0] + 4 * M_PI * std::sin(2 * M_PI * v[0]), 2 * v[1] + 4 * M_PI * std::sin(2 * M_PI * v[1]);
      });
  prog->AddCost(rastrigin, *x);
  prog->AddLinearConstraint(Eigen::RowVector2d(1, 1).sparseView(), Eigen::Matrix<double, 1, 1>(2.0),
                            Eigen::Matrix<double, 1, 1>(kInf), *x);
  prog->AddBoundingBoxConstraint(-5.0, 6.0, *x);
  prog->SetInitialGuess(*x, Eigen::Vector2d(4.7, 4.6));
  return prog;
}

TEST(NloptSolverTest, DirectThenSlsqpFindsTheGlobalMinimumOfAConstrainedMultimodalFunction) {
  DecisionVariables x;
  const auto prog = MakeConstrainedRastrigin(&x);
  SolverOptions options;
  options.Set("nlopt", "GN_ORIG_DIRECT.maxeval", 300);
  const NloptSolver chain("ORIG_DIRECT+SLSQP");
  EXPECT_EQ(chain.name(), "nlopt:GN_ORIG_DIRECT+LD_SLSQP");
  const SolverResult result = chain.Solve(*prog, prog->initial_guess(), options);
  ASSERT_EQ(result.status, SolutionStatus::kSolved) << result.message;
  EXPECT_NEAR(result.objective, 2.0, 1e-8);
  EXPECT_LT((result.x - Eigen::Vector2d(1, 1)).norm(), 1e-5);
  EXPECT_GT(result.evaluations, 300);

  // SLSQP alone from the same start stops in a local minimum: the global stage is what finds (1, 1).
  const SolverResult local = NloptSolver("SLSQP").Solve(*prog);
  EXPECT_GT(local.objective, 10.0) << local.message;
}

TEST(NloptSolverTest, StochasticAlgorithmsAreSeeded) {
  const test::TestProblem p = test::MakeHs035();
  p.prog->AddBoundingBoxConstraint(0.0, 3.0, p.x);
  SolverOptions options;
  options.Set("nlopt", "maxeval", 3000);
  const SolverResult first = NloptSolver("ISRES").Solve(*p.prog, p.prog->initial_guess(), options);
  const SolverResult second = NloptSolver("ISRES").Solve(*p.prog, p.prog->initial_guess(), options);
  EXPECT_EQ(first.x, second.x);
  EXPECT_NEAR(first.objective, 1.0 / 9.0, 0.05);  // a stochastic search gets close, not exact
  options.Set("nlopt", "seed", 2);
  const SolverResult reseeded = NloptSolver("ISRES").Solve(*p.prog, p.prog->initial_guess(), options);
  EXPECT_NE(first.x, reseeded.x);
}

TEST(NloptSolverTest, ReportsInfeasibleProgram) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(2, "x");
  prog.AddLinearConstraint(Eigen::RowVector2d(1, 1).sparseView(), Eigen::Matrix<double, 1, 1>(3.0),
                           Eigen::Matrix<double, 1, 1>(kInf), x);
  prog.AddBoundingBoxConstraint(-1.0, 1.0, x);
  prog.AddLinearCost(Eigen::Vector2d(1, 0), 0.0, x);
  const SolverResult result = NloptSolver("SLSQP").Solve(prog);
  EXPECT_EQ(result.status, SolutionStatus::kInfeasible) << result.message;
  EXPECT_THAT(result.message, HasSubstr("largest violation constraint 'LinearConstraint(x)' row 0"));
}

TEST(NloptSolverTest, ReportsUnboundedProgram) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(2, "x");
  prog.AddLinearCost(Eigen::Vector2d(-1, -1), 0.0, x);
  prog.AddLinearConstraint(Eigen::RowVector2d(1, -1).sparseView(), Eigen::Matrix<double, 1, 1>(0.0),
                           Eigen::Matrix<double, 1, 1>(0.0), x);
  const SolverResult result = NloptSolver("SLSQP").Solve(prog);
  EXPECT_EQ(result.status, SolutionStatus::kUnbounded) << result.message;
}

TEST(NloptSolverTest, StoppingCriteria) {
  const test::TestProblem p = test::MakeHs100();
  SolverOptions options;
  options.Set("nlopt", "maxeval", 3);
  const SolverResult result = NloptSolver("SLSQP").Solve(*p.prog, p.prog->initial_guess(), options);
  EXPECT_EQ(result.status, SolutionStatus::kIterationLimit) << result.message;
  EXPECT_EQ(result.evaluations, 3);
  EXPECT_THAT(result.message, HasSubstr("LD_SLSQP: MAXEVAL_REACHED"));
}

TEST(NloptSolverTest, TimeLimit) {
  DecisionVariables x;
  const auto prog = MakeConstrainedRastrigin(&x);
  SolverOptions options;
  options.Set("nlopt", "maxtime", 1e-9);
  options.Set("nlopt", "maxeval", 1000000);
  const SolverResult result = NloptSolver("ORIG_DIRECT").Solve(*prog, prog->initial_guess(), options);
  EXPECT_EQ(result.status, SolutionStatus::kTimeLimit) << result.message;
}

TEST(NloptSolverTest, EvaluatorExceptionsReachTheCaller) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(2, "x");
  prog.AddCost(std::make_shared<FunctionEvaluator>("throws", 2, 1,
                                                   [](const Ref<const VectorXd>&, Ref<VectorXd>) {
                                                     throw std::runtime_error("terrain lookup outside the map");
                                                   }),
               x);
  CAIRN_EXPECT_THROWS_WITH(NloptSolver("SLSQP").Solve(prog), std::runtime_error, "terrain lookup outside the map");
}

TEST(NloptSolverTest, ConcurrentSolvesAreIndependent) {
  // HS6's constraint uses finite differences, whose scratch space is per thread.
  const test::TestProblem hs6 = test::MakeHs006();
  const test::TestProblem hs71 = test::MakeHs071();
  std::vector<SolverResult> a, b;
  std::thread first([&] {
    for (int i = 0; i < 20; ++i) a.push_back(NloptSolver("SLSQP").Solve(*hs6.prog));
  });
  std::thread second([&] {
    for (int i = 0; i < 20; ++i) b.push_back(NloptSolver("SLSQP").Solve(*hs71.prog));
  });
  first.join();
  second.join();
  for (const SolverResult& r : a) EXPECT_NEAR(r.objective, 0.0, 1e-8);
  for (const SolverResult& r : b) EXPECT_NEAR(r.objective, hs71.optimal_cost, 1e-6);
}

TEST(NloptSolverTest, RejectsUnknownAndAmbiguousAlgorithms) {
  CAIRN_EXPECT_THROWS_WITH(NloptSolver("SLSQQP"), std::invalid_argument, "unknown NLopt algorithm 'SLSQQP'",
                           "did you mean 'LD_SLSQP'", "valid names are 'GN_DIRECT', 'GN_DIRECT_L'");
  CAIRN_EXPECT_THROWS_WITH(NloptSolver("MLSL"), std::invalid_argument,
                           "algorithm 'MLSL' is ambiguous; write one of 'GN_MLSL', 'GD_MLSL', 'G_MLSL'");
  EXPECT_EQ(NloptSolver("AUGLAG").name(), "nlopt:AUGLAG");  // an exact NLopt name wins over the short form
  CAIRN_EXPECT_THROWS_WITH(NloptSolver(""), std::invalid_argument, "no algorithm given");
  EXPECT_EQ(NloptSolver("ld_mma").name(), "nlopt:LD_MMA");
}

TEST(NloptSolverTest, RejectsProgramsAnAlgorithmCannotHandle) {
  const test::TestProblem hs6 = test::MakeHs006();
  EXPECT_THAT(NloptSolver("MMA").CheckSupport(*hs6.prog),
              HasSubstr("LD_MMA cannot handle equality constraints such as 'hs006_equality(x)'"));
  CAIRN_EXPECT_THROWS_WITH(NloptSolver("LBFGS").Solve(*test::MakeHs035().prog), std::invalid_argument,
                           "LD_LBFGS cannot handle nonlinear inequality constraints such as 'LinearConstraint(x)'");
  const test::TestProblem rosenbrock = test::MakeRosenbrock2();
  EXPECT_THAT(NloptSolver("ORIG_DIRECT").CheckSupport(*rosenbrock.prog),
              HasSubstr("the global algorithm GN_ORIG_DIRECT needs finite bounds on every variable, but 'x(0)' has "
                        "bounds [-inf, inf]; add them with AddBoundingBoxConstraint"));
}

TEST(NloptSolverTest, RejectsUnknownOptions) {
  const test::TestProblem p = test::MakeHs035();
  SolverOptions typo;
  typo.Set("nlopt", "max_eval", 10);
  CAIRN_EXPECT_THROWS_WITH(NloptSolver("SLSQP").Solve(*p.prog, p.prog->initial_guess(), typo), std::invalid_argument,
                           "unknown option 'max_eval' (did you mean 'maxeval'?)");
  SolverOptions wrong_stage;
  wrong_stage.Set("nlopt", "COBYLA.maxeval", 10);
  CAIRN_EXPECT_THROWS_WITH(NloptSolver("SLSQP").Solve(*p.prog, p.prog->initial_guess(), wrong_stage),
                           std::invalid_argument,
                           "option 'COBYLA.maxeval' names stage 'COBYLA', which is not a stage of this solver; stages "
                           "are 'LD_SLSQP'");
  SolverOptions wrong_type;
  wrong_type.Set("nlopt", "maxeval", 10.5);
  CAIRN_EXPECT_THROWS_WITH(NloptSolver("SLSQP").Solve(*p.prog, p.prog->initial_guess(), wrong_type),
                           std::invalid_argument, "option 'maxeval' is an integer but was given 10.5");
}

TEST(NloptSolverTest, RejectsOptionsOutOfRange) {
  const test::TestProblem p = test::MakeHs035();
  // NLopt read each of these differently from what was asked: maxeval <= 0 and maxtime <= 0 as no limit, a
  // negative tolerance as none, a negative seed wrapped round to a huge unsigned number.
  const std::vector<std::tuple<std::string, SolverOptions::Value, std::string>> cases = {
      {"maxeval", 0, "option 'maxeval' = 0 must be >= 1"},
      {"maxeval", -5, "option 'maxeval' = -5 must be >= 1"},
      {"seed", -1, "option 'seed' = -1 must be >= 0"},
      {"population", -2, "option 'population' = -2 must be >= 0"},
      {"maxtime", -1.0, "option 'maxtime' = -1 must be > 0 seconds"},
      {"maxtime", 0, "option 'maxtime' = 0 must be > 0 seconds"},
      {"xtol_rel", -1e-6, "option 'xtol_rel' = -1e-06 must be finite and >= 0"},
      {"ftol_abs", std::numeric_limits<double>::infinity(), "option 'ftol_abs' = inf must be finite"},
      {"constraint_tol", -1e-8, "option 'constraint_tol' = -1e-08 must be finite and >= 0."},
      {"LD_SLSQP.xtol_abs", -1.0, "option 'xtol_abs' = -1"},
  };
  for (const auto& [name, value, message] : cases) {
    SolverOptions options;
    if (const int* i = std::get_if<int>(&value)) {
      options.Set("nlopt", name, *i);
    } else {
      options.Set("nlopt", name, std::get<double>(value));
    }
    CAIRN_EXPECT_THROWS_WITH(NloptSolver("SLSQP").Solve(*p.prog, p.prog->initial_guess(), options),
                             std::invalid_argument, message);
  }
}

TEST(NloptSolverTest, TwoSidedRowsAreRegisteredTwice) {
  // 1 <= x0 + x1 <= 1.5 with cost (x0 - 2)^2 + (x1 - 2)^2: the upper side is active at (0.75, 0.75);
  // with the cost centred at -2 the lower side is active at (0.5, 0.5).
  for (const double centre : {2.0, -2.0}) {
    MathematicalProgram prog;
    const auto x = prog.NewContinuousVariables(2, "x");
    Eigen::SparseMatrix<double> Q(2, 2);
    Q.setIdentity();
    Q *= 2.0;
    prog.AddQuadraticCost(Q, Eigen::Vector2d(-2 * centre, -2 * centre), 2 * centre * centre, x);
    prog.AddLinearConstraint(Eigen::RowVector2d(1, 1).sparseView(), Eigen::Matrix<double, 1, 1>(1.0),
                             Eigen::Matrix<double, 1, 1>(1.5), x);
    const SolverResult result = NloptSolver("SLSQP").Solve(prog);
    ASSERT_EQ(result.status, SolutionStatus::kSolved) << result.message;
    const double expected = centre > 0 ? 0.75 : 0.5;
    EXPECT_NEAR(result.x[0], expected, 1e-7);
    EXPECT_NEAR(result.x[1], expected, 1e-7);
  }
}

}  // namespace
}  // namespace cairn::optimization
