#include "cairn/optimization/solvers/make_solver.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../test_problems.h"
#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using ::testing::HasSubstr;

TEST(MakeSolverTest, SwapsSolversByName) {
  const test::TestProblem p = test::MakeHs035();
  for (const std::string name : {"ipopt", "nlopt:SLSQP", "nlopt:COBYLA"}) {
    const auto solver = MakeSolver(name);
    ASSERT_TRUE(solver->available());
    SolverOptions options;
    options.Set("nlopt", "xtol_rel", 1e-10);
    const SolverResult result = solver->Solve(*p.prog, p.prog->initial_guess(), options);
    EXPECT_TRUE(result.is_success()) << name << ": " << result.message;
    EXPECT_NEAR(result.objective, 1.0 / 9.0, 1e-6) << name;
  }
  EXPECT_EQ(MakeSolver("least_squares")->name(), "least_squares");
  EXPECT_EQ(MakeSolver("nlopt:ORIG_DIRECT+SLSQP")->name(), "nlopt:GN_ORIG_DIRECT+LD_SLSQP");
}

TEST(MakeSolverTest, RejectsUnknownNames) {
  CAIRN_EXPECT_THROWS_WITH(MakeSolver("ipopt3"), std::invalid_argument,
                           "unknown solver 'ipopt3' (did you mean 'ipopt'?)",
                           "valid names are 'ipopt', 'least_squares' and 'nlopt:<ALGORITHM>");
  CAIRN_EXPECT_THROWS_WITH(MakeSolver("nlopt:SLSQP+DIRCT"), std::invalid_argument, "unknown NLopt algorithm 'DIRCT'");
}

}  // namespace
}  // namespace cairn::optimization
