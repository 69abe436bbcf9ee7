#include "cairn/optimization/evaluator.h"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cairn/optimization/autodiff_evaluator.h"
#include "cairn/optimization/function_evaluator.h"
#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using Eigen::Ref;
using Eigen::VectorXd;
using ::testing::HasSubstr;

// y = (x0^2 x1, sin(x1) + x2): row 0 depends on x0, x1; row 1 on x1, x2.
void Value(const Ref<const VectorXd>& x, Ref<VectorXd> y) {
  y[0] = x[0] * x[0] * x[1];
  y[1] = std::sin(x[1]) + x[2];
}

const std::vector<SparsityEntry> kPattern = {{0, 0}, {0, 1}, {1, 1}, {1, 2}};

Eigen::MatrixXd ExactJacobian(const Eigen::Vector3d& x) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2, 3);
  J << 2 * x[0] * x[1], x[0] * x[0], 0, 0, std::cos(x[1]), 1;
  return J;
}

struct GenericFunction {
  template <typename T>
  void operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& x, Eigen::Matrix<T, Eigen::Dynamic, 1>* y) const {
    using std::sin;
    (*y)[0] = x[0] * x[0] * x[1];
    (*y)[1] = sin(x[1]) + x[2];
  }
};

TEST(EvaluatorTest, AnalyticFiniteDifferenceAndAutoDiffJacobiansAgree) {
  const Eigen::Vector3d x(0.7, -1.3, 2.0);
  const FunctionEvaluator analytic(
      "analytic", 3, 2, kPattern, Value, [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
        Value(v, y);
        j << 2 * v[0] * v[1], v[0] * v[0], std::cos(v[1]), 1;
      });
  const FunctionEvaluator finite("finite", 3, 2, kPattern, Value, {});
  const FunctionEvaluator dense("dense", 3, 2, Value);
  const AutoDiffEvaluator<GenericFunction> autodiff("autodiff", 3, 2, kPattern, GenericFunction{});
  EXPECT_EQ(analytic.jacobian_source(), DerivativeSource::kAnalytic);
  EXPECT_EQ(finite.jacobian_source(), DerivativeSource::kFiniteDifference);
  EXPECT_EQ(autodiff.jacobian_source(), DerivativeSource::kAutoDiff);
  EXPECT_EQ(dense.jacobian_nonzeros(), 6);
  const Eigen::MatrixXd J = ExactJacobian(x);
  EXPECT_LT((Eigen::MatrixXd(analytic.EvalJacobian(x)) - J).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((Eigen::MatrixXd(autodiff.EvalJacobian(x)) - J).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((Eigen::MatrixXd(finite.EvalJacobian(x)) - J).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT((Eigen::MatrixXd(dense.EvalJacobian(x)) - J).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT((autodiff.Eval(x) - analytic.Eval(x)).norm(), 1e-15);
}

TEST(EvaluatorTest, NestedFiniteDifferencesDoNotShareScratch) {
  // The outer value function differentiates an inner finite-difference evaluator while the outer one is being
  // differentiated: y = x0 * d/dx1 (x1^3) = 3 x0 x1^2.
  auto inner = std::make_shared<FunctionEvaluator>(
      "cube", 1, 1, [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = v[0] * v[0] * v[0]; });
  const FunctionEvaluator outer("outer", 2, 1, [inner](const Ref<const VectorXd>& v, Ref<VectorXd> y) {
    VectorXd value(1), slope(1);
    inner->EvalWithJacobian(v.tail<1>(), value, slope);
    y[0] = v[0] * slope[0];
  });
  const Eigen::Vector2d x(1.5, 2.0);
  const Eigen::MatrixXd J = Eigen::MatrixXd(outer.EvalJacobian(x));
  EXPECT_NEAR(J(0, 0), 3 * 4.0, 1e-5);
  EXPECT_NEAR(J(0, 1), 6 * 1.5 * 2.0, 1e-4);
}

TEST(EvaluatorTest, ValuesFollowThePatternOrder) {
  const std::vector<SparsityEntry> reversed(kPattern.rbegin(), kPattern.rend());
  const AutoDiffEvaluator<GenericFunction> autodiff("reversed", 3, 2, reversed, GenericFunction{});
  const Eigen::Vector3d x(0.7, -1.3, 2.0);
  VectorXd y(2), values(4);
  autodiff.EvalWithJacobian(x, y, values);
  EXPECT_DOUBLE_EQ(values[0], 1.0);                // (1, 2)
  EXPECT_DOUBLE_EQ(values[3], 2 * x[0] * x[1]);    // (0, 0)
}

TEST(EvaluatorTest, RejectsBadPatternsAndSizes) {
  CAIRN_EXPECT_THROWS_WITH((FunctionEvaluator("bad", 3, 2, {{2, 0}}, Value, {})), std::invalid_argument,
                           "Evaluator 'bad': Jacobian pattern entry (2, 0) is outside the 2 x 3 matrix");
  CAIRN_EXPECT_THROWS_WITH((FunctionEvaluator("twice", 3, 2, {{0, 1}, {0, 1}}, Value, {})), std::invalid_argument,
                           "Evaluator 'twice': Jacobian pattern entry (0, 1) is declared twice");
  CAIRN_EXPECT_THROWS_WITH(
      ([] {
        FunctionEvaluator("upper", 3, 2, kPattern, Value, {}, {{0, 1}},
                          [](const Ref<const VectorXd>&, const Ref<const VectorXd>&, Ref<VectorXd>) {});
      })(),
      std::invalid_argument, "Hessian pattern entry (0, 1) is above the diagonal; declare the lower triangle only");
  CAIRN_EXPECT_THROWS_WITH(FunctionEvaluator("empty", 1, 1, nullptr), std::invalid_argument,
                           "FunctionEvaluator 'empty': the value function is empty");
  const FunctionEvaluator f("sized", 3, 2, Value);
  CAIRN_EXPECT_THROWS_WITH(f.Eval(Eigen::Vector2d(1, 2)), std::invalid_argument,
                           "Evaluator 'sized'.Eval: x has size 2 but the evaluator takes 3 inputs");
  CAIRN_EXPECT_THROWS_WITH(([&] {
                             VectorXd y(2), values(3);
                             f.EvalWithJacobian(Eigen::Vector3d::Zero(), y, values);
                           })(),
                           std::invalid_argument, "jacobian_values 3; expected 2 and 6 (one per pattern entry)");
  CAIRN_EXPECT_THROWS_WITH(([&] {
                             VectorXd h(0);
                             f.EvalHessian(Eigen::Vector3d::Zero(), Eigen::Vector2d::Ones(), h);
                           })(),
                           std::logic_error, "Evaluator 'sized' has no Hessian; check has_hessian()");
}

}  // namespace
}  // namespace cairn::optimization
