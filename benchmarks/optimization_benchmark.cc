// Framework overhead of Cairn::optimization against the raw solver APIs, measured in the same run:
//  - the sparse chain (n = 10,000) through MathematicalProgram + IpoptSolver vs a hand-written Ipopt TNLP;
//  - a 5-variable constrained SLSQP problem (the footstep oracle's size) through NloptSolver vs raw NLopt.
// Both sides use the same options, so they take the same iterations; the counters report them.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>
#include <benchmark/benchmark.h>
#include <nlopt.hpp>

#include "cairn/optimization/function_evaluator.h"
#include "cairn/optimization/mathematical_program.h"
#include "cairn/optimization/solvers/ipopt_solver.h"
#include "cairn/optimization/solvers/nlopt_solver.h"

namespace {

using cairn::optimization::DecisionVariables;
using cairn::optimization::Evaluator;
using cairn::optimization::FunctionEvaluator;
using cairn::optimization::IpoptSolver;
using cairn::optimization::MathematicalProgram;
using cairn::optimization::NloptSolver;
using cairn::optimization::SolutionStatus;
using cairn::optimization::SolverResult;
using cairn::optimization::SparsityEntry;
using Eigen::Ref;
using Eigen::VectorXd;

constexpr int kChainSize = 10000;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- The chain: min sum (x_i - 2)^2 s.t. x_i^2 + x_{i+1}^2 = 2, x >= 0, from x = 0.5; optimum x = 1. ----

std::unique_ptr<MathematicalProgram> MakeChainProgram(int n) {
  auto prog = std::make_unique<MathematicalProgram>();
  const DecisionVariables x = prog->NewContinuousVariables(n, "x");
  Eigen::SparseMatrix<double> Q(n, n);
  Q.setIdentity();
  Q *= 2.0;
  prog->AddQuadraticCost(Q, VectorXd::Constant(n, -4.0), 4.0 * n, x);
  auto link = std::make_shared<FunctionEvaluator>(
      "chain_link", 2, 1, std::vector<SparsityEntry>{{0, 0}, {0, 1}},
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = v[0] * v[0] + v[1] * v[1]; },
      [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
        y[0] = v[0] * v[0] + v[1] * v[1];
        j[0] = 2 * v[0];
        j[1] = 2 * v[1];
      },
      std::vector<SparsityEntry>{{0, 0}, {1, 1}},
      [](const Ref<const VectorXd>&, const Ref<const VectorXd>& w, Ref<VectorXd> h) { h.setConstant(2 * w[0]); });
  const Eigen::Matrix<double, 1, 1> two(2.0);
  for (int i = 0; i + 1 < n; ++i) prog->AddConstraint(link, two, two, x.Segment(i, 2));
  prog->AddBoundingBoxConstraint(0.0, kInf, x);
  prog->SetInitialGuess(x, VectorXd::Constant(n, 0.5));
  return prog;
}

// The same problem written directly against Ipopt's TNLP, as one would without Cairn.
class ChainTnlp final : public Ipopt::TNLP {
 public:
  explicit ChainTnlp(int n) : n_(n) {}
  double objective() const { return objective_; }

