#include "cairn/optimization/solve.h"

#include <gtest/gtest.h>

#include "test_problems.h"

namespace cairn::optimization {
namespace {

TEST(SolveTest, PicksLeastSquaresForResidualProgramsAndIpoptOtherwise) {
  const test::TestProblem rosenbrock = test::MakeChainedRosenbrock(10);
  EXPECT_EQ(ChooseSolver(*rosenbrock.prog)->name(), "least_squares");
  const SolverResult fit = Solve(*rosenbrock.prog);
  EXPECT_EQ(fit.solver_name, "least_squares");
  EXPECT_TRUE(fit.is_success()) << fit.message;
  EXPECT_LT((fit.x - rosenbrock.optimal_x).cwiseAbs().maxCoeff(), 1e-6);

  const test::TestProblem hs071 = test::MakeHs071();
  EXPECT_EQ(ChooseSolver(*hs071.prog)->name(), "ipopt");
  const SolverResult result = Solve(*hs071.prog);
  EXPECT_TRUE(result.is_success()) << result.message;
  EXPECT_NEAR(result.objective, hs071.optimal_cost, 1e-6);
  EXPECT_GT(result.wall_time_seconds, 0.0);
}

}  // namespace
}  // namespace cairn::optimization
