"""Long C++ calls release the GIL: a Python thread keeps running while they work."""

import threading
import time

import numpy as np

import cairn.optimization as opt
import cairn.planning as planning
from cairn.systems import ConstantVectorSource, DiagramBuilder, Integrator, Simulator
from conftest import source_path


def ticks_during(call):
    """Runs `call` while another Python thread records timestamps; returns the number recorded strictly inside the
    call (none can be if the call holds the GIL: a woken thread needs it to record) and the call's result."""
    stamps = []
    stop = threading.Event()
    started = threading.Event()

    def count():
        started.set()
        while not stop.is_set():
            stamps.append(time.perf_counter())
            time.sleep(0.0005)

    thread = threading.Thread(target=count)
    thread.start()
    started.wait()
    begin = time.perf_counter()
    result = call()
    end = time.perf_counter()
    stop.set()
    thread.join()
    return sum(1 for t in stamps if begin < t < end), result


def test_ipopt_solve_releases_the_gil():
    n = 600
    rng = np.random.default_rng(0)
    A = rng.standard_normal((n, n))
    prog = opt.MathematicalProgram()
    x = prog.NewContinuousVariables(n, "x")
    prog.AddQuadraticCost(A.T @ A + np.eye(n), rng.standard_normal(n), 0.0, x)
    prog.AddBoundingBoxConstraint(-0.1, 0.1, x)
    ticks, result = ticks_during(lambda: opt.IpoptSolver().Solve(prog))
    assert result.is_success(), result.message
    assert ticks >= 3


def test_python_cost_in_a_solve_lets_other_threads_run():
    prog = opt.MathematicalProgram()
    x = prog.NewContinuousVariables(2, "x")

    def slow_cost(v):
        time.sleep(0.002)  # releases the GIL itself; the solver must not hold it either
        return (v[0] - 1.0) ** 2 + (v[1] + 2.0) ** 2

    prog.AddCost(slow_cost, x, gradient=lambda v: np.array([2.0 * (v[0] - 1.0), 2.0 * (v[1] + 2.0)]))
    ticks, result = ticks_during(lambda: opt.IpoptSolver().Solve(prog))
    assert result.is_success()
    np.testing.assert_allclose(result.x, [1.0, -2.0], atol=1e-6)
    assert ticks >= 3


def test_simulation_releases_the_gil():
    builder = DiagramBuilder()
    source = builder.AddSystem(ConstantVectorSource(np.array([1.0])))
    integrator = builder.AddSystem(Integrator(1))
    builder.Connect(source.get_output_port(0), integrator.get_input_port(0))
    simulator = Simulator(builder.Build())
    simulator.set_target_realtime_rate(1.0)  # 0.2 s of wall time in C++
    ticks, status = ticks_during(lambda: simulator.AdvanceTo(0.2))
    assert status.reached_boundary_time()
    assert ticks >= 3


def test_planning_releases_the_gil(walking_model, oracle):
    scenario = planning.FootstepScenario.Load(source_path("examples", "scenarios", "ice_narrow_012.yaml"))
    options = scenario.planner()
    options.search.max_expansions = 30000
    options.search.time_limit = float("inf")
    terrain = scenario.BuildTerrain()
    geometry = planning.BipedGeometry.FromWalkingModel(walking_model)
    ticks, plan = ticks_during(
        lambda: planning.PlanFootsteps(terrain, scenario.start(), scenario.goal(), oracle, geometry, options))
    assert plan.found
    assert ticks >= 3