  bool get_nlp_info(Ipopt::Index& n, Ipopt::Index& m, Ipopt::Index& nnz_jac_g, Ipopt::Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = n_;
    m = n_ - 1;
    nnz_jac_g = 2 * (n_ - 1);
    nnz_h_lag = n_;
    index_style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Ipopt::Index n, Ipopt::Number* x_l, Ipopt::Number* x_u, Ipopt::Index m, Ipopt::Number* g_l,
                       Ipopt::Number* g_u) override {
    std::fill(x_l, x_l + n, 0.0);
    std::fill(x_u, x_u + n, 1e20);
    std::fill(g_l, g_l + m, 2.0);
    std::fill(g_u, g_u + m, 2.0);
    return true;
  }
  bool get_starting_point(Ipopt::Index n, bool, Ipopt::Number* x, bool, Ipopt::Number*, Ipopt::Number*, Ipopt::Index,
                          bool, Ipopt::Number*) override {
    std::fill(x, x + n, 0.5);
    return true;
  }
  bool eval_f(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number& f) override {
    f = 0.0;
    for (Ipopt::Index i = 0; i < n; ++i) f += (x[i] - 2.0) * (x[i] - 2.0);
    return true;
  }
  bool eval_grad_f(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number* g) override {
    for (Ipopt::Index i = 0; i < n; ++i) g[i] = 2.0 * (x[i] - 2.0);
    return true;
  }
  bool eval_g(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Index m, Ipopt::Number* g) override {
    for (Ipopt::Index i = 0; i < m; ++i) g[i] = x[i] * x[i] + x[i + 1] * x[i + 1];
    return true;
  }
  bool eval_jac_g(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Index m, Ipopt::Index, Ipopt::Index* rows,
                  Ipopt::Index* cols, Ipopt::Number* values) override {
    for (Ipopt::Index i = 0; i < m; ++i) {
      if (values == nullptr) {
        rows[2 * i] = rows[2 * i + 1] = i;
        cols[2 * i] = i;
        cols[2 * i + 1] = i + 1;
      } else {
        values[2 * i] = 2.0 * x[i];
        values[2 * i + 1] = 2.0 * x[i + 1];
      }
    }
    return true;
  }
  bool eval_h(Ipopt::Index n, const Ipopt::Number*, bool, Ipopt::Number obj_factor, Ipopt::Index m,
              const Ipopt::Number* lambda, bool, Ipopt::Index, Ipopt::Index* rows, Ipopt::Index* cols,
              Ipopt::Number* values) override {
    for (Ipopt::Index i = 0; i < n; ++i) {
      if (values == nullptr) {
        rows[i] = cols[i] = i;
      } else {
        values[i] = 2.0 * obj_factor + (i > 0 ? 2.0 * lambda[i - 1] : 0.0) + (i < m ? 2.0 * lambda[i] : 0.0);
      }
    }
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn, Ipopt::Index, const Ipopt::Number*, const Ipopt::Number*,
                         const Ipopt::Number*, Ipopt::Index, const Ipopt::Number*, const Ipopt::Number*,
                         Ipopt::Number obj_value, const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    objective_ = obj_value;
  }

 private:
  int n_;
  double objective_{0.0};
};

void BM_ChainIpoptFramework(benchmark::State& state) {
  const auto prog = MakeChainProgram(kChainSize);
  const IpoptSolver solver;
  SolverResult result;
  for (auto _ : state) {
    result = solver.Solve(*prog);
    benchmark::DoNotOptimize(result.x.data());
  }
  state.counters["solved"] = result.status == SolutionStatus::kSolved;
  state.counters["objective"] = result.objective;
  state.counters["iterations"] = result.iterations;
}
BENCHMARK(BM_ChainIpoptFramework)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_ChainIpoptFrameworkIncludingBuild(benchmark::State& state) {
  SolverResult result;
  for (auto _ : state) {
    const auto prog = MakeChainProgram(kChainSize);
    result = IpoptSolver().Solve(*prog);
    benchmark::DoNotOptimize(result.x.data());
  }
  state.counters["iterations"] = result.iterations;
}
BENCHMARK(BM_ChainIpoptFrameworkIncludingBuild)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_ChainIpoptRawTnlp(benchmark::State& state) {
  int iterations = 0;
  double objective = 0.0;
  for (auto _ : state) {
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
    app->Options()->SetIntegerValue("print_level", 0);
    app->Options()->SetStringValue("sb", "yes");
    app->Options()->SetStringValue("hessian_approximation", "exact");
    app->Initialize("");
    Ipopt::SmartPtr<ChainTnlp> tnlp = new ChainTnlp(kChainSize);
    const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(tnlp));
    if (status != Ipopt::Solve_Succeeded) state.SkipWithError("raw Ipopt did not solve the chain");
    iterations = app->Statistics()->IterationCount();
    objective = tnlp->objective();
    benchmark::ClobberMemory();
  }
  state.counters["objective"] = objective;
  state.counters["iterations"] = iterations;
}
BENCHMARK(BM_ChainIpoptRawTnlp)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// ---- A 5-variable constrained problem, the footstep oracle's size:
// min sum (x_i - c_i)^2 + x0 x1  s.t.  |x|^2 <= 4,  x0 + x1 + x2 = 1,  -2 <= x <= 2. ----

const double kCentre[5] = {1.5, -0.5, 1.0, 2.0, -1.0};

double SmallCost(const double* x, double* grad) {
  double f = x[0] * x[1];
  for (int i = 0; i < 5; ++i) f += (x[i] - kCentre[i]) * (x[i] - kCentre[i]);
  if (grad != nullptr) {
    for (int i = 0; i < 5; ++i) grad[i] = 2.0 * (x[i] - kCentre[i]);
    grad[0] += x[1];
    grad[1] += x[0];
  }
  return f;
}

