"""cairn.optimization: programs with built-in and Python costs and constraints, solvers by name, results."""

import pickle

import numpy as np
import pytest

from cairn.optimization import (CheckGradients, FunctionEvaluator, IpoptSolver, LeastSquaresSolver, LinearCost,
                                MakeSolver, MathematicalProgram, QuadraticCost, SolutionStatus, Solve, SolverOptions,
                                SolverResult, to_string)


def rosenbrock(x):
    return (1.0 - x[0]) ** 2 + 100.0 * (x[1] - x[0] ** 2) ** 2


def rosenbrock_gradient(x):
    return np.array([-2.0 * (1.0 - x[0]) - 400.0 * x[0] * (x[1] - x[0] ** 2), 200.0 * (x[1] - x[0] ** 2)])


@pytest.mark.parametrize("with_gradient", [True, False])
def test_python_cost_solved_by_ipopt(with_gradient):
    prog = MathematicalProgram()
    x = prog.NewContinuousVariables(2, "x")
    calls = []

    def cost(values):
        calls.append(1)
        return rosenbrock(values)

    prog.AddCost(cost, x, gradient=rosenbrock_gradient if with_gradient else None)
    prog.SetInitialGuess(x, [-1.2, 1.0])
    result = IpoptSolver().Solve(prog)
    assert result.is_success(), result.message
    assert result.status == SolutionStatus.kSolved
    np.testing.assert_allclose(result.x, [1.0, 1.0], atol=1e-5)
    assert result.objective == pytest.approx(0.0, abs=1e-9)
    assert len(calls) > 10
    assert result.iterations > 0


def test_hs071_with_python_constraints_and_jacobians():
    # Hock-Schittkowski 71: min x0 x3 (x0 + x1 + x2) + x2  s.t. x0 x1 x2 x3 >= 25, sum x_i^2 = 40, 1 <= x <= 5.
    prog = MathematicalProgram()
    x = prog.NewContinuousVariables(4, "x")
    prog.AddCost(lambda v: v[0] * v[3] * (v[0] + v[1] + v[2]) + v[2], x,
                 gradient=lambda v: np.array([v[3] * (2 * v[0] + v[1] + v[2]), v[0] * v[3], v[0] * v[3] + 1.0,
                                              v[0] * (v[0] + v[1] + v[2])]))
    prog.AddConstraint(lambda v: [v[0] * v[1] * v[2] * v[3]], [25.0], [np.inf], x,
                       jacobian=lambda v: np.array([[v[1] * v[2] * v[3], v[0] * v[2] * v[3], v[0] * v[1] * v[3],
                                                     v[0] * v[1] * v[2]]]),
                       name="product")
    prog.AddConstraint(lambda v: [np.dot(v, v)], [40.0], [40.0], x, jacobian=lambda v: 2.0 * np.asarray(v)[None, :],
                       name="sphere")
    prog.AddBoundingBoxConstraint(1.0, 5.0, x)
    prog.SetInitialGuess(x, [1.0, 5.0, 5.0, 1.0])
    assert CheckGradients(prog, np.array([1.5, 2.5, 3.5, 1.2])).passed
    result = MakeSolver("ipopt").Solve(prog)
    assert result.is_success(), result.message
    assert result.objective == pytest.approx(17.0140173, rel=1e-6)
    np.testing.assert_allclose(result.x, [1.0, 4.742999, 3.821151, 1.379408], atol=1e-5)
    assert result.constraint_duals.shape == (2,)
    # The same program by NLopt's SLSQP.
    slsqp = MakeSolver("nlopt:SLSQP").Solve(prog)
    assert slsqp.is_success(), slsqp.message
    assert slsqp.objective == pytest.approx(17.0140173, rel=1e-5)


def test_builtin_costs_and_constraints():
    prog = MathematicalProgram()
    x = prog.NewContinuousVariables(2, "x")
    # min 1/2 x'Qx - x0 s.t. x0 + x1 = 1 (C-ordered Q: copied into Eigen's column-major storage).
    prog.AddQuadraticCost(np.array([[2.0, 0.0], [0.0, 2.0]]), np.array([-1.0, 0.0]), 0.0, x)
    prog.AddLinearEqualityConstraint(np.array([[1.0, 1.0]]), np.array([1.0]), x)
    result = Solve(prog)
    assert result.solver_name == "ipopt"
    np.testing.assert_allclose(result.x, [0.75, 0.25], atol=1e-7)
    cost = prog.costs()[0].evaluator()
    assert isinstance(cost, QuadraticCost)
    np.testing.assert_array_equal(cost.Q(), [[2.0, 0.0], [0.0, 2.0]])
    assert LinearCost(np.array([1.0, 2.0]), 3.0).Eval(np.array([1.0, 1.0]))[0] == 6.0
    assert len(prog.constraints()) == 1 and prog.constraints()[0].variables().indices() == [0, 1]


