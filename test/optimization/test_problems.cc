#include "test_problems.h"

#include <limits>
#include <vector>

#include "cairn/optimization/autodiff_evaluator.h"
#include "cairn/optimization/function_evaluator.h"

namespace cairn::optimization::test {

namespace {

using Eigen::Ref;
using Eigen::VectorXd;
constexpr double kInf = std::numeric_limits<double>::infinity();

TestProblem Start(const std::string& name, int n, const std::string& var_name) {
  TestProblem p;
  p.name = name;
  p.prog = std::make_unique<MathematicalProgram>();
  p.x = p.prog->NewContinuousVariables(n, var_name);
  return p;
}

struct Hs100Cost {
  template <typename T>
  void operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& x, Eigen::Matrix<T, Eigen::Dynamic, 1>* y) const {
    const T x4_2 = x[4] * x[4];
    (*y)[0] = (x[0] - 10.0) * (x[0] - 10.0) + 5.0 * (x[1] - 12.0) * (x[1] - 12.0) + x[2] * x[2] * x[2] * x[2] +
              3.0 * (x[3] - 11.0) * (x[3] - 11.0) + 10.0 * x4_2 * x4_2 * x4_2 + 7.0 * x[5] * x[5] +
              x[6] * x[6] * x[6] * x[6] - 4.0 * x[5] * x[6] - 10.0 * x[5] - 8.0 * x[6];
  }
};

struct Hs100Constraints {
  template <typename T>
  void operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& x, Eigen::Matrix<T, Eigen::Dynamic, 1>* y) const {
    (*y)[0] = 127.0 - 2.0 * x[0] * x[0] - 3.0 * x[1] * x[1] * x[1] * x[1] - x[2] - 4.0 * x[3] * x[3] - 5.0 * x[4];
    (*y)[1] = 282.0 - 7.0 * x[0] - 3.0 * x[1] - 10.0 * x[2] * x[2] - x[3] + x[4];
    (*y)[2] = 196.0 - 23.0 * x[0] - x[1] * x[1] - 6.0 * x[5] * x[5] + 8.0 * x[6];
    (*y)[3] = -4.0 * x[0] * x[0] - x[1] * x[1] + 3.0 * x[0] * x[1] - 2.0 * x[2] * x[2] - 5.0 * x[5] + 11.0 * x[6];
  }
};

}  // namespace

TestProblem MakeHs071() {
  TestProblem p = Start("HS071", 4, "x");
  auto cost = std::make_shared<FunctionEvaluator>(
      "hs071_cost", 4, 1, Evaluator::DensePattern(1, 4),
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y) { y[0] = x[0] * x[3] * (x[0] + x[1] + x[2]) + x[2]; },
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = x[0] * x[3] * (x[0] + x[1] + x[2]) + x[2];
        j << x[3] * (2 * x[0] + x[1] + x[2]), x[0] * x[3], x[0] * x[3] + 1, x[0] * (x[0] + x[1] + x[2]);
      },
      std::vector<SparsityEntry>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}},
      [](const Ref<const VectorXd>& x, const Ref<const VectorXd>& w, Ref<VectorXd> h) {
        h << 2 * x[3], x[3], x[3], 2 * x[0] + x[1] + x[2], x[0], x[0];
        h *= w[0];
      });
  auto product = std::make_shared<FunctionEvaluator>(
      "hs071_product", 4, 1, Evaluator::DensePattern(1, 4),
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y) { y[0] = x.prod(); },
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = x.prod();
        j << x[1] * x[2] * x[3], x[0] * x[2] * x[3], x[0] * x[1] * x[3], x[0] * x[1] * x[2];
      },
      std::vector<SparsityEntry>{{1, 0}, {2, 0}, {2, 1}, {3, 0}, {3, 1}, {3, 2}},
      [](const Ref<const VectorXd>& x, const Ref<const VectorXd>& w, Ref<VectorXd> h) {
        h << x[2] * x[3], x[1] * x[3], x[0] * x[3], x[1] * x[2], x[0] * x[2], x[0] * x[1];
        h *= w[0];
      });
  auto sphere = std::make_shared<FunctionEvaluator>(
      "hs071_sphere", 4, 1, Evaluator::DensePattern(1, 4),
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y) { y[0] = x.squaredNorm(); },
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = x.squaredNorm();
        j = 2 * x;
      },
      std::vector<SparsityEntry>{{0, 0}, {1, 1}, {2, 2}, {3, 3}},
      [](const Ref<const VectorXd>&, const Ref<const VectorXd>& w, Ref<VectorXd> h) { h.setConstant(2 * w[0]); });
  p.prog->AddCost(cost, p.x);
  p.prog->AddConstraint(product, Eigen::Matrix<double, 1, 1>(25.0), Eigen::Matrix<double, 1, 1>(kInf), p.x);
  p.prog->AddConstraint(sphere, Eigen::Matrix<double, 1, 1>(40.0), Eigen::Matrix<double, 1, 1>(40.0), p.x);
  p.prog->AddBoundingBoxConstraint(1.0, 5.0, p.x);
  p.prog->SetInitialGuess(p.x, Eigen::Vector4d(1, 5, 5, 1));
  p.optimal_cost = 17.0140173;
  p.optimal_x = Eigen::Vector4d(1.0, 4.74299963, 3.82114998, 1.37940829);
  return p;
}

