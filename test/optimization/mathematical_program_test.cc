#include "cairn/optimization/mathematical_program.h"

#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cairn/optimization/function_evaluator.h"
#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using Eigen::Ref;
using Eigen::VectorXd;
using ::testing::HasSubstr;
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(MathematicalProgramTest, VariablesHaveNamesAndContiguousIndices) {
  MathematicalProgram prog;
  const DecisionVariables q = prog.NewContinuousVariables(3, "q");
  const DecisionVariables t = prog.NewContinuousVariables(1, "t");
  EXPECT_EQ(prog.num_vars(), 4);
  EXPECT_EQ(q.indices(), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(prog.VariableName(1), "q(1)");
  EXPECT_EQ(prog.VariableName(3), "t");
  EXPECT_EQ(q.Segment(1, 2).indices(), (std::vector<int>{1, 2}));
  EXPECT_EQ(q.Segment(1, 2).description(), "q[1:3]");
  EXPECT_EQ(DecisionVariables::Concatenate({q.Element(2), t}).indices(), (std::vector<int>{2, 3}));
  EXPECT_EQ(prog.GetVariables("t").indices(), t.indices());
  CAIRN_EXPECT_THROWS_WITH(prog.GetVariables("qq"), std::invalid_argument,
                           "no variable block named 'qq'; did you mean 'q'");
  CAIRN_EXPECT_THROWS_WITH(prog.NewContinuousVariables(2, "q"), std::invalid_argument,
                           "a variable block named 'q' already exists");
  CAIRN_EXPECT_THROWS_WITH(prog.NewContinuousVariables(0, "z"), std::invalid_argument,
                           "NewContinuousVariables(0, 'z'): the number of variables must be at least 1");
  CAIRN_EXPECT_THROWS_WITH(q.Segment(2, 2), std::invalid_argument,
                           "DecisionVariables 'q'.Segment(2, 2) is out of range: the list has 3 variables");
}

TEST(MathematicalProgramTest, BoundsInitialGuessAndCost) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(2, "x");
  prog.AddBoundingBoxConstraint(-1.0, 2.0, x);
  prog.AddBoundingBoxConstraint(Eigen::Vector2d(0.0, -kInf), Eigen::Vector2d(kInf, 1.5), x);
  EXPECT_EQ(prog.variable_lower_bounds(), Eigen::Vector2d(0.0, -1.0));
  EXPECT_EQ(prog.variable_upper_bounds(), Eigen::Vector2d(2.0, 1.5));
  prog.SetInitialGuess(x.Element(1), Eigen::Matrix<double, 1, 1>(0.25));
  EXPECT_EQ(prog.initial_guess(), Eigen::Vector2d(0.0, 0.25));
  prog.AddLinearCost(Eigen::Vector2d(1, 2), 3.0, x);
  prog.AddLeastSquaresCost(
      std::make_shared<FunctionEvaluator>("r", 1, 2,
                                          [](const Ref<const VectorXd>& v, Ref<VectorXd> r) { r << v[0], 2.0; }),
      x.Element(0));
  // 1 * 1 + 2 * 2 + 3 + 0.5 * (1 + 4)
  EXPECT_DOUBLE_EQ(prog.EvalCost(Eigen::Vector2d(1, 2)), 10.5);
  EXPECT_EQ(prog.bounding_box_constraints().size(), 2u);
  EXPECT_EQ(prog.costs().size(), 1u);
  EXPECT_EQ(prog.least_squares_costs().size(), 1u);
}

