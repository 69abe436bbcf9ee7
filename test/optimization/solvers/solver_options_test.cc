#include "cairn/optimization/solvers/solver_options.h"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using ::testing::HasSubstr;

TEST(SolverOptionsTest, StoresTypedValuesPerSolver) {
  SolverOptions options;
  options.Set("ipopt", "max_iter", 50);
  options.Set("ipopt", "tol", 1e-9);
  options.Set("ipopt", "mu_strategy", "adaptive");
  options.Set("nlopt", "maxeval", 10);
  EXPECT_EQ(options.solver_keys(), (std::vector<std::string>{"ipopt", "nlopt"}));
  EXPECT_EQ(std::get<int>(options.Get("ipopt").at("max_iter")), 50);
  EXPECT_EQ(std::get<std::string>(options.Get("ipopt").at("mu_strategy")), "adaptive");
  EXPECT_TRUE(options.Get("least_squares").empty());
  EXPECT_EQ(SolverOptions::ToString(options.Get("ipopt").at("tol")), "1e-09");
  EXPECT_EQ(SolverOptions::ToString(options.Get("ipopt").at("mu_strategy")), "'adaptive'");
  CAIRN_EXPECT_THROWS_WITH(options.Set("", "tol", 1.0), std::invalid_argument,
                           "both the solver key (e.g. 'ipopt') and the option name must be non-empty");
}

TEST(SolverOptionsTest, RefusesNanValues) {
  SolverOptions options;
  // Ipopt's range checks compare, and every comparison with NaN is false, so NaN passed them before.
  CAIRN_EXPECT_THROWS_WITH(options.Set("ipopt", "tol", std::nan("")), std::invalid_argument,
                           "SolverOptions::Set('ipopt', 'tol')", "NaN");
  EXPECT_TRUE(options.Get("ipopt").empty());
  options.Set("nlopt", "stopval", -HUGE_VAL);
  EXPECT_EQ(SolverOptions::ToString(options.Get("nlopt").at("stopval")), "-inf");
}

}  // namespace
}  // namespace cairn::optimization
