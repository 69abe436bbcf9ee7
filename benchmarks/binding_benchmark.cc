// The cost of the Python bindings (issue 13): the same work done by C++ and by Python code called back from C++,
// in one run. The program embeds Python and imports `cairn` from the build tree (CAIRN_PYTHON_DIR), so the Python
// objects are the ones a user's script would make.
//
// - Output evaluation: a leaf system whose output is the time, evaluated after every time change (so the cache
//   never answers). C++: a LeafSystem subclass. Python: a cairn.systems.LeafSystem subclass. The GIL is released
//   around the C++ loop as Simulator.AdvanceTo releases it, so each Python evaluation takes and drops it.
// - Cost per Ipopt iteration: the chained Rosenbrock function (n = 20, analytic gradient, L-BFGS Hessian) from the
//   same start. C++: a FunctionEvaluator over C++ lambdas. Python: prog.AddCost(f, x, gradient=g) with numpy.
// Ratios: compare the rows' times (the `per_iteration` counter for the solves).

#include <cmath>
#include <memory>
#include <string>

#include <Eigen/Core>
#include <benchmark/benchmark.h>
#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include "cairn/optimization/function_evaluator.h"
#include "cairn/optimization/mathematical_program.h"
#include "cairn/optimization/solvers/ipopt_solver.h"
#include "cairn/systems/framework/context.h"
#include "cairn/systems/framework/leaf_system.h"

namespace {

namespace py = pybind11;
using cairn::optimization::FunctionEvaluator;
using cairn::optimization::IpoptSolver;
using cairn::optimization::MathematicalProgram;
using cairn::optimization::SolverOptions;
using cairn::optimization::SolverResult;
using cairn::systems::Context;
using cairn::systems::LeafSystem;
using cairn::systems::System;

constexpr int kRosenbrockSize = 20;

const char* kPythonCode = R"(
import numpy as np
import cairn.optimization as opt
from cairn.systems import LeafSystem


class Clock(LeafSystem):
    def __init__(self):
        super().__init__()
        self.DeclareVectorOutputPort("t", 1, self.CalcTime)

    def CalcTime(self, context, y):
        y[0] = context.get_time()


def rosenbrock(x):
    return float(np.sum(100.0 * (x[1:] - x[:-1] ** 2) ** 2 + (1.0 - x[:-1]) ** 2))


def rosenbrock_gradient(x):
    g = np.zeros_like(x)
    d = x[1:] - x[:-1] ** 2
    g[:-1] = -400.0 * x[:-1] * d - 2.0 * (1.0 - x[:-1])
    g[1:] += 200.0 * d
    return g


def rosenbrock_program(n):
    prog = opt.MathematicalProgram()
    x = prog.NewContinuousVariables(n, "x")
    prog.AddCost(rosenbrock, x, gradient=rosenbrock_gradient)
    prog.SetInitialGuess(x, np.full(n, -1.2))
    return prog
)";

// The interpreter and the objects the Python benchmarks use, made once.
struct PythonObjects {
  PythonObjects() {
    py::module_::import("sys").attr("path").attr("insert")(0, CAIRN_PYTHON_DIR);
    py::exec(kPythonCode, globals);
    clock = globals["Clock"]();
    clock_context = clock.attr("CreateDefaultContext")();
    program = globals["rosenbrock_program"](kRosenbrockSize);
  }
  py::scoped_interpreter interpreter;
  py::dict globals = py::globals();
  py::object clock;
  py::object clock_context;
  py::object program;
};

PythonObjects& Python() {
  static auto* objects = new PythonObjects();  // Never destroyed: the interpreter outlives every benchmark.
  return *objects;
}

class CppClock final : public LeafSystem {
 public:
  CppClock() {
    DeclareVectorOutputPort("t", 1, [](const Context& context, Eigen::VectorXd* y) { (*y)[0] = context.get_time(); });
  }
};

void EvalClock(benchmark::State& state, const System& system, Context* context) {
  double t = 0.0;
  double sum = 0.0;
  for (auto _ : state) {
    context->SetTime(t += 1e-3);
    sum += system.get_output_port(0).Eval<Eigen::VectorXd>(*context)[0];
  }
  benchmark::DoNotOptimize(sum);
}

void BM_OutputEval_Cpp(benchmark::State& state) {
  CppClock clock;
  auto context = clock.CreateDefaultContext();
  EvalClock(state, clock, context.get());
}
BENCHMARK(BM_OutputEval_Cpp);

void BM_OutputEval_Python(benchmark::State& state) {
  PythonObjects& python = Python();
  const auto& clock = python.clock.cast<const System&>();
  auto* context = python.clock_context.cast<Context*>();
  py::gil_scoped_release release;
  EvalClock(state, clock, context);
}
BENCHMARK(BM_OutputEval_Python);

MathematicalProgram CppRosenbrock(int n) {
  MathematicalProgram prog;
  const auto x = prog.NewContinuousVariables(n, "x");
  auto value = [](const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> y) {
    double f = 0.0;
    for (Eigen::Index i = 0; i + 1 < v.size(); ++i) {
      const double d = v[i + 1] - v[i] * v[i];
      f += 100.0 * d * d + (1.0 - v[i]) * (1.0 - v[i]);
    }
    y[0] = f;
  };
  auto jacobian = [value](const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> g) {
    value(v, y);
    g.setZero();
    for (Eigen::Index i = 0; i + 1 < v.size(); ++i) {
      const double d = v[i + 1] - v[i] * v[i];
      g[i] += -400.0 * v[i] * d - 2.0 * (1.0 - v[i]);
      g[i + 1] += 200.0 * d;
    }
  };
  prog.AddCost(std::make_shared<FunctionEvaluator>("rosenbrock", n, 1, FunctionEvaluator::DensePattern(1, n), value,
                                                   jacobian),
               x);
  prog.SetInitialGuess(x, Eigen::VectorXd::Constant(n, -1.2));
  return prog;
}

void SolveRepeatedly(benchmark::State& state, const MathematicalProgram& prog) {
  const IpoptSolver solver;
  int iterations = 0;
  for (auto _ : state) {
    const SolverResult result = solver.Solve(prog, prog.initial_guess());
    if (!result.is_success()) state.SkipWithError(result.message.c_str());
    iterations += result.iterations;
  }
  state.counters["iterations"] = static_cast<double>(iterations) / static_cast<double>(state.iterations());
  state.counters["per_iteration"] =
      benchmark::Counter(static_cast<double>(iterations), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_IpoptSolve_CppCost(benchmark::State& state) { SolveRepeatedly(state, CppRosenbrock(kRosenbrockSize)); }
BENCHMARK(BM_IpoptSolve_CppCost)->Unit(benchmark::kMillisecond);

void BM_IpoptSolve_PythonCost(benchmark::State& state) {
  PythonObjects& python = Python();
  const auto& prog = python.program.cast<const MathematicalProgram&>();
  py::gil_scoped_release release;  // as Solver.Solve from Python does
  SolveRepeatedly(state, prog);
}
BENCHMARK(BM_IpoptSolve_PythonCost)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