// Shared by both sides so that they compute bit-identical values: SLSQP's end game with ftol_rel = 1e-14 reacts
// to last-bit differences (Eigen's vectorised squaredNorm sums in another order than a plain loop).
double SmallBall(const double* x, double* grad) {
  double s = 0.0;
  for (int i = 0; i < 5; ++i) {
    s += x[i] * x[i];
    if (grad != nullptr) grad[i] = 2.0 * x[i];
  }
  return s;
}

std::unique_ptr<MathematicalProgram> MakeSmallProgram() {
  auto prog = std::make_unique<MathematicalProgram>();
  const DecisionVariables x = prog->NewContinuousVariables(5, "step");
  prog->AddCost(std::make_shared<FunctionEvaluator>(
                    "small_cost", 5, 1, Evaluator::DensePattern(1, 5),
                    [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = SmallCost(v.data(), nullptr); },
                    [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
                      y[0] = SmallCost(v.data(), j.data());
                    }),
                x);
  prog->AddConstraint(std::make_shared<FunctionEvaluator>(
                          "small_ball", 5, 1, Evaluator::DensePattern(1, 5),
                          [](const Ref<const VectorXd>& v, Ref<VectorXd> y) { y[0] = SmallBall(v.data(), nullptr); },
                          [](const Ref<const VectorXd>& v, Ref<VectorXd> y, Ref<VectorXd> j) {
                            y[0] = SmallBall(v.data(), j.data());
                          }),
                      Eigen::Matrix<double, 1, 1>(-kInf), Eigen::Matrix<double, 1, 1>(4.0), x);
  Eigen::Matrix<double, 1, 5> a;
  a << 1, 1, 1, 0, 0;
  prog->AddLinearEqualityConstraint(a.sparseView(), Eigen::Matrix<double, 1, 1>(1.0), x);
  prog->AddBoundingBoxConstraint(-2.0, 2.0, x);
  return prog;
}

void BM_SmallSlsqpFramework(benchmark::State& state) {
  const auto prog = MakeSmallProgram();
  const NloptSolver solver("SLSQP");
  SolverResult result;
  for (auto _ : state) {
    result = solver.Solve(*prog);
    benchmark::DoNotOptimize(result.x.data());
  }
  if (result.status != SolutionStatus::kSolved) state.SkipWithError("the framework did not solve the problem");
  state.counters["evaluations"] = result.evaluations;
  state.counters["objective"] = result.objective;
}
BENCHMARK(BM_SmallSlsqpFramework)->Unit(benchmark::kMicrosecond)->MinTime(2.0);

double RawObjective(unsigned, const double* x, double* grad, void*) { return SmallCost(x, grad); }

double RawBall(unsigned, const double* x, double* grad, void*) { return SmallBall(x, grad) - 4.0; }

double RawPlane(unsigned, const double* x, double* grad, void*) {
  if (grad != nullptr) {
    const double g[5] = {1, 1, 1, 0, 0};
    std::copy(g, g + 5, grad);
  }
  return x[0] + x[1] + x[2] - 1.0;
}

void BM_SmallSlsqpRawNlopt(benchmark::State& state) {
  double objective = 0.0;
  int evaluations = 0;
  for (auto _ : state) {
    // The same settings the framework uses by default, so both run the same iterations.
    nlopt::opt opt(nlopt::LD_SLSQP, 5);
    opt.set_lower_bounds(std::vector<double>(5, -2.0));
    opt.set_upper_bounds(std::vector<double>(5, 2.0));
    opt.set_min_objective(RawObjective, nullptr);
    opt.add_inequality_constraint(RawBall, nullptr, 1e-8);
    opt.add_equality_constraint(RawPlane, nullptr, 1e-8);
    opt.set_xtol_rel(1e-10);
    opt.set_ftol_rel(1e-14);
    opt.set_maxeval(100000);
    opt.set_stopval(-1e20);
    std::vector<double> x(5, 0.0);
    try {
      opt.optimize(x, objective);
    } catch (const nlopt::roundoff_limited&) {
    }
    evaluations = opt.get_numevals();
    benchmark::ClobberMemory();
  }
  state.counters["evaluations"] = evaluations;
  state.counters["objective"] = objective;
}
BENCHMARK(BM_SmallSlsqpRawNlopt)->Unit(benchmark::kMicrosecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
