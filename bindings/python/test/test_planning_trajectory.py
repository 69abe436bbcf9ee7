"""cairn.planning, whole body: OptimizeWholeBodyTrajectory and the TrajectoryOptimizer system on a small plan."""

import math

import numpy as np
import pytest

import cairn.multibody as mb
import cairn.planning as planning
from conftest import source_path

HUMANOID = source_path("data", "robots", "cairn_humanoid.urdf")


@pytest.fixture(scope="module")
def model():
    options = mb.UrdfOptions()
    options.floating_base = True
    return mb.ParseUrdfFile(HUMANOID, options)


def one_step_plan():
    plan = planning.FootstepPlan()
    plan.found = True
    plan.start = planning.Stance(planning.FootPose(x=0.0, y=0.1), planning.FootPose(x=0.0, y=-0.1))
    step = planning.PlannedStep()
    step.side = planning.FootSide.kRight
    step.pose = planning.FootPose(x=0.15, y=-0.1)
    transition = step.transition
    transition.feasible = True
    parameters = transition.parameters
    parameters.t_ds, parameters.t_sw = 0.2, 0.6
    transition.parameters = parameters
    step.transition = transition
    plan.steps = [step]
    return plan


def test_the_function_solves_a_step_within_the_constraints(model):
    trajectory = planning.OptimizeWholeBodyTrajectory(model, one_step_plan())
    assert trajectory.found, trajectory.report.message
    assert [w.label for w in trajectory.waypoints] == ["stance 0 start", "stance 0 mid-swing", "stance 1 start"]
    assert trajectory.waypoints[1].contacts == ["l_sole"]
    assert len(trajectory.coordinate_names) == model.nq()
    assert trajectory.report.solver == "ipopt" and trajectory.report.iterations > 0
    for w in trajectory.waypoints:
        assert w.q.shape == (model.nq(),)
        assert abs(np.linalg.norm(w.q[3:7]) - 1.0) < 1e-9
        assert w.min_clearance > 0.025 - 0.01
    assert 0.0 < trajectory.report.torque_cost <= trajectory.report.objective
    # The waypoints' torque terms are the report's, split by waypoint (what the pipeline oracle prices steps with).
    assert all(w.torque_cost > 0.0 for w in trajectory.waypoints)
    assert sum(w.torque_cost for w in trajectory.waypoints) == pytest.approx(trajectory.report.torque_cost, rel=1e-12)


def test_the_waist_orientation_smoothness_option_is_exposed_and_validated(model):
    options = planning.TrajectoryOptimizerOptions()
    assert options.base_rotation_smoothness_weight == 0.0
    options.base_rotation_smoothness_weight = 1.0
    trajectory = planning.OptimizeWholeBodyTrajectory(model, one_step_plan(), [], options)
    assert trajectory.found, trajectory.report.message
    options.base_rotation_smoothness_weight = -1.0
    with pytest.raises(ValueError, match="base_rotation_smoothness_weight is -1"):
        planning.OptimizeWholeBodyTrajectory(model, one_step_plan(), [], options)


def test_the_warm_start_height_is_exposed_and_validated(model):
    # A crouched warm start: the refined high-bar plan solves from 0.7 m where it stalls from 0.8 m (docs/walk.md).
    options = planning.TrajectoryOptimizerOptions()
    assert options.nominal_pelvis_height == pytest.approx(0.8)
    options.nominal_pelvis_height = 0.7
    trajectory = planning.OptimizeWholeBodyTrajectory(model, one_step_plan(), [], options)
    assert trajectory.found, trajectory.report.message
    options.nominal_pelvis_height = 0.0
    with pytest.raises(ValueError, match="nominal_pelvis_height"):
        planning.OptimizeWholeBodyTrajectory(model, one_step_plan(), [], options)


def test_the_system_solves_in_an_event_and_reports_failures_by_name(model):
    from cairn.systems import Simulator

    options = planning.TrajectoryOptimizerOptions()
    options.max_iterations = 100
    system = planning.TrajectoryOptimizer(model, options)
    context = system.CreateDefaultContext()
    plan = one_step_plan()
    steps = plan.steps
    steps[0].pose = planning.FootPose(x=1.5, y=-0.1)  # out of reach
    plan.steps = steps
    system.get_plan_input_port().FixValue(context, plan)
    system.get_environment_input_port().FixValue(
        context, [planning.EnvironmentBox("bar", np.array([0.1, 2.0, 0.1]), np.array([3.0, 0.0, 1.5]))])
    before = system.get_trajectory_output_port().Eval(context)
    assert not before.found and before.report.status == "not solved yet"
    simulator = Simulator(system, context)
    simulator.Initialize()
    after = system.get_trajectory_output_port().Eval(simulator.get_context())
    assert not after.found
    assert after.report.violations and after.report.violations[0].startswith("stance 1 start, ")
    with pytest.raises(ValueError, match="d_safe"):
        bad = planning.TrajectoryOptimizerOptions()
        bad.d_safe = -1.0
        planning.TrajectoryOptimizer(model, bad)
    assert math.isfinite(after.report.seconds)


def slope(degrees):
    a = math.radians(degrees)
    terrain = planning.TerrainMap(np.array([-1.0, -1.0]), 40, 40, 0.05)
    for row in range(terrain.rows()):
        for col in range(terrain.cols()):
            terrain.SetCell(col, row, terrain.CellCenter(col, row)[0] * math.tan(a),
                            np.array([-math.sin(a), 0.0, math.cos(a)]), 1.0)
    return terrain


def test_on_a_terrain_the_soles_are_laid_on_its_slope(model):
    terrain = slope(10.0)
    normal = np.array([-math.sin(math.radians(10.0)), 0.0, math.cos(math.radians(10.0))])
    level = planning.SoleTargetPose(planning.FootPose(x=0.1, y=0.1))
    assert np.allclose(level.rotation(), np.eye(3))
    tilted = planning.SoleTargetPose(planning.FootPose(x=0.1, y=0.1), terrain)
    assert np.allclose(tilted.rotation()[:, 2], normal, atol=1e-6)
    plan = one_step_plan()
    plan.steps[0].pose = planning.FootPose(x=0.15, y=-0.1, z=0.15 * math.tan(math.radians(10.0)))
    trajectory = planning.OptimizeWholeBodyTrajectory(model, plan, terrain=terrain)
    assert trajectory.found, trajectory.report.message
    data = mb.Data(model)
    mb.ForwardKinematics(model, data, trajectory.waypoints[-1].q)
    assert np.allclose(mb.FramePose(model, data, "r_sole").rotation()[:, 2], normal, atol=1e-3)
    # The system takes the terrain on an optional input port.
    system = planning.TrajectoryOptimizer(model)
    assert system.get_terrain_input_port().get_name() == "terrain"