TEST(MathematicalProgramTest, RejectsMistakesWithMessagesThatSayHowToFixThem) {
  MathematicalProgram prog, other;
  const auto x = prog.NewContinuousVariables(2, "x");
  const auto y = other.NewContinuousVariables(2, "y");
  CAIRN_EXPECT_THROWS_WITH(prog.AddLinearCost(Eigen::Vector2d(1, 1), 0.0, y), std::invalid_argument,
                           "the variables 'y' were created by a different MathematicalProgram");
  CAIRN_EXPECT_THROWS_WITH(
      ([&] {
        prog.AddLinearCost(Eigen::Vector2d(1, 1), 0.0, DecisionVariables::Concatenate({x.Element(0), x.Element(0)}));
      })(),
      std::invalid_argument, "variable 'x(0)' appears twice in '(x[0:1], x[0:1])'; bind each variable once");
  CAIRN_EXPECT_THROWS_WITH(prog.AddLinearCost(Eigen::Vector3d(1, 1, 1), 0.0, x), std::invalid_argument,
                           "Binding 'LinearCost' to 'x': the evaluator takes 3 inputs but 2 variables were given");
  auto vector_valued = std::make_shared<FunctionEvaluator>(
      "two_outputs", 2, 2, [](const Ref<const VectorXd>& v, Ref<VectorXd> r) { r = v; });
  CAIRN_EXPECT_THROWS_WITH(prog.AddCost(vector_valued, x), std::invalid_argument,
                           "a cost must have exactly one output but it has 2; for a vector residual use "
                           "AddLeastSquaresCost");
  CAIRN_EXPECT_THROWS_WITH(prog.AddConstraint(vector_valued, Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1), x),
                           std::invalid_argument, "Constraint 'two_outputs': row 0 has bounds [1.000000, 0.000000]");
  CAIRN_EXPECT_THROWS_WITH(prog.AddBoundingBoxConstraint(Eigen::Vector2d(0, 0), Eigen::Vector3d(1, 1, 1), x),
                           std::invalid_argument, "lower bound has size 2 but upper bound has size 3");
  Eigen::Matrix2d Q;
  Q << 1, 2, 0, 1;
  CAIRN_EXPECT_THROWS_WITH(prog.AddQuadraticCost(Q.sparseView(), Eigen::Vector2d::Zero(), 0.0, x),
                           std::invalid_argument, "QuadraticCost: Q is not symmetric");
  CAIRN_EXPECT_THROWS_WITH(prog.SetInitialGuess(x, Eigen::Vector3d::Zero()), std::invalid_argument,
                           "SetInitialGuess('x'): got 3 values for 2 variables");
  CAIRN_EXPECT_THROWS_WITH(prog.NewContinuousVariables(2, ""), std::invalid_argument,
                           "give the variables a name; it appears in every message about them");
  CAIRN_EXPECT_THROWS_WITH(prog.VariableName(7), std::invalid_argument, "VariableName(7): the program has 2 variables");
  CAIRN_EXPECT_THROWS_WITH(prog.AddLinearCost(Eigen::VectorXd(0), 0.0, DecisionVariables()), std::invalid_argument,
                           "AddLinearCost: the variable list is empty; bind at least one variable");
  CAIRN_EXPECT_THROWS_WITH(prog.AddCost(nullptr, x), std::invalid_argument, "Binding to 'x': the evaluator is null");
  CAIRN_EXPECT_THROWS_WITH(prog.EvalCost(Eigen::Vector3d::Zero()), std::invalid_argument,
                           "EvalCost: x has size 3 but the program has 2 variables");
}

TEST(MathematicalProgramTest, GenericConstraintsKeepTheirEvaluatorAndBounds) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(3, "x");
  auto f = std::make_shared<FunctionEvaluator>(
      "norm2", 2, 1, [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = v.squaredNorm(); });
  const auto binding = prog.AddConstraint(f, Eigen::Matrix<double, 1, 1>(-kInf), Eigen::Matrix<double, 1, 1>(1.0),
                                          x.Segment(1, 2));
  EXPECT_EQ(binding.ToString(), "norm2(x[1:3])");
  EXPECT_EQ(binding.evaluator()->upper_bound()[0], 1.0);
  EXPECT_DOUBLE_EQ(binding.evaluator()->Violation(Eigen::Vector2d(1, 1)), 1.0);
  ASSERT_EQ(prog.constraints().size(), 1u);
  // A BoundingBoxConstraint added through the generic path is still folded into the bounds.
  prog.AddConstraint(std::make_shared<BoundingBoxConstraint>(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)),
                     x.Segment(0, 2));
  EXPECT_EQ(prog.constraints().size(), 1u);
  EXPECT_EQ(prog.variable_upper_bounds()[1], 1.0);
}

}  // namespace
}  // namespace cairn::optimization
