#include "cairn/optimization/solvers/least_squares_solver.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cairn/optimization/autodiff_evaluator.h"
#include "cairn/optimization/function_evaluator.h"
#include "cairn/optimization/solvers/ipopt_solver.h"
#include "../test_problems.h"
#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using Eigen::Ref;
using Eigen::VectorXd;
using ::testing::HasSubstr;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Residuals a exp(-b t_i) + c - y_i of an exponential decay, with an analytic dense Jacobian.
std::shared_ptr<Evaluator> DecayResiduals(const VectorXd& t, const VectorXd& y) {
  const int m = static_cast<int>(t.size());
  return std::make_shared<FunctionEvaluator>(
      "decay_fit", 3, m, Evaluator::DensePattern(m, 3),
      [t, y](const Ref<const VectorXd>& p, Ref<VectorXd> r) {
        r = p[0] * (-p[1] * t.array()).exp().matrix() + VectorXd::Constant(t.size(), p[2]) - y;
      },
      [t, y](const Ref<const VectorXd>& p, Ref<VectorXd> r, Ref<VectorXd> j) {
        for (int i = 0; i < t.size(); ++i) {
          const double e = std::exp(-p[1] * t[i]);
          r[i] = p[0] * e + p[2] - y[i];
          j[3 * i] = e;
          j[3 * i + 1] = -p[0] * t[i] * e;
          j[3 * i + 2] = 1.0;
        }
      });
}

TEST(LeastSquaresSolverTest, ExponentialCurveFit) {
  const Eigen::Vector3d truth(2.5, 1.3, 0.5);
  VectorXd t = VectorXd::LinSpaced(40, 0.0, 4.0);
  VectorXd exact = truth[0] * (-truth[1] * t.array()).exp().matrix() + VectorXd::Constant(40, truth[2]);

  // Noise-free data: the fit recovers the generating parameters.
  {
    MathematicalProgram prog;
    const auto p = prog.NewContinuousVariables(3, "decay");
    prog.AddLeastSquaresCost(DecayResiduals(t, exact), p);
    prog.SetInitialGuess(p, Eigen::Vector3d(1.0, 0.5, 0.0));
    const SolverResult result = LeastSquaresSolver().Solve(prog);
    ASSERT_EQ(result.status, SolutionStatus::kSolved) << result.message;
    EXPECT_LT((result.x - truth).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT(result.objective, 1e-20);
  }
  // Noisy data: the least-squares optimum is the same point Ipopt finds for the same program.
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.02);
  VectorXd noisy = exact;
  for (int i = 0; i < noisy.size(); ++i) noisy[i] += noise(rng);
  MathematicalProgram prog;
  const auto p = prog.NewContinuousVariables(3, "decay");
  prog.AddLeastSquaresCost(DecayResiduals(t, noisy), p);
  prog.SetInitialGuess(p, Eigen::Vector3d(1.0, 0.5, 0.0));
  const SolverResult lm = LeastSquaresSolver().Solve(prog);
  SolverOptions tight;
  tight.Set("ipopt", "tol", 1e-12);
  const SolverResult ipopt = IpoptSolver().Solve(prog, prog.initial_guess(), tight);
  ASSERT_EQ(lm.status, SolutionStatus::kSolved) << lm.message;
  ASSERT_EQ(ipopt.status, SolutionStatus::kSolved) << ipopt.message;
  EXPECT_LT((lm.x - ipopt.x).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((lm.x - truth).cwiseAbs().maxCoeff(), 0.1);
  EXPECT_LE(lm.objective, ipopt.objective + 1e-12);

  // Gauss-Newton reaches the same optimum.
  SolverOptions gauss_newton;
  gauss_newton.Set("least_squares", "algorithm", "gauss_newton");
  const SolverResult gn = LeastSquaresSolver().Solve(prog, prog.initial_guess(), gauss_newton);
  ASSERT_EQ(gn.status, SolutionStatus::kSolved) << gn.message;
  EXPECT_LT((gn.x - lm.x).cwiseAbs().maxCoeff(), 1e-7);
}

// R p + t - q for one correspondence, with the rotation parameterised by the Gibbs vector g (Cayley):
// R = ((1 - g'g) I + 2 g g' + 2 [g]x) / (1 + g'g), smooth everywhere and exact for rotations below 180 degrees.
struct PointResidual {
  Eigen::Vector3d p, q;
  template <typename T>
  void operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& v, Eigen::Matrix<T, Eigen::Dynamic, 1>* r) const {
    const Eigen::Matrix<T, 3, 1> g = v.template head<3>();
    Eigen::Matrix<T, 3, 3> skew;
    skew << T(0), -g[2], g[1], g[2], T(0), -g[0], -g[1], g[0], T(0);
    const T gg = g.dot(g);
    const Eigen::Matrix<T, 3, 3> R =
        ((T(1) - gg) * Eigen::Matrix<T, 3, 3>::Identity() + T(2) * g * g.transpose() + T(2) * skew) / (T(1) + gg);
    const Eigen::Matrix<T, 3, 1> residual = R * p.cast<T>() + v.template tail<3>() - q.cast<T>();
    *r = residual;
  }
};