def test_least_squares_with_a_python_residual():
    prog = MathematicalProgram()
    p = prog.NewContinuousVariables(2, "p")
    t = np.linspace(0.0, 1.0, 20)
    y = 3.0 * t + 0.5
    prog.AddLeastSquaresCost(lambda v: v[0] * t + v[1] - y, p, 20,
                             jacobian=lambda v: np.stack([t, np.ones_like(t)], axis=1))
    result = LeastSquaresSolver().Solve(prog)
    assert result.is_success(), result.message
    np.testing.assert_allclose(result.x, [3.0, 0.5], atol=1e-9)


def test_gauss_newton_least_squares_hessian_in_ipopt():
    # The residual declares no Hessian: Ipopt's exact mode needs the Gauss-Newton J'J for it.
    prog = MathematicalProgram()
    p = prog.NewContinuousVariables(2, "p")
    t = np.linspace(0.0, 1.0, 20)
    y = np.exp(0.7 * t) * 1.5
    prog.AddLeastSquaresCost(lambda v: v[0] * np.exp(v[1] * t) - y, p, 20,
                             jacobian=lambda v: np.stack([np.exp(v[1] * t), v[0] * t * np.exp(v[1] * t)], axis=1))
    options = SolverOptions()
    options.Set("ipopt", "hessian_approximation", "exact")
    with pytest.raises(ValueError, match="needs a Hessian from every cost"):
        IpoptSolver().Solve(prog, np.array([1.0, 0.0]), options)
    options.Set("ipopt", "least_squares_hessian", "gauss-newton")
    result = IpoptSolver().Solve(prog, np.array([1.0, 0.0]), options)
    assert result.is_success(), result.message
    np.testing.assert_allclose(result.x, [1.5, 0.7], atol=1e-6)


def test_function_evaluator_with_sparse_pattern_and_hessian():
    # f(x) = [x0^2, x1 x2]; pattern entries (0, 0), (1, 1), (1, 2).
    evaluator = FunctionEvaluator(
        "f", 3, 2, lambda x: [x[0] ** 2, x[1] * x[2]],
        jacobian=lambda x: ([x[0] ** 2, x[1] * x[2]], [2 * x[0], x[2], x[1]]),
        jacobian_pattern=[(0, 0), (1, 1), (1, 2)])
    x = np.array([1.0, 2.0, 3.0])
    np.testing.assert_array_equal(evaluator.Eval(x), [1.0, 6.0])
    np.testing.assert_array_equal(evaluator.EvalJacobian(x), [[2.0, 0.0, 0.0], [0.0, 3.0, 2.0]])
    assert CheckGradients(evaluator, x).passed
    assert evaluator.jacobian_pattern() == [(0, 0), (1, 1), (1, 2)]


def test_solver_options_and_results():
    prog = MathematicalProgram()
    x = prog.NewContinuousVariables(2, "x")
    prog.AddCost(rosenbrock, x, gradient=rosenbrock_gradient)
    options = SolverOptions()
    options.Set("ipopt", "max_iter", 3)
    options.Set("ipopt", "tol", 1e-12)
    options.Set("ipopt", "hessian_approximation", "limited-memory")
    assert options.Get("ipopt") == {"hessian_approximation": "limited-memory", "max_iter": 3, "tol": 1e-12}
    result = IpoptSolver().Solve(prog, np.array([-1.2, 1.0]), options)
    assert result.status == SolutionStatus.kIterationLimit
    assert to_string(result.status) == "iteration limit"
    copy = pickle.loads(pickle.dumps(result))
    assert isinstance(copy, SolverResult)
    assert copy.status == result.status and copy.message == result.message
    np.testing.assert_array_equal(copy.x, result.x)
    bad = SolverOptions()
    bad.Set("ipopt", "max_itr", 3)
    with pytest.raises(ValueError, match="max_iter"):
        IpoptSolver().Solve(prog, None, bad)


def test_errors_carry_the_cpp_messages():
    prog = MathematicalProgram()
    with pytest.raises(ValueError, match="n < 1|at least one|n = 0|0"):
        prog.NewContinuousVariables(0, "x")
    with pytest.raises(ValueError, match="ipopt"):
        MakeSolver("ipopot")
    x = prog.NewContinuousVariables(2, "x")
    other = MathematicalProgram().NewContinuousVariables(2, "y")
    with pytest.raises(ValueError, match="program"):
        prog.AddLinearCost(np.ones(2), 0.0, other)

    def broken(values):
        raise KeyError("a Python cost failed")

    prog.AddCost(broken, x)
    with pytest.raises(KeyError, match="a Python cost failed"):
        IpoptSolver().Solve(prog)
    wrong_size = MathematicalProgram()
    y = wrong_size.NewContinuousVariables(2, "y")
    wrong_size.AddCost(lambda v: [1.0, 2.0], y)
    with pytest.raises(ValueError, match="returned 2 values, expected 1"):
        IpoptSolver().Solve(wrong_size)


def test_decision_variable_indexing():
    prog = MathematicalProgram()
    x = prog.NewContinuousVariables(5, "x")
    assert len(x) == 5 and x[1].indices() == [1] and x[-1].indices() == [4]
    assert x[1:3].indices() == [1, 2]
    assert prog.VariableName(3) == "x(3)"
    with pytest.raises(IndexError):
        x[5]