TestProblem MakeHs006() {
  TestProblem p = Start("HS6", 2, "x");
  auto cost = std::make_shared<FunctionEvaluator>(
      "hs006_cost", 2, 1, std::vector<SparsityEntry>{{0, 0}},
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y) { y[0] = (1 - x[0]) * (1 - x[0]); },
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = (1 - x[0]) * (1 - x[0]);
        j[0] = -2 * (1 - x[0]);
      });
  // Value only: the Jacobian comes from finite differences, exercising that fallback inside the solvers.
  auto constraint = std::make_shared<FunctionEvaluator>(
      "hs006_equality", 2, 1,
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y) { y[0] = 10 * (x[1] - x[0] * x[0]); });
  p.prog->AddCost(cost, p.x);
  p.prog->AddConstraint(constraint, Eigen::Matrix<double, 1, 1>(0.0), Eigen::Matrix<double, 1, 1>(0.0), p.x);
  p.prog->SetInitialGuess(p.x, Eigen::Vector2d(-1.2, 1.0));
  p.optimal_cost = 0.0;
  p.optimal_x = Eigen::Vector2d(1.0, 1.0);
  return p;
}

TestProblem MakeHs035() {
  TestProblem p = Start("HS35", 3, "x");
  Eigen::Matrix3d Q;
  Q << 4, 2, 2, 2, 4, 0, 2, 0, 2;
  p.prog->AddQuadraticCost(Q.sparseView(), Eigen::Vector3d(-8, -6, -4), 9.0, p.x);
  Eigen::SparseMatrix<double> A = Eigen::RowVector3d(1, 1, 2).sparseView();
  p.prog->AddLinearConstraint(A, Eigen::Matrix<double, 1, 1>(-kInf), Eigen::Matrix<double, 1, 1>(3.0), p.x);
  p.prog->AddBoundingBoxConstraint(0.0, kInf, p.x);
  p.prog->SetInitialGuess(p.x, Eigen::Vector3d(0.5, 0.5, 0.5));
  p.optimal_cost = 1.0 / 9.0;
  p.optimal_x = Eigen::Vector3d(4.0 / 3.0, 7.0 / 9.0, 4.0 / 9.0);
  return p;
}

TestProblem MakeHs100() {
  TestProblem p = Start("HS100", 7, "x");
  p.prog->AddCost(std::make_shared<AutoDiffEvaluator<Hs100Cost>>("hs100_cost", 7, 1, Hs100Cost{}), p.x);
  p.prog->AddConstraint(
      std::make_shared<AutoDiffEvaluator<Hs100Constraints>>("hs100_constraints", 7, 4, Hs100Constraints{}),
      VectorXd::Zero(4), VectorXd::Constant(4, kInf), p.x);
  VectorXd x0(7);
  x0 << 1, 2, 0, 4, 0, 1, 1;
  p.prog->SetInitialGuess(p.x, x0);
  p.optimal_cost = 680.6300573;
  p.optimal_x.resize(7);
  p.optimal_x << 2.330499, 1.951372, -0.4775414, 4.365726, -0.6244870, 1.038131, 1.594227;
  return p;
}