Eigen::Matrix3d GibbsToRotation(const Eigen::Vector3d& g) {
  Eigen::Matrix3d skew;
  skew << 0, -g[2], g[1], g[2], 0, -g[0], -g[1], g[0], 0;
  return ((1 - g.squaredNorm()) * Eigen::Matrix3d::Identity() + 2 * g * g.transpose() + 2 * skew) /
         (1 + g.squaredNorm());
}

TEST(LeastSquaresSolverTest, RigidRegistrationMatchesKabsch) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  const Eigen::Matrix3d R_true = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d t_true(0.3, -0.2, 0.5);
  const int n = 30;
  Eigen::Matrix3Xd P(3, n), Q(3, n);
  for (int i = 0; i < n; ++i) {
    P.col(i) << coordinate(rng), coordinate(rng), coordinate(rng);
    Q.col(i) = R_true * P.col(i) + t_true + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  }
  // Kabsch: the closed-form least-squares rotation from the SVD of the centred cross-covariance.
  const Eigen::Vector3d p_mean = P.rowwise().mean(), q_mean = Q.rowwise().mean();
  const Eigen::Matrix3d H = (P.colwise() - p_mean) * (Q.colwise() - q_mean).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  const Eigen::Matrix3d R_kabsch = svd.matrixV() * D * svd.matrixU().transpose();
  const Eigen::Vector3d t_kabsch = q_mean - R_kabsch * p_mean;

  MathematicalProgram prog;
  const auto pose = prog.NewContinuousVariables(6, "pose");
  for (int i = 0; i < n; ++i) {
    prog.AddLeastSquaresCost(std::make_shared<AutoDiffEvaluator<PointResidual>>(
                                 "point_" + std::to_string(i), 6, 3, PointResidual{P.col(i), Q.col(i)}),
                             pose);
  }
  const SolverResult result = LeastSquaresSolver().Solve(prog);
  ASSERT_EQ(result.status, SolutionStatus::kSolved) << result.message;
  const Eigen::Matrix3d R = GibbsToRotation(result.x.head<3>());
  EXPECT_LT((R - R_kabsch).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_LT((result.x.tail<3>() - t_kabsch).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_LT((R - R_true).cwiseAbs().maxCoeff(), 0.05);
}

TEST(LeastSquaresSolverTest, ChainedRosenbrockWithSparseNormalEquations) {
  const test::TestProblem p = test::MakeChainedRosenbrock(100);
  const SolverResult result = LeastSquaresSolver().Solve(*p.prog);
  ASSERT_EQ(result.status, SolutionStatus::kSolved) << result.message;
  EXPECT_LT((result.x - p.optimal_x).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT(result.objective, 1e-14);
}

TEST(LeastSquaresSolverTest, BoundsByProjectionAndLinearEqualities) {
  // Residuals x - c, c = (3, -1, 2), with 0 <= x <= 1.5 and then x0 + x1 + x2 = 2.
  // Box only: x = clamp(c) = (1.5, 0, 1.5). With the plane, KKT gives x_i = clamp(c_i - lambda); the sum is 2 for
  // lambda = 1.5: x = (1.5, 0, 0.5), with x0 exactly at its upper bound and x1 held at its lower bound.
  auto residual = std::make_shared<FunctionEvaluator>(
      "offset", 3, 3, std::vector<SparsityEntry>{{0, 0}, {1, 1}, {2, 2}},
      [](const Ref<const VectorXd>& x, Ref<VectorXd> r) { r = x - Eigen::Vector3d(3, -1, 2); },
      [](const Ref<const VectorXd>& x, Ref<VectorXd> r, Ref<VectorXd> j) {
        r = x - Eigen::Vector3d(3, -1, 2);
        j.setOnes();
      });
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(3, "x");
  prog.AddLeastSquaresCost(residual, x);
  prog.AddBoundingBoxConstraint(0.0, 1.5, x);
  const SolverResult boxed = LeastSquaresSolver().Solve(prog);
  ASSERT_EQ(boxed.status, SolutionStatus::kSolved) << boxed.message;
  EXPECT_LT((boxed.x - Eigen::Vector3d(1.5, 0, 1.5)).cwiseAbs().maxCoeff(), 1e-9);

  prog.AddLinearEqualityConstraint(Eigen::RowVector3d(1, 1, 1).sparseView(), Eigen::Matrix<double, 1, 1>(2.0), x);
  const SolverResult constrained = LeastSquaresSolver().Solve(prog);
  ASSERT_EQ(constrained.status, SolutionStatus::kSolved) << constrained.message;
  EXPECT_LT((constrained.x - Eigen::Vector3d(1.5, 0.0, 0.5)).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT(constrained.constraint_violation, 1e-9);
  // The multiplier of x0 + x1 + x2 = 2 (L = f + lambda g): stationarity in the free x2 gives (0.5 - 2) + lambda = 0.
  ASSERT_EQ(constrained.constraint_duals.size(), 1);
  EXPECT_NEAR(constrained.constraint_duals[0], 1.5, 1e-6);
}

TEST(LeastSquaresSolverTest, RejectsProgramsItCannotSolve) {
  const test::TestProblem hs35 = test::MakeHs035();
  EXPECT_THAT(LeastSquaresSolver().CheckSupport(*hs35.prog),
              HasSubstr("the cost 'QuadraticCost(x)' is not a least-squares cost; add it as a residual with "
                        "AddLeastSquaresCost, or use 'ipopt'"));
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(2, "x");
  CAIRN_EXPECT_THROWS_WITH(LeastSquaresSolver().Solve(prog), std::invalid_argument,
                           "the program has no least-squares costs");
  prog.AddLeastSquaresCost(std::make_shared<FunctionEvaluator>(
                               "identity", 2, 2,
                               [](const Ref<const VectorXd>& v, Ref<VectorXd> r) { r = v; }),
                           x);
  prog.AddLinearConstraint(Eigen::RowVector2d(1, 1).sparseView(), Eigen::Matrix<double, 1, 1>(1.0),
                           Eigen::Matrix<double, 1, 1>(kInf), x);
  EXPECT_THAT(LeastSquaresSolver().CheckSupport(prog),
              HasSubstr("the constraint 'LinearConstraint(x)' is not a linear equality; the least-squares solver "
                        "supports bounding boxes and LinearEqualityConstraints only, so use 'ipopt'"));
}

TEST(LeastSquaresSolverTest, RejectsUnknownOptions) {
  const test::TestProblem p = test::MakeChainedRosenbrock(4);
  SolverOptions typo;
  typo.Set("least_squares", "max_iteration", 5);
  CAIRN_EXPECT_THROWS_WITH(LeastSquaresSolver().Solve(*p.prog, p.prog->initial_guess(), typo), std::invalid_argument,
                           "unknown option 'max_iteration' (did you mean 'max_iterations'?)");
  SolverOptions bad_algorithm;
  bad_algorithm.Set("least_squares", "algorithm", "dogleg");
  CAIRN_EXPECT_THROWS_WITH(LeastSquaresSolver().Solve(*p.prog, p.prog->initial_guess(), bad_algorithm),
                           std::invalid_argument,
                           "option 'algorithm' = 'dogleg' is not valid; use 'levenberg_marquardt' or 'gauss_newton'");
  // Values out of range were used as given before (a negative count ran no iteration; a zero outer count was
  // silently raised to one).
  const std::vector<std::pair<SolverOptions, std::string>> out_of_range = [] {
    std::vector<std::pair<SolverOptions, std::string>> cases(6);
    cases[0].first.Set("least_squares", "max_iterations", -1);
    cases[0].second = "option 'max_iterations' = -1 must be >= 1";
    cases[1].first.Set("least_squares", "max_outer_iterations", 0);
    cases[1].second = "option 'max_outer_iterations' = 0 must be >= 1";
    cases[2].first.Set("least_squares", "gradient_tolerance", -1e-8);
    cases[2].second = "option 'gradient_tolerance' = -1e-08 must be finite and >= 0";
    cases[3].first.Set("least_squares", "initial_damping", 0.0);
    cases[3].second = "option 'initial_damping' = 0 must be finite and > 0";
    cases[4].first.Set("least_squares", "step_tolerance", std::numeric_limits<double>::infinity());
    cases[4].second = "option 'step_tolerance' = inf must be finite";
    cases[5].first.Set("least_squares", "constraint_tol", -1);
    cases[5].second = "option 'constraint_tol' = -1 must be finite and >= 0";
    return cases;
  }();
  for (const auto& [options, message] : out_of_range) {
    CAIRN_EXPECT_THROWS_WITH(LeastSquaresSolver().Solve(*p.prog, p.prog->initial_guess(), options),
                             std::invalid_argument, message);
  }
  SolverOptions limit;
  limit.Set("least_squares", "max_iterations", 2);
  const SolverResult limited = LeastSquaresSolver().Solve(*p.prog, p.prog->initial_guess(), limit);
  EXPECT_EQ(limited.status, SolutionStatus::kIterationLimit);
  EXPECT_EQ(limited.iterations, 2);
}

}  // namespace
}  // namespace cairn::optimization