TestProblem MakeRosenbrock2() {
  TestProblem p = Start("Rosenbrock2", 2, "x");
  auto cost = std::make_shared<FunctionEvaluator>(
      "rosenbrock", 2, 1, Evaluator::DensePattern(1, 2),
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y) {
        y[0] = 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1 - x[0]) * (1 - x[0]);
      },
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y, Ref<VectorXd> j) {
        const double d = x[1] - x[0] * x[0];
        y[0] = 100 * d * d + (1 - x[0]) * (1 - x[0]);
        j << -400 * d * x[0] - 2 * (1 - x[0]), 200 * d;
      },
      std::vector<SparsityEntry>{{0, 0}, {1, 0}, {1, 1}},
      [](const Ref<const VectorXd>& x, const Ref<const VectorXd>& w, Ref<VectorXd> h) {
        h << 1200 * x[0] * x[0] - 400 * x[1] + 2, -400 * x[0], 200;
        h *= w[0];
      });
  p.prog->AddCost(cost, p.x);
  p.prog->SetInitialGuess(p.x, Eigen::Vector2d(-1.2, 1.0));
  p.optimal_cost = 0.0;
  p.optimal_x = Eigen::Vector2d(1.0, 1.0);
  return p;
}

TestProblem MakeChainedRosenbrock(int n) {
  TestProblem p = Start("ChainedRosenbrock" + std::to_string(n), n, "x");
  auto link = std::make_shared<FunctionEvaluator>(
      "rosenbrock_link", 2, 2, std::vector<SparsityEntry>{{0, 0}, {0, 1}, {1, 0}},
      [](const Ref<const VectorXd>& x, Ref<VectorXd> r) { r << 10 * (x[1] - x[0] * x[0]), 1 - x[0]; },
      [](const Ref<const VectorXd>& x, Ref<VectorXd> r, Ref<VectorXd> j) {
        r << 10 * (x[1] - x[0] * x[0]), 1 - x[0];
        j << -20 * x[0], 10, -1;
      },
      std::vector<SparsityEntry>{{0, 0}},
      [](const Ref<const VectorXd>&, const Ref<const VectorXd>& w, Ref<VectorXd> h) { h[0] = -20 * w[0]; });
  for (int i = 0; i + 1 < n; ++i) p.prog->AddLeastSquaresCost(link, p.x.Segment(i, 2));
  p.optimal_cost = 0.0;
  p.optimal_x = VectorXd::Ones(n);
  return p;
}

TestProblem MakeSparseChain(int n) {
  TestProblem p = Start("SparseChain" + std::to_string(n), n, "x");
  Eigen::SparseMatrix<double> Q(n, n);
  Q.setIdentity();
  Q *= 2.0;
  p.prog->AddQuadraticCost(Q, VectorXd::Constant(n, -4.0), 4.0 * n, p.x);
  auto link = std::make_shared<FunctionEvaluator>(
      "chain_link", 2, 1, std::vector<SparsityEntry>{{0, 0}, {0, 1}},
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y) { y[0] = x[0] * x[0] + x[1] * x[1]; },
      [](const Ref<const VectorXd>& x, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = x[0] * x[0] + x[1] * x[1];
        j << 2 * x[0], 2 * x[1];
      },
      std::vector<SparsityEntry>{{0, 0}, {1, 1}},
      [](const Ref<const VectorXd>&, const Ref<const VectorXd>& w, Ref<VectorXd> h) { h.setConstant(2 * w[0]); });
  const Eigen::Matrix<double, 1, 1> two(2.0);
  for (int i = 0; i + 1 < n; ++i) p.prog->AddConstraint(link, two, two, p.x.Segment(i, 2));
  p.prog->AddBoundingBoxConstraint(0.0, kInf, p.x);
  p.prog->SetInitialGuess(p.x, VectorXd::Constant(n, 0.5));
  p.optimal_cost = n;
  p.optimal_x = VectorXd::Ones(n);
  return p;
}

}  // namespace cairn::optimization::test
